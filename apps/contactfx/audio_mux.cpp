#include "audio_mux.h"

#include "contactfx/error.h"
#include "contactfx/render/frame_output.h"

#include <cstdlib>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cfx::cli
{

namespace
{

struct ProgramResult
{
    int status = -1;    ///< exit status; -1 when it did not run or was killed
    std::string output; ///< stdout and stderr together
};

// Runs `name` (found on $PATH) with `arguments` (no shell: paths need no quoting) and collects what it
// prints.
ProgramResult RunProgram(const std::string& name, const std::vector<std::string>& arguments)
{
    ProgramResult result;
    const std::filesystem::path program = render::FindProgram(name);
    if (program.empty())
    {
        throw std::runtime_error(name + " not found: install ffmpeg to write an .mp4 with sound");
    }
    std::vector<char*> argv;
    std::string zeroth = program.string();
    argv.push_back(zeroth.data());
    std::vector<std::string> copies = arguments;
    for (std::string& argument : copies)
    {
        argv.push_back(argument.data());
    }
    argv.push_back(nullptr);
    int pipeEnds[2];
    if (::pipe(pipeEnds) != 0)
    {
        return result;
    }
    // Between fork and exec only async-signal-safe calls.
    const pid_t child = ::fork();
    if (child == 0)
    {
        ::dup2(pipeEnds[1], STDOUT_FILENO);
        ::dup2(pipeEnds[1], STDERR_FILENO);
        const int nothing = ::open("/dev/null", O_RDONLY);
        ::dup2(nothing, STDIN_FILENO);
        ::close(pipeEnds[0]);
        ::close(pipeEnds[1]);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(pipeEnds[1]);
    char buffer[4096];
    for (ssize_t n; (n = ::read(pipeEnds[0], buffer, sizeof buffer)) > 0;)
    {
        result.output.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(pipeEnds[0]);
    int status = 0;
    if (child > 0 && ::waitpid(child, &status, 0) == child && WIFEXITED(status))
    {
        result.status = WEXITSTATUS(status);
    }
    return result;
}

std::string FirstLine(const std::string& text)
{
    return text.substr(0, text.find('\n'));
}

} // namespace

std::optional<double> ProbeAudioSeconds(const std::filesystem::path& file)
{
    const ProgramResult probe =
        RunProgram("ffprobe", {"-v", "error", "-select_streams", "a:0", "-show_entries", "stream=duration",
                               "-of", "default=noprint_wrappers=1:nokey=1", file.string()});
    char* end = nullptr;
    const double seconds = std::strtod(probe.output.c_str(), &end);
    if (probe.status != 0 || end == probe.output.c_str())
    {
        return std::nullopt;
    }
    return seconds;
}

void MuxAudio(const std::filesystem::path& video, const std::filesystem::path& wav,
              const std::filesystem::path& out, const std::string& shown)
{
    const ProgramResult mux = RunProgram(
        "ffmpeg", {"-hide_banner", "-loglevel", "error", "-y",        "-i",    video.string(), "-i",
                   wav.string(),   "-map",      "0:v:0", "-map",      "1:a:0", "-c:v",         "copy",
                   "-c:a",         "aac",       "-b:a",  "192k",      "-ar",   "48000",        "-movflags",
                   "+faststart",   "-f",        "mp4",   out.string()});
    if (mux.status != 0)
    {
        throw InputError(shown, "--out",
                         "ffmpeg failed to add the audio track (exit status " + std::to_string(mux.status) +
                             "): " + FirstLine(mux.output));
    }
    if (!ProbeAudioSeconds(out))
    {
        throw InputError(shown, "--out", "ffmpeg wrote no audio stream");
    }
}

} // namespace cfx::cli
