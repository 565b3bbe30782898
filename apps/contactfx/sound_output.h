// contactfx command line: the sound of a simulating command. --voices FILE.jsonl (voices started and
// stopped, one JSON object per line) and --audio FILE.wav (the built-in synthesizer, 48 kHz 16-bit mono),
// both streamed to their temporary files as the run goes (outputs.h), so memory stays flat for any duration;
// and for render's .mp4, the same audio in a scratch file to be muxed in.
#pragma once

#include "contactfx/effects.h"
#include "contactfx/sound.h"
#include "contactfx/sound_synth.h"
#include "outputs.h"

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cfx::cli
{

/// One line of the --voices file, newline included: {"type": "voice_started" | "voice_stopped", "time": s,
/// "voice": id, "kind": "scrape" | "impact" | "particle_hits", "pair": "A+B" (names sorted; particle hits:
/// the particle type's name), "loudness": 0..1}.
std::string VoiceJsonLine(const VoiceChange& change, const EffectsConfig& config);

/// Throws InputError naming --audio when `seconds` of audio do not fit in a WAV file (about 12.4 hours).
void CheckAudioSeconds(double seconds, const std::string& flag);

class SoundOutput
{
public:
    /// Registers with `outputs` (before Prepare): `audio` (--audio) and `voices` (--voices) when not empty;
    /// with `video` not empty and no `audio`, a scratch WAV beside the video for muxing. Throws InputError
    /// naming --audio when `audio` does not end in .wav.
    SoundOutput(OutputFiles& outputs, const std::string& audio, const std::string& voices,
                const std::filesystem::path& video = {});

    /// Whether anything is to be made: the voices are followed and synthesized only then.
    bool Active() const { return m_audio.has_value() || m_voices.has_value(); }

    /// After outputs.Prepare(): starts following `config`'s voices (seeded by `seed`).
    void Start(const EffectsConfig& config, std::uint64_t seed);
    /// After every step of the simulation, with its dt (s).
    void AfterStep(const Effects& effects, float dt);
    /// At the end: stops every voice, renders the audio up to `seconds` (the simulated time, or a video's
    /// length) and completes the WAV. Throws InputError naming the file (and the simulated time) when
    /// writing fails.
    void Finish(double seconds);

    /// The complete WAV's temporary file after Finish(), for muxing; empty without audio.
    std::filesystem::path WavFile() const;
    /// "voices: N scrape, M impact, at most K at once; audio: F (B bytes, S s to synthesize)".
    std::string Summary() const;

private:
    void WriteChanges();
    void WriteSamples();
    // Runs `write` on the audio file; a scratch file's failure is reported as the video's.
    template <typename Write> void WriteAudio(Write&& write);

    OutputFiles& m_outputs;
    std::optional<OutputFiles::Handle> m_audio;
    std::filesystem::path m_video; ///< the video whose scratch audio m_audio is; empty: --audio
    std::optional<OutputFiles::Handle> m_voices;
    std::unique_ptr<SoundVoices> m_sound;
    std::unique_ptr<SoundSynth> m_synth;
    const EffectsConfig* m_config = nullptr;
    std::vector<std::int16_t> m_samples; // of the step being written
    std::uint64_t m_written = 0;         // samples in the file
    std::chrono::steady_clock::duration m_synthTime{};
};

} // namespace cfx::cli
