// contactfx render: pictures of a simulation, headless: one PNG, a PNG sequence or a video.
#pragma once

#include <CLI/CLI.hpp>

namespace cfx::cli
{

/// Registers `render` on the app; it sets `result` to its exit code when it runs.
void RegisterRenderCommand(CLI::App& app, int& result);

} // namespace cfx::cli
