// Simulation::ReplaceEffects (the testbed's live edits) and the step times it reports.
#include "harness/scenes.h"
#include "scenes_dir.h"

#include <box2d/b2_body.h>
#include <gtest/gtest.h>

namespace cfx
{

namespace
{

std::unique_ptr<Simulation> Grinder(float seconds)
{
    const SceneEntry& entry = *FindScene("grinder");
    auto simulation = std::make_unique<Simulation>(SceneSimulationDef(entry, kScenesDir));
    for (int i = 0; i < static_cast<int>(seconds / simulation->Dt()); ++i)
    {
        StepScene(entry, *simulation);
    }
    return simulation;
}

std::uint64_t Spawned(const Effects& effects, const char* type)
{
    return effects.Stats().spawnedByType[effects.Config().FindParticleType(type).index];
}

// The default preset with steel on concrete making smoke instead of sparks.
EffectsConfig SmokingGrinder()
{
    EffectsConfig config = DefaultPreset();
    for (RuleDef& rule : config.rules)
    {
        if (rule.particleType == "sparks")
        {
            rule.particleType = "smoke";
        }
    }
    return config;
}

} // namespace

TEST(ReplaceEffects, KeepsTheWorldAndPicksUpContactsAlreadyTouching)
{
    std::unique_ptr<Simulation> simulation = Grinder(1.0f);
    ASSERT_GT(Spawned(simulation->GetEffects(), "sparks"), 0u);
    const b2Body* bar = simulation->GetScene().FindBody("steel_bar")->body;
    const b2Vec2 position = bar->GetPosition();
    const float angle = bar->GetAngle();
    const std::uint64_t steps = simulation->Steps();

    simulation->ReplaceEffects(SmokingGrinder());
    EXPECT_EQ(bar->GetPosition().x, position.x);
    EXPECT_EQ(bar->GetPosition().y, position.y);
    EXPECT_EQ(bar->GetAngle(), angle);
    EXPECT_EQ(simulation->Steps(), steps);
    EXPECT_EQ(simulation->GetEffects().Stats().live, 0u);
    EXPECT_EQ(simulation->GetEffects().Config(), SmokingGrinder());

    // The bar never left the wheel, so no new BeginContact comes: the new effects still see it.
    for (int i = 0; i < 30; ++i)
    {
        simulation->Step();
    }
    EXPECT_GT(Spawned(simulation->GetEffects(), "smoke"), 0u);
    EXPECT_EQ(Spawned(simulation->GetEffects(), "sparks"), 0u);
}

TEST(ReplaceEffects, RefusesABadConfigAndKeepsTheEffectsInForce)
{
    std::unique_ptr<Simulation> simulation = Grinder(0.5f);
    const std::uint32_t live = simulation->GetEffects().Stats().live;
    ASSERT_GT(live, 0u);

    EffectsConfig invalid = DefaultPreset();
    invalid.rules[0].threshold = -1.0f;
    EXPECT_THROW(simulation->ReplaceEffects(invalid), InputError);

    EffectsConfig noConcrete = DefaultPreset(); // valid, but the scene's fixtures name concrete
    noConcrete.rules.clear();
    noConcrete.assignments.clear();
    std::erase(noConcrete.materials, std::string("concrete"));
    ASSERT_TRUE(Validate(noConcrete).empty());
    try
    {
        simulation->ReplaceEffects(noConcrete);
        ADD_FAILURE() << "a config without the scene's materials was accepted";
    }
    catch (const InputError& error)
    {
        EXPECT_NE(std::string(error.what()).find("concrete"), std::string::npos) << error.what();
    }

    EXPECT_EQ(simulation->GetEffects().Config(), DefaultPreset());
    EXPECT_EQ(simulation->GetEffects().Stats().live, live);
    const std::uint64_t before = Spawned(simulation->GetEffects(), "sparks");
    simulation->Step();
    EXPECT_GT(Spawned(simulation->GetEffects(), "sparks"), before); // still listening to the world
}

TEST(SimulationStepTimes, AreZeroBeforeTheFirstStepAndMeasuredAfter)
{
    const SceneEntry& entry = *FindScene("rockslide");
    Simulation simulation(SceneSimulationDef(entry, kScenesDir));
    EXPECT_EQ(simulation.LastStepTimes().worldMs, 0.0);
    EXPECT_EQ(simulation.LastStepTimes().effectsMs, 0.0);
    double total = 0.0;
    for (int i = 0; i < 10; ++i)
    {
        StepScene(entry, simulation);
        EXPECT_GE(simulation.LastStepTimes().worldMs, 0.0);
        EXPECT_GE(simulation.LastStepTimes().effectsMs, 0.0);
        total += simulation.LastStepTimes().worldMs + simulation.LastStepTimes().effectsMs;
    }
    EXPECT_GT(total, 0.0);
}

} // namespace cfx
