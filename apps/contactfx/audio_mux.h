// contactfx command line: an audio track added to a finished video, in a second ffmpeg pass.
//
// The video is encoded while the simulation runs (contactfx_render's VideoSink) and the audio is
// synthesized in the same pass, so the two meet only at the end: ffmpeg copies the video stream and encodes
// the WAV as AAC into a new file, which ffprobe then checks.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace cfx::cli
{

/// Writes `out` (MP4): the video stream of `video` copied and `wav` as 48 kHz AAC, then checks that `out`
/// has an audio stream. Throws InputError naming `shown` (the file the user asked for) when ffmpeg fails or
/// the result has no audio; std::runtime_error when ffmpeg or ffprobe is not on $PATH.
void MuxAudio(const std::filesystem::path& video, const std::filesystem::path& wav,
              const std::filesystem::path& out, const std::string& shown);

/// The duration of the first audio stream of `file` as ffprobe reports it, s; nothing when it has none.
std::optional<double> ProbeAudioSeconds(const std::filesystem::path& file);

} // namespace cfx::cli
