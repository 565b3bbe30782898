// contactfx_render: where rendered frames go.
//
// One PNG file, a numbered PNG sequence, or a video that ffmpeg encodes from raw frames piped to its
// standard input. Every kind leaves either complete output or nothing: PNG files are written to a
// temporary name and renamed; a sequence that fails midway removes the frames it wrote; ffmpeg writes
// to a temporary file that is renamed only when ffmpeg exits with success and ffprobe finds every frame
// in it (ffmpeg may exit 0 after "No space left on device" and leave a video without its index).
#pragma once

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace cfx::render
{

class CairoRenderer;

/// What an output path asks for.
enum class OutputKind
{
    png,         ///< one frame: FILE.png
    pngSequence, ///< numbered frames: a .png path with one printf number, e.g. frames/frame_%04d.png
    mp4,         ///< H.264 video through ffmpeg
    gif,         ///< animated GIF through ffmpeg
};

/// The kind of `path` by its extension (case-insensitive) and, for .png, a "%d" or "%0Nd" (N in 1..9)
/// in the file name. Throws std::invalid_argument with a one-line reason for any other extension or
/// for a malformed pattern (more than one number, other % conversions, a pattern in a folder name).
OutputKind ClassifyOutput(const std::filesystem::path& path);

/// The file of frame `index` of a sequence pattern ("frame_%04d.png", 7 -> "frame_0007.png").
std::filesystem::path SequenceFile(const std::filesystem::path& pattern, long long index);

/// The full path of `program` on $PATH, or an empty path when it is not there (or not executable).
std::filesystem::path FindProgram(const std::string& program);

/// What a program run by RunProgram did.
struct ProgramResult
{
    int status = -1;    ///< exit status; -1 when it could not start or was killed
    std::string output; ///< standard output and standard error together
};
/// Runs `program` (a path, e.g. from FindProgram) with `arguments`, each passed as one word (quoted for
/// the shell), with an empty standard input (it reads nothing of ours), and collects what it prints. Blocks
/// until it exits.
ProgramResult RunProgram(const std::filesystem::path& program, const std::vector<std::string>& arguments);

/// Receives frames one after another. Finish() completes the output; destroying a sink that was not
/// finished removes everything it wrote.
class FrameSink
{
public:
    virtual ~FrameSink() = default;
    virtual void Write(const CairoRenderer& frame) = 0;
    virtual void Finish() = 0;
};

/// Writes frame i to SequenceFile(pattern, first + i), each file atomically.
class PngSequenceSink final : public FrameSink
{
public:
    explicit PngSequenceSink(std::filesystem::path pattern, long long first = 0);
    ~PngSequenceSink() override;
    void Write(const CairoRenderer& frame) override;
    void Finish() override { m_finished = true; }
    const std::vector<std::filesystem::path>& Files() const { return m_written; }

private:
    std::filesystem::path m_pattern;
    long long m_next;
    std::vector<std::filesystem::path> m_written;
    bool m_finished = false;
};

/// Pipes frames as raw pixels (Cairo's native-endian ARGB) into ffmpeg, which writes an MP4 (H.264, yuv420p:
/// width and height must be even) or a GIF (a palette per frame) at `fps` frames per second.
class VideoSink final : public FrameSink
{
public:
    /// Throws std::runtime_error "ffmpeg not found: install ffmpeg to write .mp4/.gif" when ffmpeg (or
    /// "ffprobe not found: ..." when ffprobe, which checks the result) is not on $PATH,
    /// std::invalid_argument for odd MP4 sizes, InputError naming `file` when ffmpeg cannot start. While
    /// the sink lives, SIGPIPE is ignored (so a dying ffmpeg shows as a write error, not a killed
    /// process); the previous disposition is restored after.
    ///
    /// `temporary` empty: ffmpeg writes to a hidden temporary file beside `file`, which Finish() renames
    /// to `file`. Otherwise ffmpeg writes to `temporary` (the caller's, e.g. one of several outputs
    /// committed together) and Finish() checks it and leaves it there; `file` only names the output in
    /// messages. Either way a sink that fails or is destroyed unfinished removes what ffmpeg wrote.
    VideoSink(std::filesystem::path file, OutputKind kind, int width, int height, double fps,
              std::filesystem::path temporary = {});
    ~VideoSink() override;
    VideoSink(const VideoSink&) = delete; // owns the encoder's pipe
    VideoSink& operator=(const VideoSink&) = delete;
    /// Throws InputError naming the file when ffmpeg stopped taking frames.
    void Write(const CairoRenderer& frame) override;
    /// Waits for ffmpeg, then checks the video with ffprobe: it must hold every frame written and last
    /// at least their time (frames / fps, less one frame). Throws InputError naming the file (and leaves
    /// none) when ffmpeg failed or the video is incomplete.
    void Finish() override;

private:
    void Abort();
    void CheckComplete();

    std::filesystem::path m_file;
    std::filesystem::path m_temporary;
    bool m_rename = true;    ///< Finish renames m_temporary to m_file
    bool m_finished = false; ///< Finish succeeded: the destructor leaves m_temporary
    int m_width;
    int m_height;
    double m_fps;
    long long m_frames = 0;
    std::FILE* m_pipe = nullptr;
    void (*m_previousSigpipe)(int) = nullptr;
};

/// What ffprobe finds in a video file: its video stream's packets (one per frame) and duration.
struct VideoProbe
{
    bool ok = false;      ///< ffprobe read the file
    long long frames = 0; ///< packets of the first video stream
    double seconds = 0.0; ///< the container's duration
    std::string message;  ///< ffprobe's complaint when !ok
};

/// Runs ffprobe (found on $PATH) on `file`. Throws std::runtime_error when ffprobe is not there.
VideoProbe ProbeVideo(const std::filesystem::path& file);

/// A sink for `kind` writing to `path`.
std::unique_ptr<FrameSink> MakeSink(const std::filesystem::path& path, OutputKind kind, int width, int height,
                                    double fps);

} // namespace cfx::render
