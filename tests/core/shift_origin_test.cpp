// Effects::ShiftOrigin follows b2World::ShiftOrigin: a user's trial found resting dirt left 2 m under a
// ground the world had moved, falling out of it.
#include "contactfx/error.h"
#include "test_world.h"

#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

// A rubber wheel (0.4 m) spinning at -40 rad/s in place on a dirt ground whose top is y = 0 (its spin and
// place set before every step): it throws dirt for as long as the test runs, and the dirt lands and rests
// on the ground.
struct SpinningWheel : TestWorld
{
    explicit SpinningWheel(EffectsConfig config = DefaultPreset())
    {
        particles.checkParticles = true;
        ground = CreateGround(0.8f);
        wheel = CreateCircle(b2Vec2(0.0f, 0.4f), 0.4f, 1.0f);
        Attach(std::move(config));
        effects->SetMaterial(ground, Material("dirt"));
        effects->SetMaterial(wheel, Material("rubber"));
    }

    void Run(int steps)
    {
        for (int i = 0; i < steps; ++i)
        {
            wheel->SetTransform(b2Vec2(-newOrigin.x, wheel->GetPosition().y), wheel->GetAngle());
            wheel->SetLinearVelocity(b2Vec2(0.0f, wheel->GetLinearVelocity().y));
            wheel->SetAngularVelocity(-40.0f);
            Step();
        }
    }

    b2Body* ground = nullptr;
    b2Body* wheel = nullptr;
    b2Vec2 newOrigin{0.0f, 0.0f}; // where the world's origin was shifted to
};

struct Positions
{
    std::vector<float> x, y;
};

Positions LiveParticles(const Effects& effects)
{
    const ParticleView view = effects.Particles();
    Positions positions;
    for (std::uint32_t i = 0; i < view.count; ++i)
    {
        positions.x.push_back(view.positionX[view.Slot(i)]);
        positions.y.push_back(view.positionY[view.Slot(i)]);
    }
    return positions;
}

} // namespace

TEST(ShiftOrigin, ParticlesMoveWithTheWorld)
{
    SpinningWheel scene;
    scene.Run(120);
    ASSERT_GT(scene.Spawned("dirt"), 100u);
    const Positions before = LiveParticles(*scene.effects);
    ASSERT_GT(before.x.size(), 50u);

    const b2Vec2 newOrigin(12.5f, -3.0f); // the ground's top goes to y = 3
    scene.newOrigin = newOrigin;
    scene.world->ShiftOrigin(newOrigin);
    scene.effects->ShiftOrigin(newOrigin);
    const Positions after = LiveParticles(*scene.effects);
    ASSERT_EQ(after.x.size(), before.x.size());
    for (std::size_t i = 0; i < before.x.size(); ++i)
    {
        EXPECT_EQ(after.x[i], before.x[i] - newOrigin.x) << "particle " << i;
        EXPECT_EQ(after.y[i], before.y[i] - newOrigin.y) << "particle " << i;
    }

    // The scrape going on ends where the wheel touches the ground now.
    scene.effects->EndScrapes();
    ASSERT_EQ(scene.effects->Events().size(), 1u);
    const b2Vec2 contact = scene.wheel->GetPosition() - b2Vec2(0.0f, 0.4f);
    EXPECT_LT((scene.effects->Events()[0].point - contact).Length(), 0.2f);

    // Two more seconds of dirt on the moved ground: none under it, none inside, none through it.
    scene.Run(120);
    const Positions later = LiveParticles(*scene.effects);
    ASSERT_GT(later.y.size(), 50u);
    const float groundTop = -newOrigin.y;
    for (std::size_t i = 0; i < later.y.size(); ++i)
    {
        EXPECT_GT(later.y[i], groundTop) << "particle " << i << " at x " << later.x[i];
    }
    EXPECT_EQ(scene.effects->Particles().count, later.y.size());
    EXPECT_EQ(scene.effects->Stats().particleStepsInside, 0u);
    EXPECT_EQ(scene.effects->Stats().crossings, 0u);
}

TEST(ShiftOrigin, ANonFiniteOriginIsRefusedAndChangesNothing)
{
    SpinningWheel scene;
    scene.Run(30);
    const Positions before = LiveParticles(*scene.effects);
    for (const b2Vec2 bad : {b2Vec2(std::nanf(""), 0.0f), b2Vec2(0.0f, INFINITY)})
    {
        try
        {
            scene.effects->ShiftOrigin(bad);
            ADD_FAILURE() << "accepted (" << bad.x << ", " << bad.y << ")";
        }
        catch (const InputError& error)
        {
            EXPECT_NE(std::string(error.what()).find("newOrigin"), std::string::npos) << error.what();
        }
    }
    const Positions after = LiveParticles(*scene.effects);
    EXPECT_EQ(after.x, before.x);
    EXPECT_EQ(after.y, before.y);
}

} // namespace cfx::test
