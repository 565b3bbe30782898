// contactfx: a small procedural synthesizer for voices (sound.h), and the WAV format it is written in.
//
// For the demo video and for tuning the `sound` section by ear; a game would rather drive its own audio
// engine from the voices (docs/sound.md). No samples: per rule timbre (SoundRuleDef::timbre), a scrape is
// filtered noise whose level follows the voice's loudness and whose brightness follows its slip speed
// (hiss: high-passed noise with crackle; squeal: a tone whose pitch rises with slip speed over a little
// noise; rumble: low-passed noise), and an impact is a short noise burst and thump whose level is the
// voice's and whose colour brightens with the approach speed, decaying as ImpactEnvelope over the rule's
// impactLength. Particle hits sound as impacts with their type's sound (ResolveParticleHitSounds): over
// sound.particleHitLength, a bright tick for sparks (hiss), a soft low tap for dirt (rumble).
//
// Timing: a voice started at time t is heard from sample round(t * 48000) on, rising to its loudness within
// 3 ms; between two Render calls a voice's loudness moves linearly from its old to its new value; a voice no
// longer listed fades out within the block and is silent after it (an impact or particle hits voice sounds
// to the block's end, fading over its last 3 ms: it stopped then). With no voice the output is exactly 0.
//
// Deterministic: every noise source is a seeded PCG32 of our own (seed and voice id), every sine and tangent
// a polynomial of our own, so the same voices, times and seed give the same samples bit for bit.
// Allocation: none per Render once `maxVoices` voices have sounded, besides growing the caller's buffer.
// Threading: one thread at a time per synthesizer (an audio thread may own one, fed the voices through the
// application's own queue); synthesizers are independent of each other and of the Effects.
#pragma once

#include "contactfx/config.h"
#include "contactfx/sound.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace cfx
{

class SoundSynth
{
public:
    static constexpr int kSampleRate = 48000; ///< samples per second, one channel

    /// Timbres and gains from `config` (validated by the caller, e.g. through SoundVoices).
    explicit SoundSynth(const EffectsConfig& config, std::uint64_t seed = 1);
    ~SoundSynth();
    SoundSynth(const SoundSynth&) = delete;
    SoundSynth& operator=(const SoundSynth&) = delete;

    /// Renders from the end of the last call (0 at first) up to `time` s (not before it) the voices as
    /// SoundVoices::Voices() lists them at `time`, appending 16-bit samples to `out`: sample i is the sound
    /// at i / kSampleRate s, and after the call Samples() == round(time * kSampleRate).
    void Render(std::span<const SoundVoice> voices, double time, std::vector<std::int16_t>& out);

    /// Samples rendered so far.
    std::uint64_t Samples() const { return m_samples; }

private:
    struct Voice;
    void Mix(Voice& voice, std::uint64_t first, std::size_t count, float fromLoudness, float toLoudness);

    std::vector<SoundRuleDef> m_rules;
    std::vector<SoundRuleDef> m_hitSounds; ///< by particle type (ResolveParticleHitSounds)
    float m_gain;
    std::uint64_t m_seed;
    std::vector<Voice> m_voices; // by id, ascending
    std::vector<float> m_mix;
    std::uint64_t m_samples = 0;
};

/// The 44-byte header of a RIFF WAVE file of `samples` 16-bit little-endian PCM samples, one channel at
/// `sampleRate` Hz. `samples` must be below MaxWavSamples().
std::string WavHeader(std::uint64_t samples, int sampleRate = SoundSynth::kSampleRate);

/// The most 16-bit mono samples a WAV file holds (its sizes are 32-bit): 2^31 - 23.
std::uint64_t MaxWavSamples();

/// `samples` as little-endian bytes, the body of a WAV file.
std::string PcmBytes(std::span<const std::int16_t> samples);

} // namespace cfx
