// contactfx validate: checks RUBE scenes and effects configs and reports every problem of every file.
#pragma once

#include <CLI/CLI.hpp>

namespace cfx::cli
{

/// Registers `validate` on the app; it sets `result` to 0 when every file is valid, else 1.
void RegisterValidateCommand(CLI::App& app, int& result);

} // namespace cfx::cli
