// The benchmark scene and `contactfx bench`: the scene is what it says, the same in both modes, and the
// command prints what it promises (no timing is checked: that is the benchmark's job, not a test's).
#include "cli/cli_support.h"
#include "scenes/particle_bench.h"

#include <cmath>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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
