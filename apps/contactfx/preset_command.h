// contactfx preset: a built-in effects configuration as an effects config JSON, to start tuning from.
#pragma once

#include <CLI/CLI.hpp>

namespace cfx::cli
{

void RegisterPresetCommand(CLI::App& app, int& result);

} // namespace cfx::cli
