// contactfx_scene: reading and writing whole text files, with errors that name the file.
//
// Every output file of contactfx (stats, scenes, configs, events) is written through
// WriteTextFileAtomically, so a failed run never leaves a half-written file behind.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace cfx
{

/// The file's bytes. Throws InputError naming the file when it is missing, a directory or unreadable.
std::string ReadTextFile(const std::filesystem::path& path);

/// Writes `text` to a temporary file beside `path`, then renames it over `path`: readers see the old
/// file or the new one, never half of one. Throws InputError naming `path` on failure and leaves
/// nothing behind.
void WriteTextFileAtomically(const std::filesystem::path& path, std::string_view text);

} // namespace cfx
