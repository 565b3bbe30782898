#include "particles/particle_pool_fixture.h"
#include "test_world.h"

#include <algorithm>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

// The common case of these tests: one type and a ground whose top is y = 0.
struct ParticleWorld : Pool
{
    explicit ParticleWorld(const ParticleTypeDef& type, std::uint32_t capacity = 64)
        : Pool({type}, ParticleBudget{capacity, RecyclePolicy::oldest})
    {
        ground = CreateGround();
    }

    b2Body* ground = nullptr;
};

} // namespace

TEST(Particles, HardCapRecyclesTheOldestAndKeepsOrder)
{
    ParticleTypeDef type = Ball(0.0f);
    type.gravityScale = 0.0f;
    ParticleWorld scene(type, 4);
    for (int i = 0; i < 6; ++i)
    {
        scene.Add(b2Vec2(static_cast<float>(i), 5.0f));
    }
    ASSERT_EQ(scene.system->Count(), 4u);
    EXPECT_EQ(scene.system->Recycled(), 2u);
    for (std::uint32_t i = 0; i < 4; ++i)
    {
        EXPECT_EQ(scene.Position(i).x, static_cast<float>(i + 2)) << "oldest first";
    }
    scene.StepAll();
    scene.Add(b2Vec2(9.0f, 5.0f));
    EXPECT_EQ(scene.Position(0).x, 3.0f);
    EXPECT_EQ(scene.Position(3).x, 9.0f);
}

TEST(Particles, DeadParticlesLeaveAndOrderStays)
{
    ParticleTypeDef type = Ball(0.0f);
    type.gravityScale = 0.0f;
    type.lifetime = 1.0f;
    ParticleWorld scene(type, 8);
    scene.Add(b2Vec2(0.0f, 5.0f), b2Vec2(0.0f, 0.0f), 1.0f);
    scene.Add(b2Vec2(1.0f, 5.0f), b2Vec2(0.0f, 0.0f), 0.1f); // dies after 0.1 s
    scene.Add(b2Vec2(2.0f, 5.0f), b2Vec2(0.0f, 0.0f), 1.0f);
    scene.Add(b2Vec2(3.0f, 5.0f), b2Vec2(0.0f, 0.0f), 0.0f); // never added
    EXPECT_EQ(scene.system->Count(), 3u);
    for (int i = 0; i < 7; ++i)
    {
        scene.StepAll();
    }
    ASSERT_EQ(scene.system->Count(), 2u);
    EXPECT_EQ(scene.Position(0).x, 0.0f);
    EXPECT_EQ(scene.Position(1).x, 2.0f);
    EXPECT_NEAR(scene.system->View().life[scene.system->View().Slot(0)], 1.0f - 7.0f / 60.0f, 1e-5f);
}

TEST(Particles, SparksBounceOnTheGround)
{
    ParticleWorld scene(Ball(0.8f));
    scene.Add(b2Vec2(0.0f, 2.0f));
    float lowest = 10.0f;
    bool bounced = false;
    for (int i = 0; i < 120; ++i)
    {
        float before = scene.Velocity(0).y;
        scene.StepAll();
        lowest = std::min(lowest, scene.Position(0).y);
        bounced = bounced || (before < -3.0f && scene.Velocity(0).y > 3.0f);
    }
    EXPECT_TRUE(bounced);
    EXPECT_GE(lowest, 0.05f - 1e-4f);
}

TEST(Particles, DirtLandsAndRests)
{
    ParticleWorld scene(Ball(0.2f, 0.9f));
    scene.Add(b2Vec2(0.0f, 3.0f), b2Vec2(4.0f, 2.0f));
    for (int i = 0; i < 240; ++i)
    {
        scene.StepAll();
    }
    EXPECT_NEAR(scene.Position(0).y, 0.05f, 1e-3f);
    EXPECT_LT(scene.Velocity(0).Length(), 0.05f);
}

TEST(Particles, NoTunnellingAt50MetresPerSecond)
{
    ParticleWorld scene(Ball(0.0f));
    for (int i = 0; i < 10; ++i)
    {
        scene.Add(b2Vec2(0.1f * static_cast<float>(i), 5.0f + 0.37f * static_cast<float>(i)),
                  b2Vec2(3.0f, -50.0f));
    }
    for (int step = 0; step < 60; ++step)
    {
        scene.StepAll();
        for (std::uint32_t i = 0; i < 10; ++i)
        {
            ASSERT_GE(scene.Position(i).y, 0.0f) << "particle " << i << " step " << step;
        }
    }
}

TEST(Particles, NeverCollideWithEachOther)
{
    ParticleTypeDef type = Ball(1.0f);
    type.gravityScale = 0.0f;
    ParticleWorld scene(type);
    scene.Add(b2Vec2(-1.0f, 5.0f), b2Vec2(2.0f, 0.0f));
    scene.Add(b2Vec2(1.0f, 5.0f), b2Vec2(-2.0f, 0.0f));
    for (int i = 0; i < 60; ++i)
    {
        scene.StepAll();
    }
    EXPECT_NEAR(scene.Position(0).x, 1.0f, 1e-4f);
    EXPECT_NEAR(scene.Position(1).x, -1.0f, 1e-4f);
}

TEST(Particles, OneSidedEdgeIsSolidOnlyFromItsFront)
{
    ParticleTypeDef type = Ball(0.0f);
    ParticleWorld scene(type);
    b2EdgeShape edge;
    edge.SetOneSided(b2Vec2(20.0f, 3.0f), b2Vec2(10.0f, 3.0f), b2Vec2(-10.0f, 3.0f), b2Vec2(-20.0f, 3.0f));
    b2BodyDef def;
    scene.world->CreateBody(&def)->CreateFixture(&edge, 0.0f);
    scene.Add(b2Vec2(0.0f, 1.0f), b2Vec2(0.0f, 10.0f)); // from below: passes up through the edge
    for (int i = 0; i < 180; ++i)
    {
        scene.StepAll();
    }
    EXPECT_NEAR(scene.Position(0).y, 3.05f, 1e-3f) << "came up through the back, then landed on the front";
}

TEST(Particles, FilterDecidesWhatIsHit)
{
    ParticleTypeDef type = Ball(0.0f);
    type.maskBits = 0x0004; // the ground is category 1: not hit
    ParticleWorld scene(type);
    scene.Add(b2Vec2(0.0f, 1.0f));
    for (int i = 0; i < 60; ++i)
    {
        scene.StepAll();
    }
    EXPECT_LT(scene.Position(0).y, -1.0f);
}

TEST(Particles, BodyBackedParticlesLandToo)
{
    ParticleTypeDef type = Ball(0.2f, 0.9f);
    type.backend = ParticleBackend::body;
    ParticleWorld scene(type, 2);
    scene.Add(b2Vec2(0.0f, 3.0f), b2Vec2(1.0f, 0.0f));
    EXPECT_EQ(scene.world->GetBodyCount(), 2);
    for (int i = 0; i < 240; ++i)
    {
        scene.StepAll();
    }
    EXPECT_NEAR(scene.Position(0).y, 0.05f, 0.01f);
    // Recycling destroys the old body; destruction of the system destroys the rest.
    scene.Add(b2Vec2(1.0f, 3.0f));
    scene.Add(b2Vec2(2.0f, 3.0f));
    EXPECT_EQ(scene.world->GetBodyCount(), 3);
    scene.system.reset();
    EXPECT_EQ(scene.world->GetBodyCount(), 1);
}

TEST(Particles, ColourAndSizeOverLife)
{
    ParticleTypeDef type;
    type.colorStart = Color{1.0f, 0.0f, 0.0f, 1.0f};
    type.colorEnd = Color{0.0f, 0.0f, 1.0f, 1.0f};
    type.sizeStart = 0.1f;
    type.sizeEnd = 0.5f;
    ParticleLook birth = LookAt(type, 1.0f);
    ParticleLook middle = LookAt(type, 0.5f);
    EXPECT_FLOAT_EQ(birth.color.r, 1.0f);
    EXPECT_FLOAT_EQ(birth.size, 0.1f);
    EXPECT_FLOAT_EQ(middle.color.r, 0.5f);
    EXPECT_FLOAT_EQ(middle.color.b, 0.5f);
    EXPECT_FLOAT_EQ(middle.color.a, 0.5f);
    EXPECT_FLOAT_EQ(middle.size, 0.3f);
}

// Effects passes the static cache's controls through: built at load, counted in the stats, and (not watched)
// rebuilt when the application says the static geometry changed.
TEST(Particles, EffectsBuildsTheStaticCacheAtLoadAndRebuildsItWhenTold)
{
    TestWorld scene;
    scene.particles.watchStaticGeometry = false;
    b2Body* ground = scene.CreateGround();
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    Effects& fx = scene.Attach();
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(box, fx.FindMaterial("steel"));
    EXPECT_TRUE(fx.BuildStaticGeometry());
    EXPECT_EQ(fx.Stats().staticGeometryBuilds, 1u);
    EXPECT_FALSE(fx.BuildStaticGeometry());
    auto slide = [&](int steps)
    {
        for (int i = 0; i < steps; ++i)
        {
            box->SetLinearVelocity(b2Vec2(8.0f, box->GetLinearVelocity().y));
            scene.Step();
        }
    };
    slide(60);
    EXPECT_GT(fx.Stats().live, 0u) << "sparks";
    EXPECT_EQ(fx.Stats().staticGeometryBuilds, 1u) << "the steps used the cache built at load";
    b2BodyDef wallDef;
    wallDef.position.Set(20.0f, 1.0f);
    b2PolygonShape wall;
    wall.SetAsBox(0.1f, 1.0f);
    b2Body* wallBody = scene.world->CreateBody(&wallDef);
    wallBody->CreateFixture(&wall, 0.0f);
    slide(10);
    EXPECT_EQ(fx.Stats().staticGeometryBuilds, 1u) << "not watched: the new wall is not seen";
    fx.InvalidateStaticGeometry();
    slide(1);
    EXPECT_EQ(fx.Stats().staticGeometryBuilds, 2u);
    // What goes is said to the cache by the destruction listener, or by ForgetFixture before
    // DestroyFixture: no particle meets a destroyed static fixture, or names its body in a hit (a re-check
    // found hits naming a destroyed body, then a new body Box2D put at its address).
    scene.world->DestroyBody(wallBody);
    slide(1);
    EXPECT_EQ(fx.Stats().staticGeometryBuilds, 3u) << "a static body destroyed";
    b2PolygonShape kerb;
    kerb.SetAsBox(0.5f, 0.1f, b2Vec2(-20.0f, 0.1f), 0.0f);
    b2Fixture* kerbFixture = ground->CreateFixture(&kerb, 0.0f);
    fx.InvalidateStaticGeometry(); // created: the application says so
    slide(1);
    EXPECT_EQ(fx.Stats().staticGeometryBuilds, 4u);
    fx.ForgetFixture(kerbFixture);
    ground->DestroyFixture(kerbFixture);
    slide(1);
    EXPECT_EQ(fx.Stats().staticGeometryBuilds, 5u) << "a static fixture destroyed after ForgetFixture";
}

// A level restarted in place (a trial: about 700 particles of the last attempt stayed, falling where the
// level had been): ClearParticles removes them all, the bodies of body-backed ones too, and emission goes on.
TEST(Particles, ClearParticlesRemovesEveryParticleAndItsBody)
{
    for (const bool bodies : {false, true})
    {
        SCOPED_TRACE(bodies ? "tutorial preset: a body per particle" : "default preset: pool");
        TestWorld scene;
        b2Body* ground = scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        Effects& fx = scene.Attach(bodies ? TutorialPreset() : DefaultPreset());
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(box, fx.FindMaterial("steel"));
        const int worldBodies = scene.world->GetBodyCount();
        auto slide = [&](int steps)
        {
            for (int i = 0; i < steps; ++i)
            {
                box->SetLinearVelocity(b2Vec2(8.0f, box->GetLinearVelocity().y));
                scene.Step();
            }
        };
        slide(30);
        ASSERT_GT(fx.Particles().count, 0u);
        EXPECT_EQ(scene.world->GetBodyCount() > worldBodies, bodies);
        fx.ClearParticles();
        EXPECT_EQ(fx.Particles().count, 0u);
        EXPECT_EQ(fx.Stats().live, 0u);
        EXPECT_EQ(scene.world->GetBodyCount(), worldBodies) << "the particles' bodies are gone";
        slide(5);
        EXPECT_GT(fx.Particles().count, 0u) << "emission goes on";
        EXPECT_LE(fx.Particles().count,
                  fx.Stats().spawnedByType[fx.Config().FindParticleType("sparks").index]);
    }
}

// ClearParticles where it cannot run refuses, changing nothing (a re-check: from the application's
// destruction listener while a clear destroyed particle bodies it destroyed one twice; from a contact
// listener Box2D's locked world aborted).
TEST(Particles, ClearParticlesRefusesInsideTheWorldStepAndInsideABodysDestruction)
{
    struct Listeners final : b2ContactListener, b2DestructionListener
    {
        void BeginContact(b2Contact*) override { results.push_back(fx->ClearParticles()); }
        void SayGoodbye(b2Joint*) override {}
        void SayGoodbye(b2Fixture*) override { results.push_back(fx->ClearParticles()); }
        Effects* fx = nullptr;
        std::vector<bool> results;
    };
    TestWorld scene;
    Listeners listeners;
    b2Body* ground = scene.CreateGround();
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    Effects& fx = scene.Attach(TutorialPreset(), 1, &listeners); // a body per particle
    listeners.fx = &fx;
    fx.SetDestructionListener(&listeners);
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(box, fx.FindMaterial("steel"));
    for (int i = 0; i < 30; ++i)
    {
        box->SetLinearVelocity(b2Vec2(8.0f, box->GetLinearVelocity().y));
        scene.Step();
    }
    ASSERT_FALSE(listeners.results.empty()) << "particle bodies touched the ground inside the world steps";
    EXPECT_EQ(std::count(listeners.results.begin(), listeners.results.end(), true), 0);
    const std::uint32_t live = fx.Particles().count;
    ASSERT_GT(live, 0u);
    listeners.results.clear();
    EXPECT_TRUE(fx.ClearParticles());
    ASSERT_FALSE(listeners.results.empty()) << "the particles' fixtures said goodbye";
    EXPECT_EQ(std::count(listeners.results.begin(), listeners.results.end(), true), 0);
    EXPECT_EQ(fx.Particles().count, 0u);
    EXPECT_EQ(scene.world->GetBodyCount(), 2) << "only the ground and the box are left";
}

} // namespace cfx::test
