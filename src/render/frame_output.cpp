// Frame outputs. ffmpeg runs through popen (/bin/sh -c), so every path on its command line is quoted
// for the shell; it writes to a hidden temporary file beside the target with the format named
// explicitly (-f), and only a zero exit status renames that file into place.
#include "contactfx/render/frame_output.h"

#include "contactfx/error.h"
#include "contactfx/files/text_file.h"
#include "contactfx/render/cairo_renderer.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

namespace cfx::render
{

namespace
{

std::string Lower(std::string text)
{
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

/// A sequence pattern's one number: where it starts and ends in the name and its zero-padded width.
struct NumberField
{
    std::size_t begin = std::string::npos;
    std::size_t end = 0;
    int width = 0;
};

/// Parses the printf-like pattern of a file name: "%%" is a literal percent sign, "%d" or "%0Nd" the
/// number. Throws std::invalid_argument for anything else.
NumberField ParsePattern(const std::string& name, std::string& literal)
{
    NumberField field;
    literal.clear();
    for (std::size_t i = 0; i < name.size(); ++i)
    {
        if (name[i] != '%')
        {
            literal += name[i];
            continue;
        }
        if (i + 1 < name.size() && name[i + 1] == '%')
        {
            literal += '%';
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        int width = 0;
        if (j + 1 < name.size() && name[j] == '0' && name[j + 1] >= '1' && name[j + 1] <= '9')
        {
            width = name[j + 1] - '0';
            j += 2;
        }
        if (j >= name.size() || name[j] != 'd')
        {
            throw std::invalid_argument("bad frame number pattern in \"" + name +
                                        "\": use %d or %0Nd (N from 1 to 9), and %% for a percent sign");
        }
        if (field.begin != std::string::npos)
        {
            throw std::invalid_argument("more than one frame number in \"" + name + "\"");
        }
        field.begin = literal.size();
        field.width = width;
        literal += '#'; // placeholder, replaced by the number
        field.end = literal.size();
        i = j;
    }
    return field;
}

// Cairo's ARGB32 pixels are native-endian 32-bit words: B, G, R, A bytes on little-endian machines.
const std::string kCairoPixelFormat = std::endian::native == std::endian::little ? "bgra" : "argb";

std::string ShellQuote(const std::string& text)
{
    std::string quoted = "'";
    for (char c : text)
    {
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return quoted + "'";
}

std::filesystem::path TemporaryBeside(const std::filesystem::path& file)
{
    static std::atomic<unsigned> counter{0};
    std::string name = "." + file.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                       std::to_string(counter.fetch_add(1));
    return file.parent_path() / name;
}

} // namespace

OutputKind ClassifyOutput(const std::filesystem::path& path)
{
    if (!path.has_filename())
    {
        throw std::invalid_argument("\"" + path.string() + "\" names no file");
    }
    if (path.parent_path().string().find('%') != std::string::npos)
    {
        throw std::invalid_argument("a frame number pattern belongs in the file name, not in a folder: \"" +
                                    path.string() + "\"");
    }
    const std::string extension = Lower(path.extension().string());
    if (extension == ".mp4" || extension == ".gif")
    {
        if (path.filename().string().find('%') != std::string::npos)
        {
            throw std::invalid_argument("a frame number pattern needs a .png file, found \"" +
                                        path.filename().string() + "\"");
        }
        return extension == ".mp4" ? OutputKind::mp4 : OutputKind::gif;
    }
    if (extension != ".png")
    {
        throw std::invalid_argument("unknown extension \"" + path.extension().string() + "\" of \"" +
                                    path.string() + "\": expected .png, .mp4 or .gif");
    }
    std::string literal;
    const NumberField field = ParsePattern(path.filename().string(), literal);
    return field.begin == std::string::npos ? OutputKind::png : OutputKind::pngSequence;
}

std::filesystem::path SequenceFile(const std::filesystem::path& pattern, long long index)
{
    std::string name;
    const NumberField field = ParsePattern(pattern.filename().string(), name);
    if (field.begin == std::string::npos)
    {
        return pattern.parent_path() / name;
    }
    std::string number = std::to_string(index < 0 ? -index : index);
    if (static_cast<int>(number.size()) < field.width)
    {
        number.insert(0, static_cast<std::size_t>(field.width) - number.size(), '0');
    }
    if (index < 0)
    {
        number.insert(0, 1, '-');
    }
    name.replace(field.begin, field.end - field.begin, number);
    return pattern.parent_path() / name;
}

std::filesystem::path FindProgram(const std::string& program)
{
    const char* path = std::getenv("PATH");
    if (path == nullptr)
    {
        return {};
    }
    const std::string list = path;
    std::size_t start = 0;
    while (start <= list.size())
    {
        std::size_t stop = list.find(':', start);
        if (stop == std::string::npos)
        {
            stop = list.size();
        }
        const std::string dir = list.substr(start, stop - start);
        const std::filesystem::path candidate = std::filesystem::path(dir.empty() ? "." : dir) / program;
        std::error_code error;
        if (std::filesystem::is_regular_file(candidate, error) && ::access(candidate.c_str(), X_OK) == 0)
        {
            return candidate;
        }
        start = stop + 1;
    }
    return {};
}

PngSequenceSink::PngSequenceSink(std::filesystem::path pattern, long long first)
    : m_pattern(std::move(pattern)), m_next(first)
{
}

PngSequenceSink::~PngSequenceSink()
{
    if (!m_finished)
    {
        for (const std::filesystem::path& file : m_written)
        {
            std::error_code ignored;
            std::filesystem::remove(file, ignored);
        }
    }
}

void PngSequenceSink::Write(const CairoRenderer& frame)
{
    const std::filesystem::path file = SequenceFile(m_pattern, m_next);
    WriteTextFileAtomically(file, frame.EncodePng());
    m_written.push_back(file);
    ++m_next;
}

ProgramResult RunProgram(const std::filesystem::path& program, const std::vector<std::string>& arguments)
{
    std::string command = ShellQuote(program.string());
    for (const std::string& argument : arguments)
    {
        command += " " + ShellQuote(argument);
    }
    // Its input is empty: ffmpeg reads keys from standard input, and would take the bytes our caller's
    // script feeds the commands after ours.
    command += " </dev/null 2>&1";
    ProgramResult result;
    std::FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr)
    {
        return result;
    }
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    {
        result.output.append(buffer, n);
    }
    const int status = ::pclose(pipe);
    if (status != -1 && WIFEXITED(status))
    {
        result.status = WEXITSTATUS(status);
    }
    return result;
}

VideoProbe ProbeVideo(const std::filesystem::path& file)
{
    const std::filesystem::path ffprobe = FindProgram("ffprobe");
    if (ffprobe.empty())
    {
        throw std::runtime_error("ffprobe not found: install ffmpeg (with ffprobe) to write .mp4/.gif");
    }
    // Counting packets reads the whole file without decoding it: a cut-off video has fewer.
    const ProgramResult run = RunProgram(ffprobe, {"-v", "error", "-count_packets", "-select_streams", "v:0",
                                                   "-show_entries", "stream=nb_read_packets:format=duration",
                                                   "-of", "default=noprint_wrappers=1", file.string()});
    VideoProbe probe;
    bool haveFrames = false;
    bool haveSeconds = false;
    std::istringstream lines(run.output);
    for (std::string text; std::getline(lines, text);)
    {
        while (!text.empty() && text.back() == '\r')
        {
            text.pop_back();
        }
        char* end = nullptr;
        if (text.rfind("nb_read_packets=", 0) == 0)
        {
            probe.frames = std::strtoll(text.c_str() + 16, &end, 10);
            haveFrames = end != text.c_str() + 16;
        }
        else if (text.rfind("duration=", 0) == 0)
        {
            probe.seconds = std::strtod(text.c_str() + 9, &end);
            haveSeconds = end != text.c_str() + 9;
        }
        else if (!text.empty() && probe.message.empty())
        {
            probe.message = text;
        }
    }
    probe.ok = run.status == 0 && haveFrames && haveSeconds;
    if (!probe.ok && probe.message.empty())
    {
        probe.message = run.status == -1 ? "cannot start ffprobe" : "no video stream or duration found";
    }
    return probe;
}

VideoSink::VideoSink(std::filesystem::path file, OutputKind kind, int width, int height, double fps,
                     std::filesystem::path temporary)
    : m_file(std::move(file)), m_temporary(std::move(temporary)), m_width(width), m_height(height), m_fps(fps)
{
    const std::filesystem::path ffmpeg = FindProgram("ffmpeg");
    if (ffmpeg.empty())
    {
        throw std::runtime_error("ffmpeg not found: install ffmpeg to write .mp4/.gif");
    }
    if (FindProgram("ffprobe").empty())
    {
        throw std::runtime_error("ffprobe not found: install ffmpeg (with ffprobe) to write .mp4/.gif");
    }
    if (kind == OutputKind::mp4 && (width % 2 != 0 || height % 2 != 0))
    {
        throw std::invalid_argument("an .mp4 needs an even width and height, found " + std::to_string(width) +
                                    "x" + std::to_string(height));
    }
    m_rename = m_temporary.empty();
    if (m_rename)
    {
        m_temporary = TemporaryBeside(m_file);
    }
    std::string command = ShellQuote(ffmpeg.string()) +
                          " -hide_banner -loglevel error -y -f rawvideo -pix_fmt " + kCairoPixelFormat +
                          " -s " + std::to_string(width) + "x" + std::to_string(height) + " -framerate " +
                          std::to_string(fps) + " -i -";
    if (kind == OutputKind::mp4)
    {
        command += " -c:v libx264 -preset veryfast -crf 20 -pix_fmt yuv420p -movflags +faststart -f mp4";
    }
    else
    {
        // A palette per frame keeps colours true without holding every frame in memory.
        command += " -vf 'split[a][b];[a]palettegen=stats_mode=single[p];[b][p]paletteuse=new=1' -f gif";
    }
    command += " " + ShellQuote(m_temporary.string());
    m_previousSigpipe = std::signal(SIGPIPE, SIG_IGN);
    m_pipe = ::popen(command.c_str(), "w");
    if (m_pipe == nullptr)
    {
        std::signal(SIGPIPE, m_previousSigpipe);
        throw InputError(m_file.string(), "", "cannot start ffmpeg");
    }
}

VideoSink::~VideoSink()
{
    if (!m_finished)
    {
        Abort();
    }
    std::signal(SIGPIPE, m_previousSigpipe);
}

void VideoSink::Abort()
{
    if (m_pipe != nullptr)
    {
        ::pclose(m_pipe);
        m_pipe = nullptr;
    }
    std::error_code ignored;
    std::filesystem::remove(m_temporary, ignored);
}

void VideoSink::Write(const CairoRenderer& frame)
{
    if (m_pipe == nullptr || frame.Width() != m_width || frame.Height() != m_height)
    {
        throw std::logic_error("VideoSink: frame of another size, or written after Finish");
    }
    const unsigned char* rows = frame.Rows();
    const std::size_t rowBytes = 4 * static_cast<std::size_t>(m_width);
    for (int y = 0; y < m_height; ++y)
    {
        if (std::fwrite(rows + static_cast<std::size_t>(y) * frame.Stride(), 1, rowBytes, m_pipe) != rowBytes)
        {
            Abort();
            throw InputError(m_file.string(), "", "ffmpeg stopped taking frames (see its message above)");
        }
    }
    ++m_frames;
}

void VideoSink::CheckComplete()
{
    const VideoProbe probe = ProbeVideo(m_temporary);
    const double expected = static_cast<double>(m_frames) / m_fps;
    // GIF delays are whole centiseconds, and an MP4's duration may round: allow one frame and 20 ms.
    const double slack = 1.0 / m_fps + 0.02;
    if (probe.ok && probe.frames == m_frames && probe.seconds >= expected - slack)
    {
        return;
    }
    Abort();
    char numbers[160];
    std::snprintf(numbers, sizeof numbers, "%lld of %lld frames, %.2f of %.2f s", probe.frames, m_frames,
                  probe.seconds, expected);
    throw InputError(m_file.string(), "",
                     "ffmpeg exited with success but the video is incomplete (" +
                         (probe.ok ? std::string(numbers) : "ffprobe: " + probe.message) +
                         "; a full disk?): no file written");
}

void VideoSink::Finish()
{
    if (m_pipe == nullptr)
    {
        throw std::logic_error("VideoSink: Finish called twice");
    }
    const int status = ::pclose(m_pipe);
    m_pipe = nullptr;
    std::error_code error;
    if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
        !std::filesystem::is_regular_file(m_temporary, error))
    {
        Abort();
        const std::string how = status != -1 && WIFEXITED(status)
                                    ? "exit status " + std::to_string(WEXITSTATUS(status))
                                    : std::string("abnormal end");
        throw InputError(m_file.string(), "", "ffmpeg failed (" + how + ")");
    }
    CheckComplete();
    if (!m_rename)
    {
        m_finished = true; // the caller's temporary file now: kept
        return;
    }
    std::filesystem::rename(m_temporary, m_file, error);
    if (error)
    {
        Abort();
        throw InputError(m_file.string(), "", "cannot write: " + error.message());
    }
    m_finished = true;
}

std::unique_ptr<FrameSink> MakeSink(const std::filesystem::path& path, OutputKind kind, int width, int height,
                                    double fps)
{
    if (kind == OutputKind::mp4 || kind == OutputKind::gif)
    {
        return std::make_unique<VideoSink>(path, kind, width, height, fps);
    }
    return std::make_unique<PngSequenceSink>(path);
}

} // namespace cfx::render
