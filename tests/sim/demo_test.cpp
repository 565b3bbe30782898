// The tutorial scene end to end, through the same Simulation the CLI uses.
#include "contactfx/files/text_file.h"
#include "harness/simulation.h"

#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>

namespace cfx
{

namespace
{

const std::filesystem::path kTutorialScene =
    std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes/physics_driven_particles.json";

std::uint64_t SpawnedOf(const Effects& effects, const char* type)
{
    return effects.Stats().spawnedByType[effects.Config().FindParticleType(type).index];
}

struct DrivenRun
{
    explicit DrivenRun(EffectsConfig config, float seconds = 20.0f, float hz = 60.0f, std::uint64_t seed = 1,
                       bool checkParticles = false)
    {
        SimulationDef def;
        def.particles.checkParticles = checkParticles;
        def.scene = kTutorialScene;
        def.config = std::move(config);
        def.hz = hz;
        def.seed = seed;
        def.drive = TutorialDrive();
        simulation = std::make_unique<Simulation>(def);
        const int steps = static_cast<int>(seconds * hz);
        for (int i = 0; i < steps; ++i)
        {
            simulation->Step();
        }
    }
    std::unique_ptr<Simulation> simulation;
};

} // namespace

TEST(TutorialScene, EveryFixtureGetsItsMaterial)
{
    SimulationDef def;
    def.scene = kTutorialScene;
    Simulation simulation(def);
    const Scene& scene = simulation.GetScene();
    ASSERT_EQ(scene.bodies.size(), 5u);
    for (const SceneFixture& fixture : scene.fixtures)
    {
        const std::string* name = fixture.properties.FindString("material");
        ASSERT_NE(name, nullptr);
        EXPECT_EQ(simulation.GetEffects().Material(fixture.fixture),
                  simulation.GetEffects().FindMaterial(*name));
    }
    ASSERT_TRUE(simulation.GetCar().has_value());
}

TEST(TutorialScene, ScriptedDriveMakesSparksSmokeAndDirtAllOutsideSolids)
{
    DrivenRun run(DefaultPreset(), 20.0f, 60.0f, 1, true); // the check audits every start
    const Effects& effects = run.simulation->GetEffects();
    EXPECT_GT(SpawnedOf(effects, "sparks"), 20u);
    EXPECT_GT(SpawnedOf(effects, "smoke"), 20u);
    EXPECT_GT(SpawnedOf(effects, "dirt"), 20u);
    EXPECT_EQ(effects.Stats().spawnedInsideSolid, 0u);
    EXPECT_LE(effects.Stats().liveMax, effects.Config().budget.capacity);
}

TEST(TutorialScene, TutorialPresetKeepsItsHundredBodyParticles)
{
    DrivenRun run(TutorialPreset(), 12.0f);
    const Effects& effects = run.simulation->GetEffects();
    EXPECT_GT(SpawnedOf(effects, "smoke") + SpawnedOf(effects, "dirt") + SpawnedOf(effects, "sparks"), 100u);
    EXPECT_EQ(effects.Stats().liveMax, 100u);
    // One particle per contact per step at most.
    for (const RuleStats& rule : effects.Stats().rules)
    {
        EXPECT_LE(rule.spawned, static_cast<std::uint64_t>(rule.contactsMax) * effects.Stats().steps);
    }
}

TEST(TutorialScene, SameSeedGivesIdenticalStatsAndParticles)
{
    DrivenRun first(DefaultPreset(), 8.0f);
    DrivenRun second(DefaultPreset(), 8.0f);
    EXPECT_EQ(StatsJson(first.simulation->GetEffects(), 60.0f),
              StatsJson(second.simulation->GetEffects(), 60.0f));
    ParticleView a = first.simulation->GetEffects().Particles();
    ParticleView b = second.simulation->GetEffects().Particles();
    ASSERT_EQ(a.count, b.count);
    ASSERT_GT(a.count, 0u);
    for (std::uint32_t i = 0; i < a.count; ++i)
    {
        ASSERT_EQ(a.positionX[a.Slot(i)], b.positionX[b.Slot(i)]);
        ASSERT_EQ(a.positionY[a.Slot(i)], b.positionY[b.Slot(i)]);
        ASSERT_EQ(a.life[a.Slot(i)], b.life[b.Slot(i)]);
    }
}

TEST(TutorialScene, StatsJsonHasEveryTypeAndRule)
{
    DrivenRun run(DefaultPreset(), 1.0f);
    const std::string json = StatsJson(run.simulation->GetEffects(), 60.0f);
    for (const char* key :
         {"\"steps\": 60", "\"hz\": 60", "\"seconds\": 1", "\"smoke\":", "\"sparks\":", "\"dirt\":",
          "\"concrete+steel\":", "\"concrete+rubber\":", "\"dirt+steel\":", "\"dirt+rubber\":",
          "\"contacts_max\":", "\"live_max\":", "\"spawned_inside_solid\":"})
    {
        EXPECT_NE(json.find(key), std::string::npos) << key << " in " << json;
    }
}

TEST(TutorialScene, HitGroupsOverTheBudgetAreCountedAsDropped)
{
    EffectsConfig config = DefaultPreset();
    config.budget.particleHits = 1;
    DrivenRun run(config, 0.0f);
    std::uint64_t dropped = 0;
    std::uint64_t kept = 0;
    for (int step = 0; step < 1200; ++step)
    {
        run.simulation->Step();
        const std::uint64_t before = dropped;
        dropped = run.simulation->GetEffects().Stats().droppedHitGroups;
        ASSERT_GE(dropped, before);
        int groups = 0;
        for (const EffectEvent& event : run.simulation->GetEffects().Events())
        {
            groups += event.type == EffectEventType::particleHits ? 1 : 0;
        }
        ASSERT_LE(groups, 1) << "step " << step;
        kept += static_cast<std::uint64_t>(groups);
    }
    std::printf("hit groups kept %llu, dropped %llu\n", static_cast<unsigned long long>(kept),
                static_cast<unsigned long long>(dropped));
    EXPECT_GT(kept, 0u);
    EXPECT_GT(dropped, 0u);
    const std::string json = StatsJson(run.simulation->GetEffects(), 60.0f);
    EXPECT_NE(json.find("\"dropped_hit_groups\": " + std::to_string(dropped)), std::string::npos) << json;
}

TEST(TutorialScene, UnknownMaterialNamesTheFixtureProperty)
{
    std::string text = ReadTextFile(kTutorialScene);
    const std::string needle = "\"string\": \"dirt\"";
    std::size_t at = text.find(needle);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, needle.size(), "\"string\": \"glass\"");
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "contactfx_glass_scene.json";
    WriteTextFileAtomically(path, text);
    SimulationDef def;
    def.scene = path;
    try
    {
        Simulation simulation(def);
        FAIL() << "expected InputError";
    }
    catch (const InputError& error)
    {
        const Diagnostic& problem = error.Diagnostics().front();
        EXPECT_EQ(problem.file, path.string());
        EXPECT_EQ(problem.path, "body[0].fixture[0].customProperties[0].string");
        EXPECT_NE(problem.message.find("glass"), std::string::npos);
    }
    std::filesystem::remove(path);
}

} // namespace cfx
