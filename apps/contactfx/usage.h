// The contactfx command line's conventions for finding and explaining commands: help texts, the short
// usage, and the errors for a mistyped command, option or argument, each naming what was not understood,
// suggesting the nearest valid name and pointing at `--help`.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace cfx::cli
{

/// "contactfx run": the names of `command` and of its parents, outermost first.
std::string CommandPath(const CLI::App& command);

/// The commands `group` takes (its named subcommands), in the order its help lists them.
std::vector<std::string> CommandNames(const CLI::App& group);

/// The command of `group` named `name`, or nullptr.
const CLI::App* FindCommand(const CLI::App& group, std::string_view name);

/// The help of `command`, exactly as `CommandPath(command) --help` prints it.
std::string HelpText(const CLI::App& command);

/// Reports on stderr that `name` is not a command of `group` ("contactfx: error: unknown command 'rnu';
/// did you mean 'run'?", or the list of its commands when none is near) and points at `group`'s --help.
/// Returns kExitError.
int ReportUnknownCommand(const CLI::App& group, const std::string& name);

/// Reports a failed parse of `app` (the top-level command) on stderr and returns kExitError:
/// - the first argument no command took: an unknown option, an unknown command or an unexpected
///   argument, named, with the nearest valid name when one is near;
/// - a command that needs a command (contactfx, contactfx bench) given none: "missing command" and its
///   short usage (usage line and its commands);
/// - else CLI11's message in the project's format: "<command line>: --stats: names no file",
///   "<command line>: files: required, but not given".
/// Every report ends with a pointer at the --help of the command concerned.
int ReportParseError(const CLI::App& app, const CLI::ParseError& error);

} // namespace cfx::cli
