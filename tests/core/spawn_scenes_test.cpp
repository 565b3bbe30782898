// Spawn never inside, in every scene of the project: each registered scene is run through the harness
// (the same Simulation and per-step actions the CLI and the testbed use) for a few seconds, with its own
// effects config and with the tutorial preset, at 30, 60 and 120 Hz, and no particle starts inside a solid.
#include "harness/scenes.h"
#include "scenes_dir.h"
#include "test_world.h"

#include <cmath>
#include <gtest/gtest.h>
#include <set>

namespace cfx
{

namespace
{

// Steps `entry`'s simulation `steps` times (the scene's own drive) and gives its stats.
EffectsStats RunScene(const SceneEntry& entry, const SimulationDef& def, int steps)
{
    Simulation simulation(def);
    for (int i = 0; i < steps; ++i)
    {
        StepScene(entry, simulation);
    }
    return simulation.GetEffects().Stats();
}

std::uint64_t Spawned(const EffectsStats& stats)
{
    std::uint64_t spawned = 0;
    for (std::uint64_t n : stats.spawnedByType)
    {
        spawned += n;
    }
    return spawned;
}

} // namespace

TEST(SpawnScenes, EverySceneFileIsRegistered)
{
    std::set<std::string> registered;
    for (const SceneEntry& entry : Scenes())
    {
        registered.insert(std::string(entry.file));
    }
    for (const auto& file : std::filesystem::directory_iterator(kScenesDir))
    {
        const std::string name = file.path().filename().string();
        if (file.path().extension() == ".json" && name.find(".effects.") == std::string::npos)
        {
            EXPECT_TRUE(registered.contains(name)) << name << " is not in the scene registry";
        }
    }
}

TEST(SpawnScenes, NoParticleStartsInsideInAnyScene)
{
    for (float hz : {30.0f, 60.0f, 120.0f})
    {
        for (const SceneEntry& entry : Scenes())
        {
            for (bool tutorial : {false, true})
            {
                SCOPED_TRACE(std::string(entry.name) + (tutorial ? " (tutorial preset) " : " ") +
                             std::to_string(hz) + " Hz");
                SimulationDef def = SceneSimulationDef(entry, kScenesDir);
                if (tutorial)
                {
                    def.config = TutorialPreset();
                }
                def.hz = hz;
                def.particles.checkParticles = true; // audits every start (spawnedInsideSolid)
                const EffectsStats stats = RunScene(entry, def, static_cast<int>(std::lround(8.0f * hz)));
                const std::uint64_t spawned = Spawned(stats);
                EXPECT_GT(spawned, 100u);
                EXPECT_EQ(stats.spawnedInsideSolid, 0u);
                EXPECT_LT(stats.spawnRejected, spawned / 10) << "rejections are the exception";
            }
        }
    }
}

// A trial set every particle radius to 1e-6 m (valid then): the demo counted 18,906 particle steps inside
// solids, float rounding at coordinates of metres being larger than the particles. The range now starts at
// 1 mm, and the guarantees hold there: every scene, its particles all 1 mm, no step inside, no crossing.
TEST(SpawnScenes, TheSmallestRadiusKeepsEveryParticleOutside)
{
    for (const SceneEntry& entry : Scenes())
    {
        SCOPED_TRACE(entry.name);
        SimulationDef def = SceneSimulationDef(entry, kScenesDir);
        for (ParticleTypeDef& type : def.config.particleTypes)
        {
            type.radius = 0.001f;
        }
        ASSERT_TRUE(Validate(def.config).empty());
        def.particles.checkParticles = true;
        const EffectsStats stats = RunScene(entry, def, 1200); // 20 s: the rockslide's rocks come down
        EXPECT_GT(Spawned(stats), 100u);
        EXPECT_EQ(stats.particleStepsInside, 0u);
        EXPECT_EQ(stats.crossings, 0u);
        EXPECT_EQ(stats.passedThroughMoving, 0u);
        EXPECT_EQ(stats.spawnedInsideSolid, 0u);
    }
    EffectsConfig smaller = DefaultPreset();
    smaller.particleTypes[0].radius = 0.0009f;
    const std::vector<Diagnostic> problems = Validate(smaller);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].path, "particleTypes[0].radius");
}

// The CLI's stats file reports the rejected starts: a block on a slab running under it, held in a slot
// too narrow for a spark.
TEST(SpawnScenes, StatsFileCountsRejectedStarts)
{
    test::TestWorld scene;
    b2BodyDef slabDef;
    slabDef.type = b2_kinematicBody;
    slabDef.position = b2Vec2(0.0f, -0.5f);
    b2Body* slab = scene.world->CreateBody(&slabDef);
    b2PolygonShape box;
    box.SetAsBox(60.0f, 0.5f);
    slab->CreateFixture(&box, 0.0f)->SetFriction(0.8f);
    slab->SetLinearVelocity(b2Vec2(8.0f, 0.0f));
    b2Body* block = scene.CreateBox(b2Vec2(0.0f, 0.255f), 0.5f, 0.25f, 0.5f);
    b2BodyDef wallDef;
    b2Body* walls = scene.world->CreateBody(&wallDef);
    box.SetAsBox(2.0f, 0.5f, b2Vec2(-2.51f, 0.505f), 0.0f);
    walls->CreateFixture(&box, 0.0f);
    box.SetAsBox(2.0f, 0.5f, b2Vec2(2.51f, 0.505f), 0.0f);
    walls->CreateFixture(&box, 0.0f);
    Effects& fx = scene.Attach();
    fx.SetMaterial(slab, fx.FindMaterial("concrete"));
    fx.SetMaterial(block, fx.FindMaterial("steel"));
    for (int i = 0; i < 60; ++i)
    {
        scene.Step();
    }
    const std::uint64_t rejected = fx.Stats().spawnRejected;
    ASSERT_GT(rejected, 0u);
    const std::string json = StatsJson(fx, 60.0f);
    EXPECT_NE(json.find("\"spawn_rejected\": " + std::to_string(rejected)), std::string::npos) << json;
    EXPECT_NE(json.find("\"spawned_inside_solid\": 0"), std::string::npos) << json;
}

} // namespace cfx
