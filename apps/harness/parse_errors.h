// contactfx harness: the command line's own problems, as CLI11 finds them while parsing, in the project's
// format for both programs: InputError's diagnostic with file "<command line>" and the option as path,
// printed as "contactfx: error: <command line>: --frames: ...". CLI11 2.1's exceptions do not name the
// option: it is found in their message.
#pragma once

#include "contactfx/error.h"

#include <CLI/CLI.hpp>

namespace cfx
{

/// The diagnostic of a failed `app.parse` (after it threw `error`, not for CLI::Success). Its path is
/// the argument no option took ("--no-such-flag", "extra") when there is one, else the option CLI11's
/// message names; its message says what is wrong: "expected a whole number, found \"1e3\"" for a value
/// CLI11 cannot convert, "needs a whole number" for a missing value, "given more than once", "required,
/// but not given", else CLI11's own words without the option's name ("names no file" from NamesAFile).
Diagnostic DescribeParseError(const CLI::App& app, const CLI::ParseError& error);

/// The check of an option or argument that names a file: an explicitly empty value (`--effects ''`) is
/// refused while parsing ("names no file"), an option not given is fine.
const CLI::Validator& NamesAFile();

/// The check (give it to `transform`: `check` would not let it rewrite the value) of a whole-number
/// option accepting `lowest` .. `highest`, in decimal digits with an optional
/// sign and spaces around ("+5", " 010 " is 10, never octal): anything else, out of range or not such a
/// number, is refused while parsing, before CLI11 converts it, as "expected a whole number from 1 to
/// 10000, found \"10001\"". The help shows the range after the type ("UINT:INT in [1 - 10000]").
CLI::Validator WholeNumberIn(long long lowest, long long highest);

/// The check of a number option: refuses hex ("0x10", which CLI11 alone reads as 16) while parsing; the
/// command checks the range (and NaN) itself.
const CLI::Validator& DecimalNumber();

} // namespace cfx
