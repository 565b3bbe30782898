// The synthesizer (contactfx/sound_synth.h): silence without voices, a voice heard from its start and not
// after its stop, loudness and brightness that follow the voice, impacts that follow the approach speed, the
// same samples for the same inputs, and the WAV header.
#include "contactfx/sound_synth.h"
#include "sound/sound_test_support.h"
#include "step_time.h"

#include <cmath>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

constexpr double kRate = SoundSynth::kSampleRate;

double Rms(const std::vector<std::int16_t>& samples, double from, double to)
{
    const auto first = static_cast<std::size_t>(std::llround(from * kRate));
    const auto last = std::min(samples.size(), static_cast<std::size_t>(std::llround(to * kRate)));
    double sum = 0.0;
    for (std::size_t i = first; i < last; ++i)
    {
        sum += static_cast<double>(samples[i]) * samples[i];
    }
    return last > first ? std::sqrt(sum / static_cast<double>(last - first)) / 32768.0 : 0.0;
}

// RMS of the first difference over RMS: higher for a brighter sound (a measure of the spectral centroid).
double Brightness(const std::vector<std::int16_t>& samples, double from, double to)
{
    const auto first = static_cast<std::size_t>(std::llround(from * kRate));
    const auto last = static_cast<std::size_t>(std::llround(to * kRate));
    if (last > samples.size())
    {
        ADD_FAILURE() << "Brightness up to " << to << " s of " << samples.size() << " samples";
        return 0.0;
    }
    double change = 0.0;
    double level = 0.0;
    for (std::size_t i = first + 1; i < last; ++i)
    {
        const double step = static_cast<double>(samples[i]) - samples[i - 1];
        change += step * step;
        level += static_cast<double>(samples[i]) * samples[i];
    }
    return std::sqrt(change / level);
}

// A voice as SoundVoices lists it, for driving the synthesizer directly.
SoundVoice Voice(std::uint32_t id, VoiceKind kind, float loudness, double start)
{
    SoundVoice voice;
    voice.id = id;
    voice.kind = kind;
    voice.rule = RuleId{0};
    voice.loudness = loudness;
    voice.peak = loudness;
    voice.startTime = start;
    return voice;
}

// `voice` held for `seconds` from its start (then no longer listed), rendered step by step.
std::vector<std::int16_t> Hold(const EffectsConfig& config, SoundVoice voice, double seconds, double total)
{
    SoundSynth synth(config, 7);
    std::vector<std::int16_t> samples;
    for (int step = 1; static_cast<float>(step) * kDt <= total + 1e-9; ++step)
    {
        const double time = static_cast<float>(step) * kDt; // in float, as the effects step time adds up
        std::vector<SoundVoice> voices;
        if (time >= voice.startTime - 1e-9 && time < voice.startTime + seconds)
        {
            voices.push_back(voice);
        }
        synth.Render(voices, time, samples);
    }
    return samples;
}

} // namespace

TEST(SoundSynth, NoVoiceIsExactSilence)
{
    SoundSynth synth(DefaultPreset());
    std::vector<std::int16_t> samples;
    synth.Render({}, 1.0, samples);
    ASSERT_EQ(samples.size(), 48000u);
    EXPECT_TRUE(std::all_of(samples.begin(), samples.end(), [](std::int16_t s) { return s == 0; }));
}

TEST(SoundSynth, AVoiceIsHeardFromItsStartWithin20MsAndNotAfterItsStop)
{
    for (VoiceKind kind : {VoiceKind::scrape, VoiceKind::impact})
    {
        const double start = 10 * kDt;
        const double held = 12 * kDt;
        const std::vector<std::int16_t> samples =
            Hold(DefaultPreset(), Voice(1, kind, 0.3f, start), held, 40 * kDt);
        EXPECT_EQ(Rms(samples, 0.0, start), 0.0);
        EXPECT_GT(20.0 * std::log10(Rms(samples, start, start + 0.02)), -40.0) << static_cast<int>(kind);
        // Listed until start + held: faded out within the next step, then nothing.
        EXPECT_EQ(Rms(samples, start + held + kDt, 40 * kDt), 0.0) << static_cast<int>(kind);
    }
}

TEST(SoundSynth, LoudnessAndBrightnessFollowTheVoice)
{
    const EffectsConfig config = DefaultPreset(); // rule 0: steel on concrete, a hiss
    SoundVoice quiet = Voice(1, VoiceKind::scrape, 0.1f, 0.0);
    SoundVoice loud = Voice(1, VoiceKind::scrape, 0.4f, 0.0);
    quiet.slipSpeed = loud.slipSpeed = 6.0f;
    const double quietRms = Rms(Hold(config, quiet, 2.0, 1.0), 0.1, 1.0);
    const double loudRms = Rms(Hold(config, loud, 2.0, 1.0), 0.1, 1.0);
    EXPECT_NEAR(loudRms / quietRms, 4.0, 0.4); // well below the limiter, the level is linear

    SoundVoice slow = loud;
    SoundVoice fast = loud;
    slow.slipSpeed = 1.0f;
    fast.slipSpeed = 12.0f;
    EXPECT_GT(Brightness(Hold(config, fast, 2.0, 1.0), 0.1, 1.0),
              1.3 * Brightness(Hold(config, slow, 2.0, 1.0), 0.1, 1.0));
}

TEST(SoundSynth, AnImpactsLevelFollowsItsLoudness)
{
    const EffectsConfig config = DefaultPreset();
    const double soft = Rms(Hold(config, Voice(1, VoiceKind::impact, 0.1f, 0.0), 1.0, 0.3), 0.0, 0.05);
    const double hard = Rms(Hold(config, Voice(1, VoiceKind::impact, 0.5f, 0.0), 1.0, 0.3), 0.0, 0.05);
    EXPECT_GT(hard, 3.0 * soft);
}

TEST(SoundSynth, TheSameVoicesGiveTheSameSamples)
{
    const EffectsConfig config = DefaultPreset();
    SoundVoice voice = Voice(3, VoiceKind::scrape, 0.5f, 0.05);
    voice.slipSpeed = 4.0f;
    EXPECT_EQ(Hold(config, voice, 0.5, 1.0), Hold(config, voice, 0.5, 1.0));
}

TEST(SoundSynth, WavHeaderDescribes48kHz16BitMono)
{
    const std::string header = WavHeader(480);
    ASSERT_EQ(header.size(), 44u);
    auto u32 = [&](std::size_t at)
    {
        std::uint32_t value = 0;
        for (int i = 3; i >= 0; --i)
        {
            value = value << 8 | static_cast<unsigned char>(header[at + static_cast<std::size_t>(i)]);
        }
        return value;
    };
    EXPECT_EQ(header.substr(0, 4), "RIFF");
    EXPECT_EQ(u32(4), 36u + 960u);
    EXPECT_EQ(header.substr(8, 8), "WAVEfmt ");
    EXPECT_EQ(u32(24), 48000u);
    EXPECT_EQ(header.substr(36, 4), "data");
    EXPECT_EQ(u32(40), 960u);
    EXPECT_EQ(PcmBytes(std::vector<std::int16_t>{-2, 258}), std::string("\xFE\xFF\x02\x01", 4));
}

} // namespace cfx::test
