#include "effects_access.h"
#include "test_world.h"

#include <cmath>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

// A steel box pushed along concrete at a constant speed for `seconds`; returns the sparks emitted.
std::uint64_t SlideBox(EffectsConfig config, float speed, float hz = 60.0f, float seconds = 2.0f,
                       bool swapMaterials = false, std::uint64_t* contactsMax = nullptr)
{
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* box = scene.CreateBox(b2Vec2(-10.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    Effects& fx = scene.Attach(std::move(config));
    fx.SetMaterial(ground, fx.FindMaterial(swapMaterials ? "steel" : "concrete"));
    fx.SetMaterial(box, fx.FindMaterial(swapMaterials ? "concrete" : "steel"));
    const float dt = 1.0f / hz;
    const int steps = static_cast<int>(std::lround(seconds * hz));
    for (int i = 0; i < steps; ++i)
    {
        // Hold the slide speed exactly at the moment effects look at it, whatever the step rate.
        scene.world->Step(dt, 8, 3);
        box->SetLinearVelocity(b2Vec2(speed, box->GetLinearVelocity().y));
        box->SetAngularVelocity(0.0f);
        fx.Step(dt);
    }
    if (contactsMax != nullptr)
    {
        *contactsMax = fx.Stats().rules[0].contactsMax;
    }
    return scene.Spawned("sparks");
}

} // namespace

TEST(Emission, SteelSlidingOnConcreteAboveThresholdGivesSparks)
{
    // tangential speed 4 m/s * sqrt(0.5 * 0.8) = 2.5 > threshold 1
    EXPECT_GT(SlideBox(DefaultPreset(), 4.0f), 50u);
}

TEST(Emission, SteelSlidingOnConcreteBelowThresholdGivesNone)
{
    // 1 m/s * 0.63 * (1 + pressure) < 1
    EXPECT_EQ(SlideBox(DefaultPreset(), 1.0f), 0u);
}

TEST(Emission, PairOrderDoesNotMatter)
{
    EffectsConfig swapped = DefaultPreset();
    std::swap(swapped.rules[0].materialA, swapped.rules[0].materialB);
    std::uint64_t normal = SlideBox(DefaultPreset(), 4.0f);
    EXPECT_EQ(SlideBox(swapped, 4.0f), normal);
    EXPECT_EQ(SlideBox(DefaultPreset(), 4.0f, 60.0f, 2.0f, true), normal) << "concrete box on steel ground";
}

TEST(Emission, ManifoldPointsShareOneRate)
{
    // The box's flat face touches at two points: one sliding contact, one rate. Sampling both points or
    // only the first gives the same count (the pair's pressure is the same either way) ...
    EffectsConfig firstOnly = DefaultPreset();
    firstOnly.rules[0].intensity.points = ManifoldPoints::first;
    const std::uint64_t first = SlideBox(firstOnly, 4.0f);
    const std::uint64_t all = SlideBox(DefaultPreset(), 4.0f);
    ASSERT_GT(first, 100u);
    EXPECT_NEAR(static_cast<double>(all) / static_cast<double>(first), 1.0, 0.05);

    // ... and with both sampled, the particles are shared out over both corners by their pressure (friction
    // loads the leading corner more). All of them start behind the box, the side sparks leave to.
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* box = scene.CreateBox(b2Vec2(-10.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    EffectsConfig still = DefaultPreset();
    ParticleTypeDef& sparks = still.particleTypes[still.FindParticleType("sparks").index];
    sparks.spread = sparks.normalSpeed = sparks.slipFactor = sparks.gravityScale = 0.0f;
    sparks.collide = false;
    Effects& fx = scene.Attach(still);
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(box, fx.FindMaterial("steel"));
    int rear = 0;
    int front = 0;
    for (int i = 0; i < 120; ++i)
    {
        box->SetLinearVelocity(b2Vec2(4.0f, box->GetLinearVelocity().y));
        box->SetAngularVelocity(0.0f);
        scene.Step();
        const ParticleView view = fx.Particles();
        for (std::uint32_t k = view.count - fx.Stats().rules[0].spawnedLastStep; k < view.count; ++k)
        {
            // Behind the rear face: the rear corner's particles at the first free place, within 0.05 m;
            // the front corner's walked the box's length back under it, and start further out.
            const float behindRear = box->GetPosition().x - 0.5f - view.positionX[view.Slot(k)];
            EXPECT_GT(behindRear, 0.0f) << "step " << i;
            (behindRear < 0.05f ? rear : front) += 1;
        }
    }
    EXPECT_GT(rear, (rear + front) / 10);
    EXPECT_GT(front, rear);
}

TEST(Emission, RateDoesNotDependOnTheStepRate)
{
    const std::uint64_t at60 = SlideBox(DefaultPreset(), 4.0f, 60.0f);
    ASSERT_GT(at60, 100u);
    for (float hz : {30.0f, 120.0f, 240.0f})
    {
        const std::uint64_t count = SlideBox(DefaultPreset(), 4.0f, hz);
        EXPECT_NEAR(static_cast<double>(count) / static_cast<double>(at60), 1.0, 0.05) << hz << " Hz";
    }
}

TEST(Emission, TutorialModeEmitsOneParticlePerContactPerStep)
{
    EffectsConfig tutorial = TutorialPreset();
    // 4 m/s * 0.5 * 0.8 = 1.6 > 1: every step of the 2 s slide emits exactly one particle.
    std::uint64_t at60 = SlideBox(tutorial, 4.0f, 60.0f);
    EXPECT_GE(at60, 118u);
    EXPECT_LE(at60, 120u);
    std::uint64_t at120 = SlideBox(tutorial, 4.0f, 120.0f);
    EXPECT_GE(at120, 236u);
    EXPECT_LE(at120, 240u);
}

TEST(Emission, RubberSpinningOnConcreteGivesSmoke)
{
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* wheel = scene.CreateCircle(b2Vec2(0.0f, 0.4f), 0.4f, 0.9f);
    scene.particles.checkParticles = true; // audits every start (spawnedInsideSolid)
    Effects& fx = scene.Attach();
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(wheel, fx.FindMaterial("rubber"));
    for (int i = 0; i < 120; ++i)
    {
        wheel->SetAngularVelocity(-25.0f); // spinning in place: 10 m/s at the tread
        wheel->SetLinearVelocity(b2Vec2(0.0f, wheel->GetLinearVelocity().y));
        scene.Step();
    }
    EXPECT_GT(scene.Spawned("smoke"), 50u);
    EXPECT_EQ(scene.Spawned("sparks"), 0u);
    EXPECT_EQ(fx.Stats().spawnedInsideSolid, 0u);
}

TEST(Emission, SteelOnRubberGivesNothing)
{
    TestWorld scene;
    b2Body* ground = scene.CreateBox(b2Vec2(0.0f, -1.0f), 50.0f, 1.0f, 0.9f, b2_staticBody);
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    Effects& fx = scene.Attach();
    fx.SetMaterial(ground, fx.FindMaterial("rubber"));
    fx.SetMaterial(box, fx.FindMaterial("steel"));
    for (int i = 0; i < 120; ++i)
    {
        box->SetLinearVelocity(b2Vec2(6.0f, box->GetLinearVelocity().y));
        scene.Step();
    }
    EXPECT_EQ(detail::EffectsAccess::Tracker(fx).TrackedCount(), 0u);
    for (std::uint64_t spawned : fx.Stats().spawnedByType)
    {
        EXPECT_EQ(spawned, 0u);
    }
}

TEST(Emission, ThresholdIsPerRule)
{
    EffectsConfig high = DefaultPreset();
    high.rules[0].threshold = 100.0f;
    EXPECT_EQ(SlideBox(high, 4.0f), 0u);
    EffectsConfig low = DefaultPreset();
    low.rules[0].threshold = 0.1f;
    EXPECT_GT(SlideBox(low, 1.0f), 0u);
}

TEST(Emission, RateGrowsWithIntensity)
{
    std::uint64_t slow = SlideBox(DefaultPreset(), 3.0f);
    std::uint64_t fast = SlideBox(DefaultPreset(), 6.0f);
    EXPECT_GT(slow, 0u);
    EXPECT_GT(fast, 2 * slow);
}

TEST(Emission, SameSeedSameParticlesOtherSeedOthers)
{
    auto run = [](std::uint64_t seed)
    {
        TestWorld scene;
        b2Body* ground = scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        Effects& fx = scene.Attach(DefaultPreset(), seed);
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(box, fx.FindMaterial("steel"));
        for (int i = 0; i < 60; ++i)
        {
            box->SetLinearVelocity(b2Vec2(5.0f, box->GetLinearVelocity().y));
            scene.Step();
        }
        std::vector<float> state;
        ParticleView view = fx.Particles();
        for (std::uint32_t i = 0; i < view.count; ++i)
        {
            std::uint32_t slot = view.Slot(i);
            state.insert(state.end(), {view.positionX[slot], view.positionY[slot], view.velocityX[slot],
                                       view.velocityY[slot], view.life[slot]});
        }
        return state;
    };
    std::vector<float> a = run(7);
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, run(7));
    EXPECT_NE(a, run(8));
}

} // namespace cfx::test
