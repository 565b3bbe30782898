// contactfx_files: reading and writing whole files, with errors that name the file.
//
// The one place contactfx writes a file: the scene and effects writers (contactfx::scene), the frames of
// the renderer (contactfx::render) and the testbed's screenshots go through WriteTextFileAtomically, and
// the command line checks its outputs with OutputFileProblem before it simulates. A failed write never
// leaves a half-written file, a temporary file, or a device or read-only file replaced behind it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace cfx
{

/// The file's bytes. Throws InputError naming the file when it is missing, a directory or unreadable.
std::string ReadTextFile(const std::filesystem::path& path);

/// Why `file` cannot be written as an output, or an empty string when it can. Refused: a path that
/// names no file; an existing directory, device (`/dev/full`, `/dev/null`), FIFO or other non-regular
/// file; an existing file with no write permission bit (a mode 444 file, even for root, who could write
/// it) or that cannot be written; a folder that is missing, not writable or not a folder (the first file on
/// the way to it is named: `"out/afile" is not a folder`). Messages name the folder as in `given` (the path
/// as the user wrote it) when that is not empty, e.g. "is a device, not a regular file: give a file to
/// write".
std::string OutputFileProblem(const std::filesystem::path& file, const std::filesystem::path& given = {});

/// Writes `bytes` to a temporary file beside `path`, then renames it over `path`: readers see the old
/// file or the new one, never half of one. Throws InputError naming `path` when OutputFileProblem
/// refuses it (nothing is written then) or when writing fails (the temporary file is removed).
void WriteTextFileAtomically(const std::filesystem::path& path, std::string_view bytes);

} // namespace cfx
