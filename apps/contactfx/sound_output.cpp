#include "sound_output.h"

#include "cli_common.h"
#include "contactfx/error.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace cfx::cli
{

namespace
{

constexpr const char* kKinds[] = {"scrape", "impact", "particle_hits"};

} // namespace

std::string VoiceJsonLine(const VoiceChange& change, const EffectsConfig& config)
{
    nlohmann::ordered_json line;
    line["type"] = change.type == VoiceChangeType::started ? "voice_started" : "voice_stopped";
    line["time"] = std::round(change.time * 1e6) / 1e6; // s, to the microsecond
    line["voice"] = change.voice.id;
    line["kind"] = kKinds[static_cast<int>(change.voice.kind)];
    line["pair"] = VoiceName(change.voice, config); // particle hits: the particle type's name
    line["loudness"] = std::round(static_cast<double>(change.voice.loudness) * 1e6) / 1e6;
    return line.dump() + "\n";
}

void CheckAudioSeconds(double seconds, const std::string& flag)
{
    const double most = static_cast<double>(MaxWavSamples()) / SoundSynth::kSampleRate;
    if (seconds > most)
    {
        throw InputError(kCommandLine, flag,
                         "a WAV file holds at most " + NumberText(std::floor(most * 100.0) / 100.0) +
                             " s of 48 kHz 16-bit audio, asked for " + NumberText(seconds) +
                             " s (--seconds)");
    }
}

SoundOutput::SoundOutput(OutputFiles& outputs, const std::string& audio, const std::string& voices,
                         const std::filesystem::path& video)
    : m_outputs(outputs)
{
    if (!audio.empty())
    {
        m_audio = outputs.Add("--audio", audio, ".wav");
    }
    else if (!video.empty())
    {
        m_audio = outputs.AddScratch("--out", video.string() + ".audio.wav");
        m_video = video;
    }
    if (!voices.empty())
    {
        m_voices = outputs.Add("--voices", voices);
    }
}

template <typename Write> void SoundOutput::WriteAudio(Write&& write)
{
    try
    {
        write();
    }
    catch (const InputError& error)
    {
        if (m_video.empty())
        {
            throw;
        }
        throw InputError(m_video.string(), "--out",
                         "its audio track is incomplete (" + error.Diagnostics().at(0).message +
                             "; a full disk?): no file written");
    }
}

void SoundOutput::Start(const EffectsConfig& config, std::uint64_t seed)
{
    if (!Active())
    {
        return;
    }
    m_config = &config;
    m_sound = std::make_unique<SoundVoices>(config);
    if (m_audio)
    {
        m_synth = std::make_unique<SoundSynth>(config, seed);
        m_samples.reserve(SoundSynth::kSampleRate);
        WriteAudio([&] { m_outputs.Append(*m_audio, WavHeader(0)); }); // sizes written by Finish
    }
}

void SoundOutput::WriteChanges()
{
    if (m_voices)
    {
        for (const VoiceChange& change : m_sound->Changes())
        {
            m_outputs.Append(*m_voices, VoiceJsonLine(change, *m_config));
        }
    }
}

void SoundOutput::WriteSamples()
{
    WriteAudio([&] { m_outputs.Append(*m_audio, PcmBytes(m_samples)); });
    m_written += m_samples.size();
    m_samples.clear();
}

void SoundOutput::AfterStep(const Effects& effects, float dt)
{
    if (!m_sound)
    {
        return;
    }
    m_sound->Step(effects.Events(), dt);
    WriteChanges();
    if (m_synth)
    {
        const auto start = std::chrono::steady_clock::now();
        m_synth->Render(m_sound->Voices(), m_sound->Time(), m_samples);
        m_synthTime += std::chrono::steady_clock::now() - start;
        WriteSamples();
    }
}

void SoundOutput::Finish(double seconds)
{
    if (!m_sound)
    {
        return;
    }
    m_sound->StopAll();
    WriteChanges();
    if (m_synth)
    {
        const auto start = std::chrono::steady_clock::now();
        m_synth->Render(m_sound->Voices(), std::max(seconds, m_sound->Time()), m_samples);
        m_synthTime += std::chrono::steady_clock::now() - start;
        WriteSamples();
        WriteAudio([&] { m_outputs.WriteAt(*m_audio, 0, WavHeader(m_written)); });
    }
}

std::filesystem::path SoundOutput::WavFile() const
{
    return m_audio ? m_outputs.Temporary(*m_audio) : std::filesystem::path();
}

std::string SoundOutput::Summary() const
{
    if (!m_sound)
    {
        return {};
    }
    const SoundStats& stats = m_sound->Stats();
    char text[256];
    std::snprintf(text, sizeof text, "  voices: %llu scrape, %llu impact, at most %u at once",
                  static_cast<unsigned long long>(stats.scrapeVoices),
                  static_cast<unsigned long long>(stats.impactVoices), stats.soundingMax);
    std::string summary = text;
    if (m_synth)
    {
        std::snprintf(text, sizeof text, "; audio: %.2f s, %llu bytes, synthesized in %.3f s",
                      static_cast<double>(m_written) / SoundSynth::kSampleRate,
                      static_cast<unsigned long long>(44 + 2 * m_written),
                      std::chrono::duration<double>(m_synthTime).count());
        summary += text;
    }
    return summary + "\n";
}

} // namespace cfx::cli
