// The benchmark scenes and `contactfx bench`: each scene is what it says (the particle scene the same in
// both modes; the debris scene deterministic, its pool full of sparks from steel on concrete, its boxes
// piled), and the command prints what it promises (no timing is checked: that is the benchmark's job, not
// a test's).
#include "cli/cli_support.h"
#include "scenes/debris_bench.h"
#include "scenes/particle_bench.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace cfx::test
{

TEST(BenchScene, KeepsTheCountAndLandsParticlesOnTheChain)
{
    for (ParticleBackend backend : {ParticleBackend::pool, ParticleBackend::body})
    {
        bench::ParticleBenchScene scene;
        scene.Populate(300, backend);
        for (int i = 0; i < 150; ++i)
        {
            scene.Step();
            ASSERT_EQ(scene.Particles().Count(), 300u);
        }
        const ParticleView view = scene.Particles().View();
        int resting = 0;
        for (std::uint32_t i = 0; i < view.count; ++i)
        {
            const std::uint32_t slot = view.Slot(i);
            const float x = view.positionX[slot];
            const float ground = 0.5f * std::sin(0.3f * x);
            EXPECT_GT(view.positionY[slot], ground - 0.1f) << "under the chain at x " << x;
            resting += view.positionY[slot] < ground + 0.2f ? 1 : 0;
        }
        EXPECT_GT(resting, 30) << (backend == ParticleBackend::pool ? "pool" : "bodies");
    }
}

TEST(BenchScene, SameSeedSameParticles)
{
    bench::ParticleBenchScene a(5), b(5);
    a.Populate(200, ParticleBackend::pool);
    b.Populate(200, ParticleBackend::pool);
    for (int i = 0; i < 60; ++i)
    {
        a.Step();
        b.Step();
    }
    const ParticleView va = a.Particles().View(), vb = b.Particles().View();
    for (std::uint32_t i = 0; i < va.count; ++i)
    {
        ASSERT_EQ(va.positionX[va.Slot(i)], vb.positionX[vb.Slot(i)]);
        ASSERT_EQ(va.positionY[va.Slot(i)], vb.positionY[vb.Slot(i)]);
    }
}

TEST(BenchCli, ParticlesJsonHasEveryField)
{
    const CliResult result = RunCli("bench particles --count 500 --steps 5 --warmup 2 --mode pool --json");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json out = nlohmann::json::parse(result.output);
    EXPECT_EQ(out["mode"], "pool");
    EXPECT_EQ(out["count"], 500);
    EXPECT_EQ(out["steps"], 5);
    for (const char* key : {"ms_per_step_min", "ms_per_step_median", "bytes_per_particle", "plain_ms_median"})
    {
        ASSERT_TRUE(out.contains(key)) << key;
        EXPECT_GT(out[key].get<double>(), 0.0) << key;
    }
    EXPECT_LE(out["ms_per_step_min"].get<double>(), out["ms_per_step_median"].get<double>());
}

TEST(BenchCli, BothModesAndTheirRatio)
{
    const CliResult text = RunCli("bench particles --count 200 --steps 3 --warmup 1");
    ASSERT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find("pool"), std::string::npos);
    EXPECT_NE(text.output.find("bodies"), std::string::npos);
    EXPECT_NE(text.output.find("faster than a body per particle"), std::string::npos);
    const CliResult json = RunCli("bench particles --count 200 --steps 3 --warmup 1 --json");
    ASSERT_EQ(json.exitCode, 0) << json.output;
    const nlohmann::json out = nlohmann::json::parse(json.output);
    EXPECT_EQ(out["pool"]["mode"], "pool");
    EXPECT_EQ(out["bodies"]["mode"], "bodies");
    EXPECT_GT(out["bodies_over_pool"].get<double>(), 0.0);
}

TEST(BenchCli, DemoComparesWithWorldStepAlone)
{
    const CliResult result = RunCli("bench demo --steps 30 --json");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json out = nlohmann::json::parse(result.output);
    EXPECT_GT(out["world_alone_ms_median"].get<double>(), 0.0);
    EXPECT_GT(out["with_effects_ms_median"].get<double>(), 0.0);
    EXPECT_EQ(out["steps"], 30);
}

TEST(DebrisScene, SameSeedSameState)
{
    // A small pool so that recycling is exercised within the few steps.
    bench::DebrisBenchScene a(60, 7, 512), b(60, 7, 512), other(60, 8, 512);
    for (int i = 0; i < 120; ++i)
    {
        a.Step();
        b.Step();
        other.Step();
        ASSERT_EQ(a.LiveDuringLastStep(), b.LiveDuringLastStep()) << "step " << i;
    }
    EXPECT_EQ(a.StateHash(), b.StateHash());
    EXPECT_EQ(a.Fx().Stats().live, b.Fx().Stats().live);
    EXPECT_EQ(a.Fx().Stats().spawnedByType, b.Fx().Stats().spawnedByType);
    EXPECT_EQ(a.Fx().Stats().recycled, b.Fx().Stats().recycled);
    EXPECT_EQ(a.Dropped(), b.Dropped());
    EXPECT_GT(a.Fx().Stats().recycled, 0u);
    EXPECT_NE(a.StateHash(), other.StateHash()) << "the seed should matter";
}

// The benchmark's own configuration (200 boxes, the default preset's 8,192 particles), four seconds.
TEST(DebrisScene, FillsTheBudgetWithSparksFromSteelOnConcreteAndPilesTheBoxes)
{
    bench::DebrisBenchScene scene(200);
    const EffectsStats& stats = scene.Fx().Stats();
    const std::uint32_t capacity = scene.Fx().Config().budget.capacity;
    ASSERT_EQ(capacity, 8192u) << "the default preset's budget";
    std::uint32_t liveMax = 0;
    int stepsFull = 0;
    for (int i = 0; i < 240; ++i)
    {
        scene.Step();
        liveMax = std::max(liveMax, scene.LiveDuringLastStep());
        stepsFull += i >= 180 && scene.LiveDuringLastStep() == capacity ? 1 : 0;
        ASSERT_LE(stats.live, scene.LiveDuringLastStep());
    }
    EXPECT_EQ(liveMax, capacity);
    EXPECT_GT(stepsFull, 30) << "of the last 60 steps, full while emitting";
    EXPECT_GT(stats.recycled, 0u);
    EXPECT_GT(stats.liveMax, capacity / 2);

    // Every particle is a spark, from the one rule in the scene: steel on concrete.
    const EffectsConfig& config = scene.Fx().Config();
    const int sparks = config.FindParticleType("sparks").index;
    for (std::size_t type = 0; type < stats.spawnedByType.size(); ++type)
    {
        EXPECT_EQ(stats.spawnedByType[type] > 0, static_cast<int>(type) == sparks)
            << config.particleTypes[type].name;
    }
    for (std::size_t rule = 0; rule < config.rules.size(); ++rule)
    {
        const bool steelOnConcrete = config.rules[rule].particleType == "sparks";
        EXPECT_EQ(stats.rules[rule].spawned > 0, steelOnConcrete) << rule;
        if (steelOnConcrete)
        {
            EXPECT_EQ(std::set<std::string>({config.rules[rule].materialA, config.rules[rule].materialB}),
                      std::set<std::string>({"steel", "concrete"}));
            EXPECT_GT(stats.rules[rule].contactsMax, 20u);
        }
    }

    // Boxes went round (onto the ramps and down) and most of them pile in the bin, touching each other.
    EXPECT_GT(scene.Dropped(), 50u);
    EXPECT_GT(scene.BoxesInBin(), 120u);
    EXPECT_GT(scene.BoxesTouchingBoxes(), 120u);
}

TEST(BenchCli, DebrisJsonHasExactlyItsFields)
{
    const CliResult result = RunCli("bench debris --boxes 50 --steps 60 --json");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json out = nlohmann::json::parse(result.output);
    std::set<std::string> keys;
    for (const auto& item : out.items())
    {
        keys.insert(item.key());
    }
    EXPECT_EQ(keys, std::set<std::string>({"boxes", "steps", "world_ms_median", "effects_ms_median",
                                           "effects_ms_p99", "effects_ms_max", "effects_over_world",
                                           "live_max", "ns_per_particle"}));
    EXPECT_EQ(out["boxes"], 50);
    EXPECT_EQ(out["steps"], 60);
    for (const char* key : {"world_ms_median", "effects_ms_median", "effects_ms_p99", "effects_ms_max",
                            "effects_over_world", "ns_per_particle"})
    {
        ASSERT_TRUE(out[key].is_number()) << key;
        EXPECT_GT(out[key].get<double>(), 0.0) << key;
        EXPECT_TRUE(std::isfinite(out[key].get<double>())) << key;
    }
    EXPECT_LE(out["effects_ms_median"].get<double>(), out["effects_ms_p99"].get<double>());
    EXPECT_LE(out["effects_ms_p99"].get<double>(), out["effects_ms_max"].get<double>());
    ASSERT_TRUE(out["live_max"].is_number_unsigned());
    EXPECT_GT(out["live_max"].get<int>(), 0) << "one second of boxes sliding on concrete emits sparks";
    EXPECT_LE(out["live_max"].get<int>(), 8192);
}

TEST(BenchCli, DebrisText)
{
    const CliResult result = RunCli("bench debris --boxes 20 --steps 10");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("contactfx bench debris: 20 steel boxes"), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("world.Step"), std::string::npos);
    EXPECT_NE(result.output.find("Effects::Step"), std::string::npos);
    EXPECT_NE(result.output.find("effects / world"), std::string::npos);
}

TEST(BenchCli, DebrisBadFlagsNameTheFlag)
{
    const std::pair<const char*, const char*> cases[] = {
        {"bench debris --boxes 0", "--boxes"},      {"bench debris --boxes 10001", "--boxes"},
        {"bench debris --boxes abc", "--boxes"},    {"bench debris --boxes", "--boxes"},
        {"bench debris --steps 0", "--steps"},      {"bench debris --steps -1", "--steps"},
        {"bench debris --steps 100001", "--steps"}, {"bench debris --count 5", "--count"},
    };
    for (const auto& [args, flag] : cases)
    {
        const CliResult result = RunCli(args);
        EXPECT_EQ(result.exitCode, 1) << args << "\n" << result.output;
        EXPECT_NE(result.output.find("error"), std::string::npos) << args;
        EXPECT_NE(result.output.find(flag), std::string::npos) << args << "\n" << result.output;
        EXPECT_EQ(result.output.find("terminate"), std::string::npos) << args;
    }
}

TEST(BenchCli, BadFlagsExitWithOne)
{
    for (const char* args : {"bench particles", "bench particles --count 0", "bench particles --count abc",
                             "bench particles --count 10 --mode gpu", "bench particles --count 10 --steps -1",
                             "bench demo --steps 0", "bench"})
    {
        const CliResult result = RunCli(args);
        EXPECT_EQ(result.exitCode, 1) << args << "\n" << result.output;
        EXPECT_NE(result.output.find("error"), std::string::npos) << args;
        EXPECT_EQ(result.output.find("terminate"), std::string::npos) << args;
    }
}

} // namespace cfx::test
