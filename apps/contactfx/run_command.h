// contactfx demo / contactfx run: simulate a scene with effects, headless.
#pragma once

#include <CLI/CLI.hpp>

namespace cfx::cli
{

/// Registers `demo` and `run` on the app; each sets `result` to its exit code when it runs.
void RegisterRunCommands(CLI::App& app, int& result);

} // namespace cfx::cli
