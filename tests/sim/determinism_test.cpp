// Determinism you can check, as Box2D's own determinism test does: the hash of a reference run (every
// event, then the live particles, bit for bit; harness/state_hash.h) is stored here and every build must
// reproduce it, with one thread and with two. A change that moves one bit of one event or particle changes
// the hash: update the stored value (and say why in the commit) only when the change means to.
#include "cli/cli_support.h"
#include "harness/scenes.h"
#include "scenes_dir.h"

#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cfx
{

namespace
{

constexpr std::uint64_t kSteps = 1200; // 20 s at 60 Hz: `contactfx demo` as it is

struct Reference
{
    std::string_view scene;
    std::string_view hash; ///< StateHash::Hex() after kSteps steps
};

constexpr Reference kReferences[] = {
    {"tutorial", "384f9742851624f7"},
    {"rockslide", "30d6205777464b7f"},
};

std::string RunHash(std::string_view name, unsigned threads)
{
    const SceneEntry* entry = FindScene(name);
    SimulationDef def = SceneSimulationDef(*entry, kScenesDir);
    def.particles.threads = threads;
    def.particles.minParticlesPerThread = 1; // split every step, however few particles
    Simulation simulation(def);
    for (std::uint64_t i = 0; i < kSteps; ++i)
    {
        StepScene(*entry, simulation);
    }
    return simulation.RunHash().Hex();
}

} // namespace

TEST(Determinism, ReferenceRunsReproduceTheirStoredHashesWithOneAndTwoThreads)
{
    for (const Reference& reference : kReferences)
    {
        for (const unsigned threads : {1u, 2u})
        {
            EXPECT_EQ(RunHash(reference.scene, threads), reference.hash)
                << reference.scene << " with " << threads << " thread(s)";
        }
    }
}

// The same through the command line: `contactfx demo --threads N --stats FILE` writes the tutorial's hash.
TEST(Determinism, TheDemoStatsCarryTheStoredHash)
{
    const std::filesystem::path dir = test::ScratchDir("determinism-demo");
    for (const char* threads : {"1", "2"})
    {
        const std::filesystem::path stats = dir / (std::string("stats-") + threads + ".json");
        const test::CliResult result =
            test::RunCli(std::string("demo --threads ") + threads + " --stats " + stats.string());
        ASSERT_EQ(result.exitCode, 0) << result.output;
        const nlohmann::json json = nlohmann::json::parse(test::FileText(stats));
        EXPECT_EQ(json["state_hash"], std::string(kReferences[0].hash)) << threads << " thread(s)";
    }
}

} // namespace cfx
