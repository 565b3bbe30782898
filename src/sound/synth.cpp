// The procedural synthesizer (contactfx/sound_synth.h).
//
// Each voice owns its noise generator (PCG32 seeded from the synth's seed and the voice id, so a voice sounds
// the same whatever else sounds), two state-variable filters and an oscillator phase. Filters are the
// trapezoidal ("TPT") state-variable form, stable at any cutoff below Nyquist, retuned once per block from
// the voice's slip or approach speed. Voices are summed in id order and the sum goes through a soft limiter
// (a Pade approximation of tanh) before it becomes 16-bit samples.
#include "contactfx/sound_synth.h"
#include "random.h"

#include <algorithm>
#include <cmath>

namespace cfx
{

namespace
{

constexpr float kPi = 3.14159265358979f;
constexpr float kAttackSeconds = 0.003f;

// sin(x) for any finite x, from a degree-9 polynomial on [-pi/2, pi/2] (error below 4e-6): the same bits on
// every platform, unlike std::sin.
float Sine(float x)
{
    const float turns = std::floor((x + kPi) * (0.5f / kPi));
    x -= turns * 2.0f * kPi;
    if (x > 0.5f * kPi)
    {
        x = kPi - x;
    }
    else if (x < -0.5f * kPi)
    {
        x = -kPi - x;
    }
    const float x2 = x * x;
    return x * (1.0f + x2 * (-1.0f / 6.0f + x2 * (1.0f / 120.0f + x2 * (-1.0f / 5040.0f + x2 / 362880.0f))));
}

// A trapezoidal state-variable filter: low, band and high pass of one input.
struct Filter
{
    float ic1 = 0.0f;
    float ic2 = 0.0f;
    float a1 = 1.0f;
    float a2 = 0.0f;
    float a3 = 0.0f;
    float k = 1.0f;

    struct Out
    {
        float low;
        float band;
        float high;
    };

    void Tune(float cutoff, float q)
    {
        const float angle = kPi * std::clamp(cutoff, 10.0f, 0.45f * SoundSynth::kSampleRate) /
                            static_cast<float>(SoundSynth::kSampleRate);
        const float g = Sine(angle) / Sine(angle + 0.5f * kPi);
        k = 1.0f / q;
        a1 = 1.0f / (1.0f + g * (g + k));
        a2 = g * a1;
        a3 = g * a2;
    }

    Out Process(float x)
    {
        const float v3 = x - ic2;
        const float v1 = a1 * ic1 + a2 * v3;
        const float v2 = ic2 + a2 * ic1 + a3 * v3;
        ic1 = 2.0f * v1 - ic1;
        ic2 = 2.0f * v2 - ic2;
        return {v2, v1, x - k * v1 - v2};
    }
};

// tanh-like limiter: linear near 0, never beyond +-1.
float Limit(float x)
{
    if (x >= 3.0f)
    {
        return 1.0f;
    }
    if (x <= -3.0f)
    {
        return -1.0f;
    }
    const float x2 = x * x;
    return x * (27.0f + x2) / (27.0f + 9.0f * x2);
}

float Unit(float value)
{
    return std::clamp(value, 0.0f, 1.0f);
}

} // namespace

struct SoundSynth::Voice
{
    std::uint32_t id = 0;
    VoiceKind kind = VoiceKind::scrape;
    const SoundRuleDef* rule = nullptr;
    std::uint64_t startSample = 0;
    float loudness = 0.0f; // at the last call
    float target = 0.0f;   // now: the listed loudness, 0 when no longer listed
    float peak = 0.0f;
    bool listed = false;
    Random noise;
    Filter first;
    Filter second;
    float phase = 0.0f;   // cycles, oscillator
    float wobble = 0.0f;  // cycles, the squeal's vibrato
    float crackle = 0.0f; // hiss: the current crackle impulse
    float pitch = 0.0f;   // Hz, squeal tone or impact thump
    float bright = 0.0f;  // 0..1, hiss: slip speed / brightSpeed
};

SoundSynth::SoundSynth(const EffectsConfig& config, std::uint64_t seed)
    : m_rules(ResolveSoundRules(config)), m_hitSounds(ResolveParticleHitSounds(config)),
      m_gain(config.sound.gain), m_seed(seed)
{
    m_voices.reserve(2 * static_cast<std::size_t>(config.sound.maxVoices)); // sounding and fading out
    m_mix.reserve(kSampleRate / 10);
}

SoundSynth::~SoundSynth() = default;

void SoundSynth::Mix(Voice& voice, std::uint64_t first, std::size_t count, float fromLoudness,
                     float toLoudness)
{
    const float attackSamples = kAttackSeconds * kSampleRate;
    const float lengthSamples = voice.rule->impactLength * kSampleRate;
    const float step = 1.0f / static_cast<float>(count);
    const float fadeSamples = std::min(attackSamples, static_cast<float>(count));
    for (std::size_t i = 0; i < count; ++i)
    {
        const std::uint64_t sample = first + i;
        if (sample < voice.startSample)
        {
            continue;
        }
        const auto age = static_cast<float>(sample - voice.startSample);
        const float along = static_cast<float>(i + 1) * step;
        const float white = voice.noise.Range(-1.0f, 1.0f);
        float signal = 0.0f;
        float level = 0.0f;
        if (voice.kind != VoiceKind::scrape)
        {
            // Listed: the rule's decay. No longer listed (it stopped at the end of this block: replaced by
            // the next voice of its pair, or cut by the cap): that decay to the block's end, faded out over
            // its last 3 ms only, so that how much of it is heard does not depend on the step rate.
            const float fade =
                toLoudness > 0.0f ? 1.0f : std::min(1.0f, static_cast<float>(count - 1 - i) / fadeSamples);
            level = voice.peak * ImpactEnvelope(age / lengthSamples) * fade;
            voice.phase += voice.pitch / kSampleRate;
            voice.phase -= std::floor(voice.phase);
            signal = 0.9f * voice.first.Process(white).band + 0.6f * Sine(2.0f * kPi * voice.phase);
        }
        else
        {
            level =
                (fromLoudness + (toLoudness - fromLoudness) * along) * std::min(1.0f, age / attackSamples);
            switch (voice.rule->timbre)
            {
            case SoundTimbre::squeal:
            {
                voice.wobble += 6.0f / kSampleRate;
                voice.wobble -= std::floor(voice.wobble);
                voice.phase += voice.pitch * (1.0f + 0.02f * Sine(2.0f * kPi * voice.wobble)) / kSampleRate;
                voice.phase -= std::floor(voice.phase);
                const float angle = 2.0f * kPi * voice.phase;
                signal =
                    0.55f * Sine(angle) + 0.2f * Sine(2.0f * angle) + 0.6f * voice.first.Process(white).band;
                break;
            }
            case SoundTimbre::rumble:
                signal = 3.0f * voice.second.Process(voice.first.Process(white).low).low;
                break;
            default: // hiss
            {
                if (voice.noise.NextFloat() < 0.0005f + 0.004f * voice.bright)
                {
                    voice.crackle = voice.noise.Range(-1.0f, 1.0f);
                }
                voice.crackle *= 0.85f;
                signal = 1.5f * voice.second.Process(voice.first.Process(white).low).high + voice.crackle;
                break;
            }
            }
        }
        m_mix[i] += m_gain * level * signal;
    }
}

void SoundSynth::Render(std::span<const SoundVoice> voices, double time, std::vector<std::int16_t>& out)
{
    const auto end = static_cast<std::uint64_t>(std::max(0LL, std::llround(time * kSampleRate)));
    const std::size_t count = end > m_samples ? static_cast<std::size_t>(end - m_samples) : 0;

    for (Voice& voice : m_voices)
    {
        voice.listed = false;
        voice.target = 0.0f;
    }
    // New voices in id order after the known ones: m_voices stays sorted by id.
    std::size_t known = m_voices.size();
    for (const SoundVoice& given : voices)
    {
        auto found = std::lower_bound(m_voices.begin(), m_voices.begin() + static_cast<std::ptrdiff_t>(known),
                                      given.id, [](const Voice& v, std::uint32_t id) { return v.id < id; });
        Voice* voice = nullptr;
        if (found != m_voices.begin() + static_cast<std::ptrdiff_t>(known) && found->id == given.id)
        {
            voice = &*found;
        }
        else
        {
            voice = &m_voices.emplace_back();
            voice->id = given.id;
            voice->kind = given.kind;
            voice->rule = given.kind == VoiceKind::particleHits ? &m_hitSounds[given.particleType.index]
                                                                : &m_rules[given.rule.index];
            voice->startSample = static_cast<std::uint64_t>(std::llround(given.startTime * kSampleRate));
            voice->loudness = given.loudness;
            voice->noise = Random(m_seed, given.id);
        }
        voice->listed = true;
        voice->target = given.loudness;
        voice->peak = given.peak;
        // Colour of this block, from the voice now.
        const SoundRuleDef& rule = *voice->rule;
        if (voice->kind != VoiceKind::scrape) // particle hits: impacts with their type's sound
        {
            const float hard = Unit(given.approachSpeed / 10.0f);
            const float centre = rule.timbre == SoundTimbre::hiss     ? 2500.0f + 3000.0f * hard
                                 : rule.timbre == SoundTimbre::squeal ? 300.0f + 400.0f * hard
                                                                      : 110.0f + 200.0f * hard;
            voice->first.Tune(centre, 1.5f);
            voice->pitch = 0.25f * centre;
        }
        else
        {
            const float bright = Unit(given.slipSpeed / rule.brightSpeed);
            switch (rule.timbre)
            {
            case SoundTimbre::squeal:
                voice->pitch = 420.0f + 900.0f * bright;
                voice->first.Tune(voice->pitch * 2.0f, 4.0f);
                break;
            case SoundTimbre::rumble:
                voice->first.Tune(70.0f + 330.0f * bright, 0.8f);
                voice->second.Tune(140.0f + 660.0f * bright, 0.7f);
                break;
            default:
                voice->bright = bright;
                voice->first.Tune(2000.0f + 14000.0f * bright, 0.7f); // the top of the hiss
                voice->second.Tune(800.0f + 1200.0f * bright, 0.7f);  // its bottom
                break;
            }
        }
    }
    // Ids grow in start order, so every new voice is newer than every known one: sorting the new ones keeps
    // the whole array sorted.
    std::sort(m_voices.begin() + static_cast<std::ptrdiff_t>(known), m_voices.end(),
              [](const Voice& a, const Voice& b) { return a.id < b.id; });

    m_mix.assign(count, 0.0f);
    if (count > 0)
    {
        for (Voice& voice : m_voices)
        {
            Mix(voice, m_samples, count, voice.loudness, voice.target);
            voice.loudness = voice.target;
        }
    }
    std::erase_if(m_voices, [](const Voice& voice) { return !voice.listed; });
    out.reserve(out.size() + count);
    for (float value : m_mix)
    {
        out.push_back(static_cast<std::int16_t>(std::lround(Limit(value) * 32767.0f)));
    }
    m_samples = std::max(m_samples, end);
}

std::string WavHeader(std::uint64_t samples, int sampleRate)
{
    const auto dataBytes = static_cast<std::uint32_t>(samples * 2);
    std::string header;
    auto text = [&](const char* four) { header.append(four, 4); };
    auto u32 = [&](std::uint32_t value)
    {
        for (int i = 0; i < 4; ++i)
        {
            header.push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
        }
    };
    auto u16 = [&](std::uint32_t value)
    {
        header.push_back(static_cast<char>(value & 0xFFu));
        header.push_back(static_cast<char>((value >> 8) & 0xFFu));
    };
    text("RIFF");
    u32(36 + dataBytes);
    text("WAVE");
    text("fmt ");
    u32(16);                                         // size of the format chunk
    u16(1);                                          // PCM
    u16(1);                                          // channels
    u32(static_cast<std::uint32_t>(sampleRate));     // samples per second
    u32(static_cast<std::uint32_t>(sampleRate) * 2); // bytes per second
    u16(2);                                          // bytes per sample frame
    u16(16);                                         // bits per sample
    text("data");
    u32(dataBytes);
    return header;
}

std::uint64_t MaxWavSamples()
{
    return (0xFFFFFFFFull - 36) / 2;
}

std::string PcmBytes(std::span<const std::int16_t> samples)
{
    std::string bytes;
    bytes.reserve(samples.size() * 2);
    for (std::int16_t sample : samples)
    {
        const auto bits = static_cast<std::uint16_t>(sample);
        bytes.push_back(static_cast<char>(bits & 0xFFu));
        bytes.push_back(static_cast<char>(bits >> 8));
    }
    return bytes;
}

} // namespace cfx
