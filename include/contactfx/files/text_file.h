// contactfx_files: reading and writing whole files, with errors that name the file.
//
// The one place contactfx writes a file: the scene and effects writers (contactfx::scene), the frames of
// the renderer (contactfx::render) and the testbed's screenshots go through WriteTextFileAtomically, and
// the command line checks its outputs with OutputFileProblem before it simulates. A failed write never
// leaves a half-written file, a temporary file, or a device or read-only file replaced behind it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace cfx
{

/// The most ReadTextFile reads: 256 MiB, far above any scene or effects config, far below what would
/// exhaust memory (an endless device such as /dev/zero, a huge sparse file).
inline constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t{256} << 20;

/// The file's bytes. Throws InputError naming the file when it is missing, a directory, unreadable or
/// longer than kMaxTextFileBytes (a regular file is refused by its size before anything is read).
std::string ReadTextFile(const std::filesystem::path& path);

/// The file that a write of `file` replaces or creates: `file` made absolute, with its symbolic links
/// followed, a dangling one at the end too (to the file it names, which the write creates), so that an
/// output given through a link replaces the link's target and keeps the link. A chain of links longer than
/// the kernel follows (a loop) stops at its last link, which OutputFileProblem then refuses (ELOOP).
std::filesystem::path WrittenPath(const std::filesystem::path& file);

/// Why `file` cannot be written as an output, or an empty string when it can, e.g. "is a device, not a
/// regular file: give a file to write". The file checked is WrittenPath(file). Refused: a path that names
/// no file; an existing directory, device (`/dev/full`, `/dev/null`), FIFO or other non-regular file; an
/// existing file with no write permission bit (a mode 444 file, even for root, who could write it) or that
/// cannot be written; a folder that is missing, not writable or not a folder (the first file on the way to
/// it is named: `"out/afile" is not a folder`). Messages name folders as `file` names them, or as its
/// target does when `file` is a symbolic link.
std::string OutputFileProblem(const std::filesystem::path& file);

/// Writes `bytes` to a temporary file beside WrittenPath(path), then renames it over that file: readers see
/// the old file or the new one, never half of one; a file replaced keeps its mode, and a symbolic link
/// given as `path` stays. Throws InputError naming `path` when OutputFileProblem
/// refuses it (nothing is written then) or when writing fails (the temporary file is removed).
void WriteTextFileAtomically(const std::filesystem::path& path, std::string_view bytes);

} // namespace cfx
