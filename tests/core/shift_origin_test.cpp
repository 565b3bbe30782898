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

std::uint64_t ParticleHitEvents(const Effects& effects)
{
    std::uint64_t count = 0;
    for (const EffectEvent& event : effects.Events())
    {
        count += event.type == EffectEventType::particleHits ? 1u : 0u;
    }
    return count;
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
    EXPECT_EQ(scene.effects->Stats().passedThroughMoving, 0u);
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

// Box2D's ShiftOrigin moves the broad phase's boxes, not the boxes fixtures keep themselves (GetAABB), which
// a static body's fixtures never refresh: a trial's spawn placement read those and started every spark
// inside a static slab after a shift (458 spawned, all crushed), where without a shift all were refused. A
// steel box slides through a static slab it does not collide with, but the sparks do: every start near the
// contact is inside the slab.
TEST(ShiftOrigin, StartsStayOutsideStaticFixturesAfterAShift)
{
    for (const float shift : {0.0f, 30.0f, -200.0f})
    {
        SCOPED_TRACE(testing::Message() << "shift " << shift << " m");
        TestWorld scene;
        scene.particles.checkParticles = true;
        b2Body* ground = scene.CreateGround();
        b2Filter groundFilter;
        groundFilter.categoryBits = 0x0010;
        ground->GetFixtureList()->SetFilterData(groundFilter);
        b2Body* slab = scene.CreateBox(b2Vec2(10.0f, 0.5f), 20.0f, 0.5f, 0.5f, b2_staticBody);
        b2Filter slabFilter;
        slabFilter.categoryBits = 0x0001;
        slabFilter.maskBits = 0x0002;
        slab->GetFixtureList()->SetFilterData(slabFilter);
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.25f), 0.5f, 0.25f, 0.6f);
        b2Filter boxFilter;
        boxFilter.categoryBits = 0x0004;
        boxFilter.maskBits = 0x0010;
        box->GetFixtureList()->SetFilterData(boxFilter);
        EffectsConfig config = DefaultPreset();
        for (ParticleTypeDef& type : config.particleTypes)
        {
            type.maskBits = 0x0001 | 0x0010; // the slab and the ground
        }
        scene.Attach(config);
        scene.effects->SetMaterial(ground, scene.Material("concrete"));
        scene.effects->SetMaterial(box, scene.Material("steel"));
        scene.world->ShiftOrigin(b2Vec2(shift, 0.0f));
        scene.effects->ShiftOrigin(b2Vec2(shift, 0.0f));
        box->SetLinearVelocity(b2Vec2(10.0f, 0.0f));
        int inSlab = 0;
        for (int step = 0; step < 60; ++step)
        {
            scene.Step();
            const ParticleView view = scene.effects->Particles();
            for (std::uint32_t i = 0; i < view.count; ++i)
            {
                const b2Vec2 p(view.positionX[view.Slot(i)], view.positionY[view.Slot(i)]);
                inSlab += slab->GetFixtureList()->TestPoint(p) ? 1 : 0;
            }
        }
        const EffectsStats& stats = scene.effects->Stats();
        EXPECT_GT(stats.spawnRejected, 100u) << "the box slid and its sparks had nowhere to start";
        EXPECT_EQ(scene.Spawned("sparks"), 0u);
        EXPECT_EQ(stats.crushed, 0u);
        EXPECT_EQ(stats.spawnedInsideSolid, 0u);
        EXPECT_EQ(inSlab, 0);
    }
}

// Shifting the origin between world.Step and Effects::Step is as good as before world.Step: a trial shifted
// by 1 m there and that step's sparks started 1 m off (where the boxes' own stale GetAABB said they were),
// with 8 hit groups more. Eight steel boxes slide on concrete; the origin moves by 1 m every 10 steps, in
// one world before world.Step, in the other after it.
TEST(ShiftOrigin, BetweenTheWorldStepAndTheEffectsStepIsAsGoodAsBeforeTheWorldStep)
{
    struct Slide : TestWorld
    {
        Slide()
        {
            b2Body* ground = CreateGround();
            Attach();
            effects->SetMaterial(ground, Material("concrete"));
            for (int k = 0; k < 8; ++k)
            {
                b2Body* box =
                    CreateBox(b2Vec2(-20.0f + 5.0f * static_cast<float>(k), 0.25f), 0.4f, 0.25f, 0.6f);
                effects->SetMaterial(box, Material("steel"));
                box->SetLinearVelocity(b2Vec2(8.0f, 0.0f));
            }
        }
        void Shift()
        {
            world->ShiftOrigin(b2Vec2(1.0f, 0.0f));
            effects->ShiftOrigin(b2Vec2(1.0f, 0.0f));
        }
    };
    Slide before, after;
    constexpr float kStepTime = 1.0f / 60.0f;
    float farthest = 0.0f;
    std::uint64_t hitsBefore = 0, hitsAfter = 0;
    for (int step = 0; step < 120; ++step)
    {
        const bool shift = step % 10 == 5;
        if (shift)
        {
            before.Shift();
        }
        before.world->Step(kStepTime, 8, 3);
        after.world->Step(kStepTime, 8, 3);
        if (shift)
        {
            after.Shift();
        }
        before.effects->Step(kStepTime);
        after.effects->Step(kStepTime);
        const ParticleView a = before.effects->Particles();
        const ParticleView b = after.effects->Particles();
        ASSERT_EQ(a.count, b.count) << "step " << step;
        for (std::uint32_t i = 0; i < a.count; ++i)
        {
            farthest = std::max(farthest, b2Distance(b2Vec2(a.positionX[a.Slot(i)], a.positionY[a.Slot(i)]),
                                                     b2Vec2(b.positionX[b.Slot(i)], b.positionY[b.Slot(i)])));
        }
        hitsBefore += ParticleHitEvents(*before.effects);
        hitsAfter += ParticleHitEvents(*after.effects);
    }
    EXPECT_GT(before.Spawned("sparks"), 500u);
    EXPECT_LT(farthest, 1.0e-3f) << "the same particles, up to rounding in the bodies' positions";
    EXPECT_EQ(hitsAfter, hitsBefore);
}

} // namespace cfx::test
