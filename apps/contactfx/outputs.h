// contactfx command line: the output files of one command, checked before it simulates and committed
// together after it succeeded, or not at all.
//
// Every output flag (--stats, --events, --plot, render --out and its frames, preset --out) registers its
// path here. Prepare() checks them all before anything is simulated and reports every problem at once:
// - a target that must have an extension (--plot .png, --audio .wav) has it;
// - the path names a file in a folder that exists and can be written to (OutputFileProblem, the check
//   every file write of contactfx makes: contactfx/files/text_file.h);
// - an existing target is a regular file (not a directory, device, FIFO or socket: `--stats /dev/full`
//   and `--stats /dev/null` are refused rather than replaced by a regular file) with a write permission
//   bit set (a mode 444 file is refused even for root, who could write it);
// - no target is one of the command's input files (`run scene.json --stats scene.json`) or another
//   output of the same command.
// It then creates an empty hidden temporary file beside each target (".NAME.tmp-PID-N"), exclusively.
// Outputs are written to their temporary files while the
// command runs (a stream for --events, so memory stays flat). Commit() checks the targets again, then
// renames every temporary file over its target (a replaced file keeps its mode); when a rename fails, the
// targets already renamed get their previous files back (kept as hard links until then). An OutputFiles
// destroyed before Commit() removes its temporary files: after a failed command no output of it is left, and
// pre-existing files are untouched. SIGINT, SIGTERM and SIGHUP remove the temporary files too.
#pragma once

#include "contactfx/error.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace cfx::cli
{

class OutputFiles
{
public:
    /// One registered output; an index into this set.
    using Handle = std::size_t;

    OutputFiles();
    ~OutputFiles();
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;

    /// An input file of the command: no output may be the same file. Missing files are ignored (reading
    /// them fails on its own).
    void AddInput(const std::filesystem::path& file);

    /// Registers `file`, given by option `flag` ("--stats"). Nothing is checked until Prepare(). With
    /// `extension` (".png"), Prepare() also refuses a file not named so (ExtensionProblem).
    Handle Add(const std::string& flag, const std::filesystem::path& file, const std::string& extension = "");

    /// A problem of an output found by the command itself: Prepare() reports it first, with the problems it
    /// finds.
    void Refuse(Diagnostic problem);

    /// Registers a scratch file for `flag`: a temporary file beside `file` (another output's target),
    /// created by Prepare() like the others and always removed, never renamed into place (the audio of a
    /// video before it is muxed in). Its target is not checked.
    Handle AddScratch(const std::string& flag, const std::filesystem::path& file);

    /// Checks every registered output (see the file comment) and creates their temporary files. Throws
    /// InputError with one diagnostic per problem ("FILE: --flag: message"), leaving nothing behind.
    void Prepare();

    /// The temporary file of `output`, for a writer that opens it itself (ffmpeg).
    const std::filesystem::path& Temporary(Handle output) const;
    /// The target as given.
    const std::filesystem::path& Target(Handle output) const;

    /// Replaces the contents of `output`'s temporary file by `bytes`. Throws InputError naming the
    /// target on failure (a full disk, a file size limit).
    void Write(Handle output, std::string_view bytes);

    /// Appends `bytes` to `output`'s temporary file through a buffered stream. Throws InputError naming
    /// the target when writing fails.
    void Append(Handle output, std::string_view bytes);

    /// Overwrites bytes of `output`'s temporary file at `offset` (a header whose sizes are known at the
    /// end), after what Append() wrote so far; later Appends go on at the end. Throws InputError naming the
    /// target on failure.
    void WriteAt(Handle output, std::uint64_t offset, std::string_view bytes);

    /// Throws std::runtime_error when SIGINT, SIGTERM or SIGHUP arrived since Prepare(): long loops call
    /// it so that an interrupted command unwinds and leaves no file.
    void CheckInterrupted() const;

    /// Flushes and syncs every temporary file, checks the targets again, and renames them all into
    /// place, or none (see the file comment). Throws InputError naming the file that failed. An interrupt
    /// before the renames unwinds as in CheckInterrupted; one during them waits until they are done, then
    /// throws std::runtime_error ("interrupted by ... after its outputs were written"); one after them
    /// stops the program with that message (exit 1).
    void Commit();

    /// For tests: where a step over the outputs is, with the output's index.
    enum class FileStep : std::uint8_t
    {
        prepared, ///< Prepare made its temporary file
        renaming, ///< Commit is about to rename it into place
    };
    void OnEachFile(std::function<void(FileStep, std::size_t)> call) { m_testHook = std::move(call); }

private:
    struct Output
    {
        std::string flag;
        std::filesystem::path target;    ///< as given
        std::filesystem::path real;      ///< where it is written: WrittenPath(target)
        std::filesystem::path temporary; ///< empty until Prepare()
        std::FILE* stream = nullptr;     ///< Append()'s stream, open until Commit()
        bool scratch = false;            ///< AddScratch(): removed at Commit(), never renamed
        std::string extension;           ///< the one the target must have; empty: any
    };

    [[noreturn]] void Fail(const Output& output, const std::string& message) const;
    // Opens the temporary file with `mode`, writes `bytes` at `offset`, closes it; Fail()s on error.
    void PutBytes(const Output& output, const char* mode, std::uint64_t offset, std::string_view bytes) const;
    void CloseStream(Output& output, bool check);
    void
    CreateTemporary(Output& output); ///< Prepare: the hidden file beside the target, listed for the handler
    void RemoveTemporaries();

    std::vector<std::filesystem::path> m_inputs;
    std::vector<Output> m_outputs;
    std::vector<Diagnostic> m_refused; ///< Refuse()'s problems
    bool m_prepared = false;
    bool m_committed = false;
    std::function<void(FileStep, std::size_t)> m_testHook; ///< OnEachFile
};

/// Called once, first thing in main: SIGINT, SIGTERM and SIGHUP before any OutputFiles is prepared (a
/// command reading its inputs, or with no output files) stop contactfx at once with the message the
/// prepared outputs' stop gives ("contactfx: error: interrupted by Interrupt: no output written", exit 1).
/// Once outputs are prepared, the signal stops the command as OutputFiles describes.
void InstallInterruptHandlers();

} // namespace cfx::cli
