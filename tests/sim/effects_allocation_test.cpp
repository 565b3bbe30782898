// No allocation per step, anywhere: with no more touching contacts than the config's budget.contacts,
// neither the contact callbacks (inside world.Step) nor Effects::Step allocate once the first second has
// passed, in whole scenes with moving bodies: the demo (the tutorial car driven by its script) and the
// debris benchmark scene (200 boxes sliding and piling, the particle budget full). Box2D's own step
// allocates through b2Alloc (malloc), which the counter does not count: what is counted is contactfx's.
#include "allocation_counter.h"
#include "harness/scenes.h"
#include "harness/simulation.h"
#include "scenes/debris_bench.h"
#include "scenes_dir.h"

#include <cstdio>
#include <filesystem>
#include <gtest/gtest.h>

namespace cfx::test
{
namespace
{

// Allocations in steps [warmUp, steps) of `step`, each step that allocated printed.
template <typename Step> long AllocationsAfterWarmUp(int steps, int warmUp, Step&& step)
{
    long total = 0;
    for (int i = 0; i < steps; ++i)
    {
        const long before = Allocations();
        step();
        const long made = Allocations() - before;
        if (i >= warmUp && made > 0)
        {
            std::printf("step %d: %ld allocations\n", i, made);
            total += made;
        }
    }
    return total;
}

TEST(EffectsAllocation, NoneInTheDemoAfterItsFirstSecond)
{
    const SceneEntry& tutorial = *FindScene("tutorial");
    for (float hz : {30.0f, 60.0f, 120.0f})
    {
        SimulationDef def = SceneSimulationDef(tutorial, kScenesDir);
        def.hz = hz;
        Simulation simulation(def);
        const int steps = static_cast<int>(20.0f * hz);
        EXPECT_EQ(
            AllocationsAfterWarmUp(steps, static_cast<int>(hz), [&] { StepScene(tutorial, simulation); }), 0)
            << hz << " Hz";
        EXPECT_GT(simulation.GetEffects().Stats().liveMax, 0u);
    }
}

TEST(EffectsAllocation, NoneInTheDebrisSceneAfterItsFirstSecond)
{
    bench::DebrisBenchScene scene(200);
    EXPECT_EQ(AllocationsAfterWarmUp(600, 60, [&] { scene.Step(); }), 0);
    // The budget was full: at most the particles that died in their last step short of it.
    EXPECT_GE(scene.Fx().Stats().liveMax, scene.Fx().Config().budget.capacity * 9 / 10);
}

TEST(EffectsAllocation, NoneWhenTheStaticGeometryIsRebuilt)
{
    // A rebuild of the static cache (the origin shifted, a static body moved, a static fixture's friction
    // changed) of as many primitives as before allocates nothing: its arrays and tables keep their room.
    const SceneEntry& tutorial = *FindScene("tutorial");
    SimulationDef def = SceneSimulationDef(tutorial, kScenesDir);
    Simulation simulation(def);
    b2World& world = simulation.GetEffects().World();
    b2Body* ground = nullptr;
    for (b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
    {
        ground = body->GetType() == b2_staticBody ? body : ground;
    }
    ASSERT_NE(ground, nullptr);
    const long made = AllocationsAfterWarmUp(600, 60,
                                             [&, step = 0]() mutable
                                             {
                                                 if (step % 60 == 30)
                                                 {
                                                     const b2Vec2 shift(0.5f, 0.0f);
                                                     world.ShiftOrigin(shift);
                                                     simulation.GetEffects().ShiftOrigin(shift);
                                                 }
                                                 else if (step % 60 == 45)
                                                 {
                                                     ground->GetFixtureList()->SetFriction(
                                                         ground->GetFixtureList()->GetFriction() + 0.01f);
                                                 }
                                                 ++step;
                                                 StepScene(tutorial, simulation);
                                             });
    EXPECT_EQ(made, 0);
}

} // namespace
} // namespace cfx::test
