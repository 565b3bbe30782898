#include "audio_mux.h"

#include "contactfx/error.h"
#include "contactfx/render/frame_output.h"

#include <cstdlib>
#include <vector>

namespace cfx::cli
{

namespace
{

// Runs `name` (found on $PATH) with `arguments` and collects what it prints.
render::ProgramResult RunProgram(const std::string& name, const std::vector<std::string>& arguments)
{
    const std::filesystem::path program = render::FindProgram(name);
    if (program.empty())
    {
        throw std::runtime_error(name + " not found: install ffmpeg to write an .mp4 with sound");
    }
    return render::RunProgram(program, arguments);
}

std::string FirstLine(const std::string& text)
{
    return text.substr(0, text.find('\n'));
}

} // namespace

std::optional<double> ProbeAudioSeconds(const std::filesystem::path& file)
{
    const render::ProgramResult probe =
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
    const render::ProgramResult mux = RunProgram(
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
        // What a full disk does to the last step: ffmpeg is told of no error, and the file is cut short.
        throw InputError(
            shown, "--out",
            "ffmpeg exited with success but the video is incomplete (ffprobe finds no audio stream "
            "in what it wrote; a full disk?): no file written");
    }
}

} // namespace cfx::cli
