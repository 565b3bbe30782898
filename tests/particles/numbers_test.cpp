// Absurd numbers never reach the collision: particles thrown out of the world die and are counted, bodies
// with state that is not finite are left out and counted, and duplicated fixtures are met once.
#include "particle_pool_fixture.h"
#include "particles/world_geometry.h"

#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <cmath>
#include <gtest/gtest.h>
#include <limits>

namespace cfx::test
{

namespace
{

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool AllFinite(const Pool& scene)
{
    for (std::uint32_t i = 0; i < scene.system->Count(); ++i)
    {
        const b2Vec2 p = scene.Position(i), v = scene.Velocity(i);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) || !std::isfinite(v.y))
        {
            return false;
        }
    }
    return true;
}

} // namespace

TEST(ParticleNumbers, SpawnsThatAreNotFiniteAreRefusedAndCounted)
{
    for (const ParticleBackend backend : {ParticleBackend::pool, ParticleBackend::body})
    {
        Pool scene({Ball(0.0f, 0.5f, backend)});
        scene.CreateGround();
        scene.Add(b2Vec2(kNaN, 1.0f));
        scene.Add(b2Vec2(0.0f, kInf));
        scene.Add(b2Vec2(0.0f, 1.0f), b2Vec2(kNaN, 0.0f));
        scene.Add(b2Vec2(0.0f, 1.0f), b2Vec2(0.0f, -3.0e38f));
        scene.Add(b2Vec2(2.0e7f, 1.0f));
        scene.Add(b2Vec2(0.0f, 1.0f), b2Vec2(0.0f, 0.0f), kNaN);  // a trial's was dropped and not counted
        scene.Add(b2Vec2(0.0f, 1.0f), b2Vec2(0.0f, 0.0f), -1.0f); // not added, not counted: life <= 0
        scene.Add(b2Vec2(0.0f, 1.0f));                            // the only sane one
        EXPECT_EQ(scene.system->Count(), 1u);
        EXPECT_EQ(scene.system->Counters().nonFinite, 6u);
        EXPECT_EQ(scene.world->GetBodyCount(), backend == ParticleBackend::body ? 2 : 1);
        scene.StepAll();
        EXPECT_TRUE(AllFinite(scene));
    }
}

// A restitution of 1e30 (set by the application, past any config check) throws a particle out of the world
// at its first bounce: it dies and is counted, nothing else is touched.
TEST(ParticleNumbers, ParticlesThrownOutOfTheWorldDieAndAreCounted)
{
    Pool scene({Ball(0.0f, 0.5f)}, {256, RecyclePolicy::oldest});
    b2Body* ground = scene.CreateGround();
    ground->GetFixtureList()->SetRestitution(1.0e30f);
    for (int i = 0; i < 100; ++i)
    {
        scene.Add(b2Vec2(-5.0f + 0.1f * static_cast<float>(i), 0.5f), b2Vec2(0.0f, -2.0f));
    }
    for (int step = 0; step < 60; ++step)
    {
        scene.StepAll();
        ASSERT_TRUE(AllFinite(scene)) << "step " << step;
    }
    EXPECT_EQ(scene.system->Counters().nonFinite, 100u) << "every one bounced out of the world";
    EXPECT_EQ(scene.system->Count(), 0u);
}

// A body whose velocity the application set to not-a-number, infinity or 3e38 while particles are near it:
// the step ends (it used to loop forever growing the grid), the body is skipped and counted, the particles
// stay finite.
TEST(ParticleNumbers, BodiesThatAreNotFiniteAreSkippedAndCounted)
{
    for (const float speed : {kNaN, kInf, 3.0e38f})
    {
        Pool scene({Ball(0.3f, 0.5f)}, {256, RecyclePolicy::oldest});
        scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 1.0f), 0.5f, 0.5f, 0.5f);
        for (int i = 0; i < 50; ++i)
        {
            scene.Add(b2Vec2(-2.5f + 0.1f * static_cast<float>(i), 2.0f), b2Vec2(0.0f, -1.0f));
        }
        scene.StepAll();
        box->SetLinearVelocity(b2Vec2(speed, 0.0f));
        for (int step = 0; step < 10; ++step)
        {
            scene.system->Step(kDt, scene.world->GetGravity()); // the world is not stepped: Box2D would
                                                                // spread the velocity to the position
        }
        EXPECT_EQ(scene.system->Counters().skippedBodies, 10u) << speed;
        EXPECT_EQ(scene.system->Count(), 50u) << speed;
        EXPECT_TRUE(AllFinite(scene)) << speed;
        box->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
        scene.system->Step(kDt, scene.world->GetGravity());
        EXPECT_EQ(scene.system->Counters().skippedBodies, 10u) << "sane again: collided with again";
    }
}

// A ground fixture duplicated 1,000 times (an editor's slip) is one primitive to the particles: a sweep
// does not test it 1,000 times. A copy with another friction is another surface.
TEST(ParticleNumbers, DuplicatedFixturesAreMetOnce)
{
    TestWorld scene;
    b2BodyDef def;
    b2Body* ground = scene.world->CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(20.0f, 1.0f, b2Vec2(0.0f, -1.0f), 0.0f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.friction = 0.5f;
    for (int i = 0; i < 1000; ++i)
    {
        ground->CreateFixture(&fixture);
    }
    fixture.friction = 0.9f;
    ground->CreateFixture(&fixture);
    particles::WorldGeometry geometry;
    geometry.Scan(*scene.world, nullptr, kDt);
    EXPECT_EQ(geometry.StaticPrimitives(), 2u);

    // And particles still land on it.
    Pool pool({Ball()});
    b2Body* poolGround = pool.CreateGround();
    b2PolygonShape same = *static_cast<const b2PolygonShape*>(poolGround->GetFixtureList()->GetShape());
    for (int i = 0; i < 999; ++i)
    {
        poolGround->CreateFixture(&same, 0.0f)->SetFriction(0.8f);
    }
    pool.Add(b2Vec2(0.0f, 1.0f));
    for (int step = 0; step < 120; ++step)
    {
        pool.StepAll();
    }
    EXPECT_NEAR(pool.Position(0).y, 0.05f, 1e-3f);
}

} // namespace cfx::test
