// Particle hits -> voices (contactfx/sound.h): short ticks and taps per particle type and body, loudness from
// the number of hits and their mean speed, merged within the impact window, capped with the other voices;
// then the demo, whose dirt and sparks make them.
#include "contactfx/sound_synth.h"
#include "harness/scenes.h"
#include "harness/simulation.h"
#include "sound/sound_test_support.h"
#include "step_time.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>
#include <initializer_list>
#include <map>
#include <vector>

namespace cfx::test
{

namespace
{

// The particle hits of `count` particles of `type` on the body of `bench.boxes[box]` at `meanSpeed`.
EffectEvent Hits(const EventBench& bench, int box, std::uint16_t type, std::uint32_t count, float meanSpeed)
{
    EffectEvent event;
    event.type = EffectEventType::particleHits;
    event.body = bench.boxes[static_cast<std::size_t>(box)]->GetBody();
    event.particleType = ParticleTypeId{type};
    event.count = count;
    event.approachSpeed = meanSpeed;
    event.point = event.body->GetPosition();
    return event;
}

std::uint16_t TypeNamed(const EffectsConfig& config, const char* name)
{
    return config.FindParticleType(name).index;
}

// Particle hits wait for their merge time before their voice starts: steps of `dt` with no event until
// `voices` has one (at most 100). Returns how many steps that took.
int StepUntilAVoice(SoundVoices& voices, float dt)
{
    int steps = 0;
    for (; voices.Voices().empty() && steps < 100; ++steps)
    {
        voices.Step({}, dt);
    }
    return steps;
}

// The loudest a rain of 480 hits a second at 2 m/s on one body gets over 1 s, stepped at `dts` in turn.
float RainPeak(const EventBench& bench, std::uint16_t type, std::initializer_list<float> dts)
{
    SoundVoices rain(bench.config);
    float peak = 0.0f;
    for (float time = 0.0f; time < 1.0f;)
    {
        for (const float dt : dts)
        {
            const EffectEvent hits =
                Hits(bench, 0, type, static_cast<std::uint32_t>(std::lround(480.0f * dt)), 2.0f);
            rain.Step(std::span(&hits, 1), dt);
            for (const SoundVoice& voice : rain.Voices())
            {
                peak = std::max(peak, voice.peak);
            }
            time += dt;
        }
    }
    return peak;
}

} // namespace

TEST(ParticleHitVoices, LoudnessFollowsCountAndMeanSpeedAndTheVoiceDecaysOverItsLength)
{
    EventBench bench(2);
    const std::uint16_t dirt = TypeNamed(bench.config, "dirt");
    SoundVoices voices(bench.config);
    const SoundConfig& sound = bench.config.sound;
    const EffectEvent hits = Hits(bench, 0, dirt, 9, 2.5f);
    voices.Step(std::span(&hits, 1), kDt);
    EXPECT_TRUE(voices.Voices().empty()) << "the hits wait for their merge time";
    // 40 ms: the step of the hits and the next fit, a third would not; the voice starts after them.
    EXPECT_EQ(StepUntilAVoice(voices, kDt), 1);
    ASSERT_EQ(voices.Voices().size(), 1u);
    const SoundVoice& voice = voices.Voices()[0];
    EXPECT_EQ(voice.kind, VoiceKind::particleHits);
    EXPECT_EQ(voice.particleType, ParticleTypeId{dirt});
    EXPECT_FALSE(voice.rule.IsValid());
    EXPECT_EQ(VoiceName(voice, bench.config), "dirt");
    EXPECT_FLOAT_EQ(voice.loudness, 1.0f - std::exp(-sound.particleHitGain * 2.5f * 3.0f)); // sqrt(9) = 3
    EXPECT_EQ(voices.VoiceSound(voice).timbre, SoundTimbre::rumble) << "dirt: a soft tap";
    // Silent steps: it decays and stops within its length.
    const int lengthSteps = static_cast<int>(std::ceil(sound.particleHitLength / kDt));
    int stoppedAfter = 0;
    for (int step = 1; step <= lengthSteps + 1 && stoppedAfter == 0; ++step)
    {
        voices.Step({}, kDt);
        stoppedAfter = voices.Voices().empty() ? step : 0;
    }
    EXPECT_GE(stoppedAfter, lengthSteps - 1);
    EXPECT_LE(stoppedAfter, lengthSteps + 1);
    EXPECT_EQ(voices.Stats().particleHitVoices, 1u);
}

TEST(ParticleHitVoices, AGainOfZeroMakesThemSilentAndStartsNoVoice)
{
    // particleHitGain 0: loudness 1 - exp(0) = 0, so nothing sounds (214 voices of loudness 1e-6 started).
    EventBench bench(2);
    bench.config.sound.particleHitGain = 0.0f;
    const std::uint16_t dirt = TypeNamed(bench.config, "dirt");
    SoundVoices voices(bench.config);
    for (int step = 0; step < 30; ++step)
    {
        const EffectEvent hits = Hits(bench, step % 2, dirt, 9, 2.5f);
        voices.Step(std::span(&hits, 1), kDt);
        EXPECT_TRUE(voices.Voices().empty()) << "step " << step;
    }
    EXPECT_EQ(voices.Stats().particleHitVoices, 0u);
}

TEST(ParticleHitVoices, AreOnePerTypeAndBodyAndMergeWithinTheWindow)
{
    EventBench bench(2);
    const std::uint16_t dirt = TypeNamed(bench.config, "dirt");
    const std::uint16_t sparks = TypeNamed(bench.config, "sparks");
    SoundVoices voices(bench.config);
    const std::vector<EffectEvent> first{Hits(bench, 0, dirt, 4, 2.0f), Hits(bench, 1, dirt, 4, 2.0f),
                                         Hits(bench, 0, sparks, 2, 6.0f)};
    voices.Step(first, kDt);
    EXPECT_TRUE(voices.Voices().empty()) << "waiting for the merge time";
    // The next step, within the merge window: merged into the same three slots, which then start.
    voices.Step(first, kDt);
    ASSERT_EQ(voices.Voices().size(), 3u);
    EXPECT_EQ(voices.Stats().particleHitVoices, 3u);
    EXPECT_EQ(voices.Stats().particleHitsMerged, 3u);
    // Ids go loudest first: the sparks (4 hits at 6 m/s) before the dirt (8 at 2 m/s).
    EXPECT_EQ(voices.Voices()[0].particleType, ParticleTypeId{sparks});
    EXPECT_EQ(voices.VoiceSound(voices.Voices()[0]).timbre, SoundTimbre::hiss) << "sparks: a bright tick";
    // After the window, dirt on box 0 again: a new tap (no cooldown).
    const int windowSteps = static_cast<int>(std::ceil(bench.config.sound.impactMergeWindow / kDt));
    for (int step = 0; step < windowSteps; ++step)
    {
        voices.Step({}, kDt);
    }
    voices.Step(std::span(&first[0], 1), kDt);
    voices.Step({}, kDt);
    EXPECT_EQ(voices.Stats().particleHitVoices, 4u);
}

// A trial's rain of dirt at about 500 hits a second summed to a third less loudness at 240 Hz than at 30 Hz:
// the loudness counted one step's hits, and a step at 240 Hz has an eighth of them. A voice now counts all
// the whole steps that fit in its merge time (40 ms: particleHitLength), so the rain peaks alike at every
// rate, within the part of a step that does not fit (16 hits at 30, 60 and 120 Hz, 18 at 240 Hz), and within
// one step more when the step time changes from step to step; a lone hit is the same at all rates.
TEST(ParticleHitVoices, ARainSoundsAlikeAtEveryStepRateAndALoneHitTheSame)
{
    EventBench bench(2);
    const std::uint16_t dirt = TypeNamed(bench.config, "dirt");
    const float gain = bench.config.sound.particleHitGain;
    const auto loudness = [&](float hits) { return 1.0f - std::exp(-gain * 2.0f * std::sqrt(hits)); };
    std::vector<float> peaks;
    for (const int hz : {30, 60, 120, 240})
    {
        SCOPED_TRACE(hz);
        const float dt = 1.0f / static_cast<float>(hz);
        peaks.push_back(RainPeak(bench, dirt, {dt}));
        SoundVoices lone(bench.config);
        const EffectEvent hit = Hits(bench, 0, dirt, 1, 2.0f);
        lone.Step(std::span(&hit, 1), dt);
        StepUntilAVoice(lone, dt);
        ASSERT_EQ(lone.Voices().size(), 1u);
        EXPECT_FLOAT_EQ(lone.Voices()[0].peak, loudness(1.0f));
    }
    std::printf("a rain of 480 hits a second at 30, 60, 120, 240 Hz peaks at %.4f %.4f %.4f %.4f\n", peaks[0],
                peaks[1], peaks[2], peaks[3]);
    EXPECT_FLOAT_EQ(peaks[0], loudness(16.0f));
    EXPECT_FLOAT_EQ(peaks[1], loudness(16.0f));
    EXPECT_FLOAT_EQ(peaks[2], loudness(16.0f));
    EXPECT_FLOAT_EQ(peaks[3], loudness(18.0f));
    // Steps of 1/30 and 1/120 s in turn (the trial: a 1/30 s step weighted by a fifth, 0.1487), and of 4 to
    // 40 ms. A voice starts when one more step as long as the last would no longer fit, so when the next is
    // longer it takes that one in too: at most the merge time and one step (1/120 + 1/30 s: 20 hits; 13 + 9
    // + 31 ms: 25).
    const float alternating = RainPeak(bench, dirt, {1.0f / 30.0f, 1.0f / 120.0f});
    EXPECT_GE(alternating, loudness(16.0f));
    EXPECT_LE(alternating, loudness(20.0f) * (1.0f + 1e-6f));
    const float uneven = RainPeak(bench, dirt, {0.004f, 0.021f, 0.04f, 0.013f, 0.009f, 0.031f});
    EXPECT_GE(uneven, loudness(16.0f));
    EXPECT_LE(uneven, loudness(25.0f) * (1.0f + 1e-6f));
}

// A burst of hits late in a voice's merge time: before, a step that reached past it counted for the part
// within it, and the burst in the step where that part was 0 raised nothing and started nothing (40 Hz, a
// merge window of 50 ms and taps of 100 ms: the voice stayed at 0.030 where the burst alone sounds 0.95).
// Now a step merges only whole: the burst is merged in full or starts its own voice, within its merge time.
TEST(ParticleHitVoices, ABurstLateInTheMergeTimeIsNeverLost)
{
    EventBench bench(2);
    bench.config.sound.particleHitLength = 0.1f;
    bench.config.sound.impactMergeWindow = 0.05f;
    const std::uint16_t dirt = TypeNamed(bench.config, "dirt");
    const float alone = 1.0f - std::exp(-bench.config.sound.particleHitGain * 10.0f * 10.0f);
    for (const int hz : {40, 80, 100, 200})
    {
        const float dt = 1.0f / static_cast<float>(hz);
        for (int later = 1; later <= hz / 20 + 1; ++later)
        {
            SCOPED_TRACE(testing::Message() << hz << " Hz, burst " << later << " steps later");
            SoundVoices voices(bench.config);
            const EffectEvent lone = Hits(bench, 0, dirt, 1, 1.0f);
            voices.Step(std::span(&lone, 1), dt);
            for (int step = 1; step < later; ++step)
            {
                voices.Step({}, dt);
            }
            const EffectEvent burst = Hits(bench, 0, dirt, 100, 10.0f);
            voices.Step(std::span(&burst, 1), dt);
            // Merged into the waiting voice, or waiting for a voice of its own: either sounds it in full
            // within its merge time.
            float loudest = 0.0f;
            for (int step = 0; step <= hz / 20 + 1; ++step)
            {
                ASSERT_LE(voices.Voices().size(), 1u);
                loudest = std::max(loudest, voices.Voices().empty() ? 0.0f : voices.Voices()[0].peak);
                voices.Step({}, dt);
            }
            EXPECT_GE(loudest, 0.99f * alone);
        }
    }
}

// A trial's rain of 480 dirt hits a second at 2 m/s gave voices of the same final peak at 30, 60 and 120 Hz,
// yet its synthesized RMS was 392, 491, 394 and 315 at 30, 60, 120 and 240 Hz: a voice started with its
// first step's hits and grew as later steps merged into it (so the loudest start of its decay was played at
// an eighth of the hits at 240 Hz), and the synthesizer faded a replaced voice over its whole last step (at
// 30 Hz all of it). Hits now wait for their merge time and start their voice with all of them, and a
// replaced voice sounds to its step's end. Also with hits in only some steps (merge time is elapsed time).
TEST(ParticleHitVoices, ARainsTapsSoundAlikeAtEveryStepRate)
{
    EventBench bench(2);
    const std::uint16_t dirt = TypeNamed(bench.config, "dirt");
    for (const int gaps : {0, 3})
    {
        std::vector<double> rms;
        for (const int hz : {30, 60, 120, 240})
        {
            SCOPED_TRACE(testing::Message() << hz << " Hz, gaps " << gaps);
            SoundVoices voices(bench.config);
            SoundSynth synth(bench.config);
            std::vector<std::int16_t> samples;
            std::map<std::uint32_t, float> startPeak;
            const float dt = 1.0f / static_cast<float>(hz);
            double owed = 0.0;
            double time = 0.0;
            for (int step = 0; step < 2 * hz; ++step)
            {
                owed += 480.0 * dt;
                std::vector<EffectEvent> events;
                if ((gaps == 0 || hz < 120 || step % gaps != 0) &&
                    owed >= 1.0) // hz >= 120: a third of steps none
                {
                    events.push_back(Hits(bench, 0, dirt, static_cast<std::uint32_t>(owed), 2.0f));
                    owed -= static_cast<std::uint32_t>(owed);
                }
                voices.Step(events, dt);
                time += dt;
                for (const VoiceChange& change : voices.Changes()) // as loud at its stop as at its start
                {
                    if (change.type == VoiceChangeType::started)
                    {
                        startPeak[change.voice.id] = change.voice.peak;
                    }
                    else
                    {
                        EXPECT_EQ(change.voice.peak, startPeak.at(change.voice.id));
                    }
                }
                synth.Render(voices.Voices(), time, samples);
            }
            double sum = 0.0;
            for (std::size_t i = samples.size() / 4; i < samples.size(); ++i)
            {
                sum += static_cast<double>(samples[i]) * samples[i];
            }
            rms.push_back(std::sqrt(sum / static_cast<double>(samples.size() - samples.size() / 4)));
        }
        std::printf("a rain of 480 hits a second (gaps %d): RMS %.0f %.0f %.0f %.0f at 30, 60, 120, 240 Hz\n",
                    gaps, rms[0], rms[1], rms[2], rms[3]);
        for (std::size_t i = 1; i < rms.size(); ++i)
        {
            EXPECT_NEAR(rms[i] / rms[0], 1.0, 0.06) << "rate " << i;
        }
    }
}

TEST(ParticleHitVoices, ShareTheCapWithTheOtherVoicesLoudestFirst)
{
    const int count = 300;
    EventBench bench(count);
    const std::uint16_t dirt = TypeNamed(bench.config, "dirt");
    SoundVoices voices(bench.config);
    std::vector<EffectEvent> events;
    for (int box = 0; box < count; ++box)
    {
        events.push_back(Hits(bench, box, dirt, 1 + static_cast<std::uint32_t>(box % 7), 3.0f));
    }
    events.push_back(bench.Impact(0, 1, 0.99f)); // louder than any tap
    voices.Step(events, kDt);
    voices.Step({}, kDt); // the taps wait for their merge time, the impact sounds on
    const std::uint32_t cap = bench.config.sound.maxVoices;
    ASSERT_EQ(voices.Voices().size(), cap);
    int impacts = 0;
    for (const SoundVoice& voice : voices.Voices())
    {
        impacts += voice.kind == VoiceKind::impact ? 1 : 0;
        if (voice.kind == VoiceKind::particleHits)
        {
            EXPECT_FLOAT_EQ(voice.loudness,
                            1.0f - std::exp(-bench.config.sound.particleHitGain * 3.0f * std::sqrt(7.0f)))
                << "only the loudest taps (7 hits) sound";
        }
    }
    EXPECT_EQ(impacts, 1);
    EXPECT_EQ(voices.Stats().particleHitsOverCap, static_cast<std::uint64_t>(count) - (cap - 1));
}

TEST(ParticleHitVoices, TheTutorialScenePattersAndTicksWithinTheCap)
{
    const SceneEntry& entry = *FindScene("tutorial");
    Simulation simulation(SceneSimulationDef(entry, std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes"));
    SoundVoices voices(simulation.GetEffects().Config());
    std::uint64_t groups = 0, hits = 0;
    std::uint32_t mostGroups = 0;
    const int steps = static_cast<int>(20.0f / simulation.Dt());
    for (int step = 0; step < steps; ++step)
    {
        StepScene(entry, simulation);
        std::uint32_t stepGroups = 0;
        for (const EffectEvent& event : simulation.GetEffects().Events())
        {
            if (event.type == EffectEventType::particleHits)
            {
                ++stepGroups;
                hits += event.count;
            }
        }
        groups += stepGroups;
        mostGroups = std::max(mostGroups, stepGroups);
        voices.Step(simulation.GetEffects().Events(), simulation.Dt());
        ASSERT_LE(voices.Voices().size(), simulation.GetEffects().Config().sound.maxVoices);
    }
    std::printf(
        "tutorial, 20 s: %llu particle hit groups (%llu hits; at most %u groups a step), %llu particle "
        "hit voices, %llu merged, %llu over the cap\n",
        static_cast<unsigned long long>(groups), static_cast<unsigned long long>(hits), mostGroups,
        static_cast<unsigned long long>(voices.Stats().particleHitVoices),
        static_cast<unsigned long long>(voices.Stats().particleHitsMerged),
        static_cast<unsigned long long>(voices.Stats().particleHitsOverCap));
    EXPECT_GT(groups, 0u);
    EXPECT_LE(mostGroups, simulation.GetEffects().Config().budget.particleHits);
    EXPECT_GT(voices.Stats().particleHitVoices, 0u);
}

} // namespace cfx::test
