// contactfx harness: checks of command-line outputs shared by the CLI and the testbed.
#pragma once

#include <filesystem>
#include <string>

namespace cfx
{

/// What InputError names as the file of a command-line problem.
inline constexpr const char* kCommandLine = "<command line>";

/// Why `file` (when not empty) cannot be an output of `extension` (".wav", compared in any case): an output
/// is named after what is written to it. Empty when it can.
std::string ExtensionProblem(const std::string& file, const std::string& extension);
/// Throws InputError (kCommandLine, `flag`) with the ExtensionProblem of `file`, if any.
void CheckExtension(const std::string& flag, const std::string& file, const std::string& extension);

/// Throws InputError (kCommandLine, `flag`) naming `file` when OutputFileProblem (contactfx/files) refuses
/// it as an output: a folder, a device, a read-only file, a missing or unwritable folder.
void CheckOutputFile(const std::string& flag, const std::string& file);

/// `value` as the shortest text that reads back as the same double ("0.9999999", "-5", "nan"): what a
/// range error shows, so a rejected value never looks like one inside the range.
std::string NumberText(double value);
/// The same for a float: the shortest text that reads back as the same float ("59.99", a step rate as its
/// file has it, not 59.9900016784668).
std::string NumberText(float value);

/// Whether `a` and `b` name one file: the same path once made absolute and normal, or existing files that
/// are one (a symbolic or hard link). Empty names name no file.
bool SameFile(const std::filesystem::path& a, const std::filesystem::path& b);

} // namespace cfx
