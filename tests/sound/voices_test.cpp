// Events -> voices (contactfx/sound.h): hysteresis, minimum duration and release, the impact merge window,
// the cooldown, the cap and its priority, on hand-made events; then whole scenes whose events chatter.
#include "harness/scenes.h"
#include "harness/simulation.h"
#include "sound/sound_test_support.h"
#include "step_time.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

using Type = EffectEventType;

const SoundRuleDef kRule{}; // the defaults every rule of the default preset uses

} // namespace

TEST(SoundVoices, AStepTimeThatIsNotAFiniteTimeAboveZeroIsRefusedAndChangesNothing)
{
    // Time is summed over the steps: one NaN made every later voice's time NaN, and a scrape voice sounded
    // for ever; a negative step ran time backwards.
    EventBench bench(1);
    SoundVoices voices(bench.config);
    voices.Step(std::vector<EffectEvent>{bench.Scrape(Type::scrapeBegan, 0, 1, 2.0f * kRule.scrapeStart)},
                kDt);
    ASSERT_EQ(voices.Voices().size(), 1u);
    const double time = voices.Time();
    for (const float dt : {0.0f, -0.0f, -1.0f, std::nanf(""), INFINITY})
    {
        try
        {
            voices.Step({}, dt);
            ADD_FAILURE() << "dt " << dt << " was accepted";
        }
        catch (const InputError& error)
        {
            EXPECT_EQ(error.Diagnostics().front().path, "dt");
            EXPECT_NE(std::string(error.what()).find("expected a finite step time > 0 s"), std::string::npos);
        }
        EXPECT_EQ(voices.Time(), time) << dt;
    }
    voices.Step(std::vector<EffectEvent>{bench.Scrape(Type::scrapeEnded, 0, 1, 0.0f)}, kDt);
    EXPECT_EQ(voices.Time(), time + static_cast<double>(kDt));
}

TEST(SoundVoices, AFlickeringScrapeAboveTheContinueThresholdIsOneVoice)
{
    EventBench bench(1);
    SoundVoices voices(bench.config);
    VoiceLog log;
    // A rock bouncing along: a new scrape every 3 steps, each ending after 2, loud enough to go on but
    // (after the first) below the start threshold.
    const float between = 0.5f * (kRule.scrapeStart + kRule.scrapeStart * kRule.scrapeContinueRatio);
    std::uint32_t id = 1;
    int scrapes = 0;
    for (int step = 0; step < 60; ++step)
    {
        std::vector<EffectEvent> events;
        const float loudness = step == 0 ? 2.0f * kRule.scrapeStart : between;
        if (step % 3 == 0)
        {
            events.push_back(bench.Scrape(Type::scrapeBegan, 0, id, loudness));
            ++scrapes;
        }
        else if (step % 3 == 1)
        {
            events.push_back(bench.Scrape(Type::scrapeChanged, 0, id, loudness));
        }
        else
        {
            events.push_back(bench.Scrape(Type::scrapeEnded, 0, id++, 0.0f));
        }
        voices.Step(events, kDt);
        log.Record(voices);
    }
    EXPECT_EQ(scrapes, 20);
    EXPECT_EQ(log.Count(VoiceKind::scrape), 1);
    EXPECT_EQ(voices.Voices().size(), 1u);

    // Below the start threshold, a new scrape starts nothing.
    EventBench quiet(1);
    SoundVoices quietVoices(quiet.config);
    quietVoices.Step(std::vector{quiet.Scrape(Type::scrapeBegan, 0, 1, between)}, kDt);
    EXPECT_TRUE(quietVoices.Changes().empty());
}

// A trial kept one SoundVoices across level reloads (a new Effects each level, StopAll between): a scrape
// the old level left open started a voice again at the new level's first step, at the old level's place,
// and a new scrape with the same id (a new Effects counts from 1) joined the old level's bodies. StopAll
// now forgets every pair; particle hits still waiting for their merge time are counted, never sounded.
TEST(SoundVoices, StopAllForgetsTheScrapesAndHitsOfTheLevelItEnds)
{
    EventBench bench(2);
    bench.config.sound.rules.back().scrapeWindow = SoundRuleDef{}.scrapeWindow; // the default window
    SoundVoices voices(bench.config);
    const float loud = 2.0f * kRule.scrapeStart;
    voices.Step(std::vector{bench.Scrape(Type::scrapeBegan, 0, 1, loud)}, kDt);
    for (int step = 0; step < 60; ++step) // past the cooldown
    {
        voices.Step(std::vector{bench.Scrape(Type::scrapeChanged, 0, 1, loud)}, kDt);
    }
    ASSERT_EQ(voices.Voices().size(), 1u);
    EffectEvent hits;
    hits.type = Type::particleHits;
    hits.body = bench.boxes[1]->GetBody();
    hits.particleType = bench.config.FindParticleType("dirt");
    hits.count = 5;
    hits.approachSpeed = 3.0f;
    // The level's last step: still scraping, and hits that wait for their merge time.
    voices.Step(std::vector{bench.Scrape(Type::scrapeChanged, 0, 1, loud), hits}, kDt);
    voices.StopAll(); // the level ends without scrapeEnded
    EXPECT_TRUE(voices.Voices().empty());
    EXPECT_EQ(voices.Stats().particleHitVoicesNotStarted, 1u);
    // The next level: a quiet step starts nothing.
    for (int step = 0; step < 5; ++step)
    {
        voices.Step({}, kDt);
        EXPECT_TRUE(voices.Changes().empty()) << "step " << step;
    }
    // Its scrape number 1, on box 1, starts a voice of its own.
    EffectEvent next = bench.Scrape(Type::scrapeBegan, 1, 1, loud);
    next.point = b2Vec2(7.0f, 0.0f);
    for (int step = 0; step < 4; ++step) // the window fills
    {
        voices.Step(std::vector{next}, kDt);
        next.type = Type::scrapeChanged;
    }
    ASSERT_EQ(voices.Voices().size(), 1u);
    EXPECT_EQ(voices.Voices()[0].point.x, 7.0f);
    EXPECT_EQ(voices.Stats().scrapeVoices, 2u);
}

TEST(SoundVoices, AOneStepScrapeSoundsItsMinimumDurationThenFadesOverItsRelease)
{
    EventBench bench(1);
    SoundVoices voices(bench.config);
    VoiceLog log;
    voices.Step(std::vector{bench.Scrape(Type::scrapeBegan, 0, 1, 0.5f)}, kDt);
    log.Record(voices);
    voices.Step(std::vector{bench.Scrape(Type::scrapeEnded, 0, 1, 0.0f)}, kDt);
    log.Record(voices);
    float previous = 1.0f;
    bool faded = false;
    for (int step = 0; step < 60 && !voices.Voices().empty(); ++step)
    {
        voices.Step({}, kDt);
        log.Record(voices);
        if (!voices.Voices().empty() && voices.Voices()[0].releasing)
        {
            EXPECT_LT(voices.Voices()[0].loudness, previous);
            previous = voices.Voices()[0].loudness;
            faded = true;
        }
    }
    ASSERT_EQ(log.lives.size(), 1u);
    const VoiceLog::Life& life = log.lives.begin()->second;
    EXPECT_TRUE(faded);
    EXPECT_EQ(life.stops, 1);
    EXPECT_GE(life.stop - life.start, kRule.minDuration + kRule.release - 1e-6);
    EXPECT_LT(life.stop - life.start, kRule.minDuration + kRule.release + 2.0 * kDt);
}

TEST(SoundVoices, ImpactsOfOnePairMergeWithinTheWindowAndWaitForTheCooldown)
{
    EventBench bench(2);
    SoundVoices voices(bench.config);
    VoiceLog log;
    std::uint32_t id = 1;
    auto step = [&](std::vector<EffectEvent> events)
    {
        voices.Step(events, kDt);
        log.Record(voices);
    };
    step({bench.Impact(0, id++, 0.3f), bench.Impact(1, id++, 0.2f)}); // two pairs: two voices
    EXPECT_EQ(voices.Voices().size(), 2u);
    step({bench.Impact(0, id++, 0.6f)}); // 17 ms later, within the 50 ms window: merged, louder
    EXPECT_EQ(log.Count(VoiceKind::impact), 2);
    EXPECT_FLOAT_EQ(voices.Voices()[0].peak, 0.6f);
    EXPECT_EQ(voices.Stats().impactsMerged, 1u);
    for (int i = 0; i < 3; ++i) // 67 ms: outside the window, inside the 100 ms cooldown
    {
        step({});
    }
    step({bench.Impact(0, id++, 0.9f)});
    EXPECT_EQ(voices.Stats().impactsCooling, 1u);
    EXPECT_EQ(log.Count(VoiceKind::impact), 2);
    for (int i = 0; i < 3; ++i) // 133 ms: a new voice, which replaces the old one of the pair
    {
        step({});
    }
    step({bench.Impact(0, id++, 0.9f)});
    EXPECT_EQ(log.Count(VoiceKind::impact), 3);
    for (int i = 0; i < 30; ++i)
    {
        step({});
    }
    EXPECT_TRUE(voices.Voices().empty()); // every impact decayed within its impactLength
    for (const auto& [voiceId, life] : log.lives)
    {
        EXPECT_EQ(life.starts, 1);
        EXPECT_EQ(life.stops, 1) << voiceId;
        EXPECT_LE(life.stop - life.start, kRule.impactLength + kDt + 1e-6);
    }
}

TEST(SoundVoices, TheCapKeepsTheLoudestAndBreaksTiesByAge)
{
    const int count = 1000;
    EventBench bench(count);
    SoundVoices voices(bench.config);
    std::vector<EffectEvent> events;
    for (int i = 0; i < count; ++i)
    {
        // Loudness in 50 levels, so that ties are many.
        events.push_back(
            bench.Impact(i, static_cast<std::uint32_t>(i + 1), 0.01f + 0.018f * static_cast<float>(i % 50)));
    }
    voices.Step(events, kDt);
    const std::uint32_t cap = bench.config.sound.maxVoices;
    ASSERT_EQ(voices.Voices().size(), cap);
    EXPECT_EQ(voices.Stats().impactsOverCap, static_cast<std::uint64_t>(count) - cap);
    // The loudest level is i % 50 == 49: boxes 49, 99, 149, ... in event order.
    for (std::uint32_t k = 0; k < cap; ++k)
    {
        EXPECT_FLOAT_EQ(voices.Voices()[k].approachSpeed, events[49 + 50 * k].approachSpeed) << k;
    }
    // A louder newcomer takes the place of the quietest sounding voice; a quieter one does not.
    voices.Step(std::vector{bench.Impact(0, 5000, 0.99f), bench.Impact(1, 5001, 0.001f)}, kDt);
    ASSERT_EQ(voices.Voices().size(), cap);
    EXPECT_EQ(voices.Stats().voicesCut, 1u);
    EXPECT_FLOAT_EQ(voices.Voices().back().peak, 0.99f);
}

TEST(SoundVoices, AThousandSimultaneousImpactsSoundAtMostTheCap)
{
    // 1,000 steel boxes falling onto concrete side by side, all touching down in the same step.
    TestWorld test;
    b2Body* ground = test.CreateGround(0.8f, 320.0f);
    EffectsDef def{DefaultPreset()};
    b2World& world = *test.world;
    Effects fx(world, def);
    fx.SetMaterial(ground->GetFixtureList(), fx.FindMaterial("concrete"));
    for (int i = 0; i < 1000; ++i)
    {
        b2Body* box = test.CreateBox(b2Vec2(-300.0f + 0.6f * static_cast<float>(i), 0.3f), 0.2f, 0.2f, 0.5f);
        box->SetLinearVelocity(b2Vec2(0.0f, -6.0f));
        fx.SetMaterial(box->GetFixtureList(), fx.FindMaterial("steel"));
    }
    SoundVoices voices(fx.Config());
    std::size_t mostImpactsInAStep = 0;
    for (int step = 0; step < 30; ++step)
    {
        world.Step(kDt, 8, 3);
        fx.Step(kDt);
        const auto impacts = static_cast<std::size_t>(std::count_if(fx.Events().begin(), fx.Events().end(),
                                                                    [](const EffectEvent& e)
                                                                    { return e.type == Type::impact; }));
        mostImpactsInAStep = std::max(mostImpactsInAStep, impacts);
        voices.Step(fx.Events(), kDt);
        EXPECT_LE(voices.Voices().size(), fx.Config().sound.maxVoices);
    }
    EXPECT_EQ(mostImpactsInAStep, 1000u);
    EXPECT_EQ(voices.Stats().soundingMax, fx.Config().sound.maxVoices);
    std::printf("1000 impacts in one step: %llu impact voices, %llu never sounded, most at once %u\n",
                static_cast<unsigned long long>(voices.Stats().impactVoices),
                static_cast<unsigned long long>(voices.Stats().impactsOverCap), voices.Stats().soundingMax);
}

namespace
{

struct SceneSound
{
    int shortScrapeEvents = 0; ///< scrapes (began .. ended) of fewer steps than 100 ms holds (6 at 60 Hz)
    int scrapeEvents = 0;
    int shortScrapeVoices = 0; ///< scrape voices shorter than 100 ms, not counting those the end cut
    VoiceLog log;
    std::vector<VoiceChange> changes;
};

SceneSound RunScene(const char* name, float seconds)
{
    const SceneEntry& entry = *FindScene(name);
    Simulation simulation(SceneSimulationDef(entry, std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes"));
    SoundVoices voices(simulation.GetEffects().Config());
    SceneSound out;
    std::map<std::uint32_t, std::uint64_t> began; // step of each open scrape's scrape_began
    const auto steps = static_cast<int>(std::lround(seconds / simulation.Dt())); // as the CLI: 1200 for 20 s
    // Counted in whole steps: a 6-step scrape's time difference at 60 Hz is 0.1 give or take rounding.
    const auto shortSteps = static_cast<std::uint64_t>(std::llround(0.1 / simulation.Dt()));
    for (int i = 0; i < steps; ++i)
    {
        StepScene(entry, simulation);
        for (const EffectEvent& event : simulation.GetEffects().Events())
        {
            if (event.type == Type::scrapeBegan)
            {
                began[event.id] = simulation.Steps();
                ++out.scrapeEvents;
            }
            else if (event.type == Type::scrapeEnded && began.count(event.id) != 0)
            {
                out.shortScrapeEvents += simulation.Steps() - began[event.id] < shortSteps ? 1 : 0;
            }
        }
        voices.Step(simulation.GetEffects().Events(), simulation.Dt());
        out.log.Record(voices);
        out.changes.insert(out.changes.end(), voices.Changes().begin(), voices.Changes().end());
    }
    voices.StopAll();
    out.log.Record(voices, true);
    out.changes.insert(out.changes.end(), voices.Changes().begin(), voices.Changes().end());
    double shortest = 1e9;
    for (const auto& [id, life] : out.log.lives)
    {
        if (life.kind == VoiceKind::scrape && !life.stoppedAtEnd)
        {
            shortest = std::min(shortest, life.stop - life.start);
            out.shortScrapeVoices += life.stop - life.start < 0.1 ? 1 : 0;
        }
    }
    std::printf("%s, %.0f s: %d scrape events (%d shorter than 100 ms), %d scrape voices (shortest %.3f s), "
                "%d impact voices, %llu impacts merged, at most %u voices at once\n",
                name, seconds, out.scrapeEvents, out.shortScrapeEvents, out.log.Count(VoiceKind::scrape),
                shortest, out.log.Count(VoiceKind::impact),
                static_cast<unsigned long long>(voices.Stats().impactsMerged), voices.Stats().soundingMax);
    return out;
}

} // namespace

TEST(SoundVoices, ChatteringScenesGiveNoScrapeVoiceShorterThan100Ms)
{
    for (const char* name : {"rockslide", "tutorial"})
    {
        const SceneSound sound = RunScene(name, 20.0f);
        EXPECT_GT(sound.shortScrapeEvents, 0)
            << name << ": the events no longer chatter; the test shows nothing";
        EXPECT_GT(sound.log.Count(VoiceKind::scrape), 0) << name;
        EXPECT_EQ(sound.shortScrapeVoices, 0) << name;
        for (const auto& [id, life] : sound.log.lives)
        {
            EXPECT_EQ(life.starts, 1) << name << " voice " << id;
            EXPECT_EQ(life.stops, 1) << name << " voice " << id;
            EXPECT_GE(life.stop, life.start) << name << " voice " << id;
        }
    }
}

TEST(SoundVoices, SameEventsGiveTheSameVoices)
{
    const SceneSound first = RunScene("rockslide", 5.0f);
    const SceneSound second = RunScene("rockslide", 5.0f);
    ASSERT_EQ(first.changes.size(), second.changes.size());
    for (std::size_t i = 0; i < first.changes.size(); ++i)
    {
        EXPECT_EQ(first.changes[i].voice.id, second.changes[i].voice.id);
        EXPECT_EQ(first.changes[i].time, second.changes[i].time);
        EXPECT_EQ(first.changes[i].voice.loudness, second.changes[i].voice.loudness);
    }
}

TEST(SoundVoices, AnInvalidConfigIsRefusedWithItsPath)
{
    EffectsConfig config = DefaultPreset();
    config.sound.maxVoices = 0;
    try
    {
        SoundVoices voices(config);
        ADD_FAILURE() << "accepted";
    }
    catch (const InputError& error)
    {
        EXPECT_EQ(error.Diagnostics().at(0).path, "sound.maxVoices");
    }
}

} // namespace cfx::test

namespace cfx::test
{

namespace
{

// A trial's scene: a steel block (1 m, 16 kg) landing on concrete at 10 m/s while sliding at 3 m/s, under
// the default preset, at `hz`. The loudest its scrape voice got, and its impact voice.
struct Landing
{
    float scrapePeak = 0.0f;
    float impactPeak = 0.0f;
};

Landing LandWhileSliding(float hz, float scrapeWindow)
{
    TestWorld scene;
    b2Body* ground = scene.CreateGround(0.5f);
    b2Body* block = scene.CreateBox(b2Vec2(0.0f, 0.6f), 0.5f, 0.5f, 0.3f);
    block->GetFixtureList()->SetDensity(16.0f);
    block->ResetMassData();
    block->SetLinearVelocity(b2Vec2(3.0f, -10.0f));
    EffectsConfig config = DefaultPreset();
    SoundRuleDef sound;
    sound.materialA = "steel";
    sound.materialB = "concrete";
    sound.scrapeWindow = scrapeWindow;
    config.sound.rules = {sound};
    Effects& fx = scene.Attach(config);
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(block, fx.FindMaterial("steel"));
    SoundVoices voices(config);
    Landing landing;
    const float dt = 1.0f / hz;
    for (int step = 0; step < static_cast<int>(0.5f * hz); ++step)
    {
        scene.Step(dt);
        voices.Step(fx.Events(), dt);
        for (const SoundVoice& voice : voices.Voices())
        {
            float& peak = voice.kind == VoiceKind::scrape ? landing.scrapePeak : landing.impactPeak;
            peak = std::max(peak, voice.loudness);
        }
    }
    return landing;
}

} // namespace

// A steady scrape reaches its own loudness once the window is full, at any step rate, and rises to it.
TEST(SoundVoices, ASteadyScrapeReachesItsLoudnessOverTheWindow)
{
    for (const float hz : {25.0f, 60.0f, 240.0f, 1000.0f})
    {
        EventBench bench(1);
        bench.config.sound.rules.front().scrapeWindow = 0.04f;
        SoundVoices voices(bench.config);
        const float dt = 1.0f / hz;
        float first = -1.0f;
        const int steps = static_cast<int>(0.1f * hz);
        for (int step = 0; step < steps; ++step)
        {
            voices.Step(
                std::vector{bench.Scrape(step == 0 ? Type::scrapeBegan : Type::scrapeChanged, 0, 1, 0.5f)},
                dt);
            if (first < 0.0f && !voices.Voices().empty())
            {
                first = voices.Voices()[0].loudness;
            }
        }
        ASSERT_EQ(voices.Voices().size(), 1u) << hz << " Hz";
        EXPECT_NEAR(voices.Voices()[0].loudness, 0.5f, 1e-4f) << hz << " Hz";
        if (dt < 0.04f) // a step as long as the window fills it at once
        {
            EXPECT_LT(first, 0.45f) << hz << " Hz: it rises over the window";
        }
    }
}

// The landing's step has the landing's whole impulse as its normal force, so its intensity grows with the
// step rate (1.6, 3.2, 6.4, 12.6 at 30 to 240 Hz), and so did the scrape voice's loudness: none at 30 Hz,
// then 0.15, 0.27, 0.47 (a trial; here 0.29 at 60 Hz and 0.75 at 240). Averaged over scrapeWindow (40 ms),
// the spike's loudness is about the same at every rate (here 0.140 to 0.144): within 10 % of the 120 Hz one.
TEST(SoundVoices, AScrapesLandingSpikeSoundsAlikeAtEveryStepRate)
{
    const float reference = LandWhileSliding(120.0f, SoundRuleDef{}.scrapeWindow).scrapePeak;
    ASSERT_GT(reference, 0.0f);
    for (const float hz : {30.0f, 60.0f, 240.0f})
    {
        const Landing landing = LandWhileSliding(hz, SoundRuleDef{}.scrapeWindow);
        EXPECT_NEAR(landing.scrapePeak, reference, 0.1f * reference) << hz << " Hz";
        EXPECT_GT(landing.impactPeak, 0.5f) << hz << " Hz";
    }
    // Each step's own drive, as before: the spike is louder the higher the rate.
    EXPECT_GT(LandWhileSliding(240.0f, 0.0f).scrapePeak, 1.5f * LandWhileSliding(60.0f, 0.0f).scrapePeak);
}

} // namespace cfx::test
