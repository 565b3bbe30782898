// contactfx-testbed: the command line's own problems (those CLI11 finds while parsing, and file flags
// given an empty value) in the project's format: InputError's diagnostic with file "<command line>" and
// the flag as path, printed as "contactfx-testbed: error: <command line>: --frames: ...".
#pragma once

#include "contactfx/error.h"

#include <CLI/CLI.hpp>
#include <initializer_list>

namespace cfx::testbed
{

/// The diagnostic of a failed `app.parse` (after it threw `error`, not for CLI::Success). Its path is
/// the argument no option took ("--no-such-flag", "extra") when there is one, else the option CLI11's
/// message names (CLI11 2.1 names it there, not in the exception); its message says what is wrong:
/// "expected a whole number, found \"1e3\"" for a value CLI11 cannot convert, "needs a whole number"
/// for a missing value, "given more than once", else CLI11's own words without the option's name.
Diagnostic DescribeParseError(const CLI::App& app, const CLI::ParseError& error);

/// Throws InputError (kCommandLine, the flag, "names no file") for the first of `fileOptions` given on
/// the command line with an empty value (`--effects ''`): an explicitly empty file is a mistake, not
/// "none". Options not given are fine.
void CheckFilesNamed(std::initializer_list<const CLI::Option*> fileOptions);

} // namespace cfx::testbed
