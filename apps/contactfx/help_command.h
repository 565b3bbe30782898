// contactfx help [COMMAND...]: the help of contactfx or of one of its commands, on standard output.
#pragma once

#include <CLI/CLI.hpp>

namespace cfx::cli
{

/// Registers `help` on the app (register it last: it finds the commands of `app` when it runs). `help`
/// prints what `contactfx --help` prints, `help run` what `contactfx run --help` prints (exit code 0);
/// an unknown command is an error (exit code 1) suggesting the nearest. Sets `result` when it runs.
void RegisterHelpCommand(CLI::App& app, int& result);

} // namespace cfx::cli
