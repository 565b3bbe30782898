// Steady state is allocation-free: this binary replaces the global operator new with one that counts,
// warms a particle system up (static cache built, helper thread started, vectors grown), then steps it
// with spawning, dying, recycling, moving bodies, particle hits and both threads, and asks for zero
// allocations.
// Body-backed particles are Box2D's to allocate (its block allocator), so they are not part of this.
#include "allocation_counter.h"
#include "test_world.h"

#include <box2d/box2d.h>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace cfx::test
{

namespace
{

void RunSteadyState(RecyclePolicy policy)
{
    TestWorld scene;
    scene.CreateGround();
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 2.0f), 1.0f, 0.5f, 0.5f);
    b2Body* spinner = scene.CreateBox(b2Vec2(4.0f, 1.0f), 1.0f, 0.1f, 0.5f, b2_kinematicBody);
    spinner->SetAngularVelocity(3.0f);
    std::vector<ParticleTypeDef> types(2);
    types[0].name = "short";
    types[0].lifetime = 0.5f;
    types[1].name = "long";
    types[1].lifetime = 3.0f;
    types[1].restitution = 0.6f;
    ParticleSystemOptions options;
    options.threads = 2;
    options.minParticlesPerThread = 64;
    ParticleSystem particles(*scene.world, types, ParticleBudget{2000, policy}, options);
    std::uint32_t seed = 11;
    auto next = [&]()
    {
        seed = seed * 1664525u + 1013904223u;
        return static_cast<float>(seed >> 8) / 16777216.0f;
    };
    auto step = [&]()
    {
        for (int k = 0; k < 60; ++k) // more than the pool holds over time: recycling
        {
            particles.Spawn(ParticleSpawn{b2Vec2(-6.0f + 12.0f * next(), 0.1f + 4.0f * next()),
                                          b2Vec2(-4.0f + 8.0f * next(), -4.0f + 8.0f * next()),
                                          0.3f + 0.7f * next(),
                                          ParticleTypeId{static_cast<std::uint16_t>(k % 2)}});
        }
        scene.world->Step(1.0f / 60.0f, 8, 3);
        particles.Step(1.0f / 60.0f, scene.world->GetGravity());
    };
    for (int i = 0; i < 120; ++i)
    {
        step();
    }
    ASSERT_EQ(particles.ThreadsUsed(), 2u);
    ASSERT_GT(particles.Recycled(), 0u);
    const long before = Allocations();
    int stepsWithHits = 0;
    for (int i = 0; i < 120; ++i)
    {
        step();
        stepsWithHits += particles.Hits().empty() ? 0 : 1;
    }
    EXPECT_EQ(Allocations() - before, 0) << "allocations in 120 warmed-up steps";
    EXPECT_GT(stepsWithHits, 60) << "particle hits were recorded and grouped";
    EXPECT_GT(box->GetPosition().y, -1.0f);
}

// A particle type that lives through any test.
ParticleTypeDef LongLivedDust()
{
    ParticleTypeDef type;
    type.name = "dust";
    type.lifetime = 100.0f;
    return type;
}

} // namespace

TEST(ParticleAllocation, NoneOnceWarmedUpOldestFirst)
{
    RunSteadyState(RecyclePolicy::oldest);
}

TEST(ParticleAllocation, NoneOnceWarmedUpLowestLife)
{
    RunSteadyState(RecyclePolicy::lowestLife);
}

// Moving bodies that spread far apart and fall out of the world change the moving grid's bounds every
// step; with as many bodies as before, the grid allocates nothing, however far they are spread.
TEST(ParticleAllocation, NoneWhileBodiesSpreadApartAndFallOutOfTheWorld)
{
    TestWorld scene;
    scene.CreateGround(0.5f, 5.0f);
    std::vector<b2Body*> bodies;
    for (int i = 0; i < 40; ++i)
    {
        b2Body* body = scene.CreateBox(
            b2Vec2(-4.0f + 0.2f * static_cast<float>(i), 1.0f + 0.1f * static_cast<float>(i % 7)),
            0.1f + 0.02f * static_cast<float>(i % 5), 0.1f, 0.5f);
        bodies.push_back(body);
    }
    const ParticleTypeDef type = LongLivedDust();
    ParticleSystem particles(*scene.world, std::span<const ParticleTypeDef>(&type, 1),
                             ParticleBudget{500, RecyclePolicy::oldest});
    for (int i = 0; i < 500; ++i)
    {
        particles.Spawn(ParticleSpawn{b2Vec2(-4.5f + 0.018f * static_cast<float>(i), 0.2f),
                                      b2Vec2(0.0f, 0.0f), 1.0f, ParticleTypeId{0}});
    }
    auto step = [&]()
    {
        scene.world->Step(1.0f / 60.0f, 8, 3);
        particles.Step(1.0f / 60.0f, scene.world->GetGravity());
    };
    for (int i = 0; i < 30; ++i)
    {
        step();
    }
    // Thrown apart at up to 50 m/s: they leave the 10 m ground and fall for ever.
    for (std::size_t i = 0; i < bodies.size(); ++i)
    {
        const float f = static_cast<float>(i) / static_cast<float>(bodies.size() - 1);
        bodies[i]->SetLinearVelocity(b2Vec2(-50.0f + 100.0f * f, 20.0f * f));
    }
    const long before = Allocations();
    for (int i = 0; i < 600; ++i)
    {
        step();
    }
    EXPECT_EQ(Allocations() - before, 0) << "allocations in 600 steps of bodies spreading apart";
    EXPECT_LT(bodies.front()->GetPosition().y, -100.0f); // they did fall out of the world
    EXPECT_GT(particles.Count(), 0u);
}

// Shifting the origin rebuilds the static cache with the same primitives, lined up with the grid's cells
// differently each time: a trial's finely split ground far from the origin grew the grid's lists (32 KB) at
// the shift. The grid keeps room for any alignment.
TEST(ParticleAllocation, NoneWhenTheOriginShiftsUnderAFinelySplitGround)
{
    // Also with a static box far away, which makes the static grid hashed.
    for (const bool farBox : {false, true})
    {
        SCOPED_TRACE(farBox ? "with a box far away" : "alone");
        TestWorld scene;
        const b2Vec2 far(1000.0f, 1000.0f);
        b2BodyDef def;
        def.position = far;
        b2Body* ground = scene.world->CreateBody(&def);
        std::vector<b2Vec2> vertices;
        for (int i = 800; i >= 0; --i) // 0.05 m segments over 40 m, right to left: solid below
        {
            vertices.emplace_back(-20.0f + 0.05f * static_cast<float>(i), 0.0f);
        }
        b2ChainShape chain;
        chain.CreateChain(vertices.data(), static_cast<int>(vertices.size()),
                          vertices.front() + b2Vec2(1.0f, 0.0f), vertices.back() - b2Vec2(1.0f, 0.0f));
        ground->CreateFixture(&chain, 0.0f);
        for (const float x : {-20.5f, 20.5f}) // a wall at each end, 10 m tall
        {
            b2PolygonShape wall;
            wall.SetAsBox(0.5f, 5.0f, b2Vec2(x, 4.0f), 0.0f);
            ground->CreateFixture(&wall, 0.0f);
        }
        if (farBox)
        {
            // A box 5 km off: the static grid keeps only its cells that list something (hashed).
            b2PolygonShape box;
            box.SetAsBox(1.0f, 1.0f, b2Vec2(5000.0f, 5000.0f), 0.0f);
            ground->CreateFixture(&box, 0.0f);
        }
        const ParticleTypeDef type = LongLivedDust();
        ParticleSystem particles(*scene.world, std::span<const ParticleTypeDef>(&type, 1),
                                 ParticleBudget{300, RecyclePolicy::oldest});
        for (int i = 0; i < 300; ++i)
        {
            particles.Spawn(ParticleSpawn{far + b2Vec2(-9.0f + 0.06f * static_cast<float>(i), 1.0f),
                                          b2Vec2(0.0f, 0.0f), 1.0f, ParticleTypeId{0}});
        }
        b2Vec2 origin(0.0f, 0.0f);
        auto step = [&](int i)
        {
            if (i >= 30 && i % 10 == 5) // none while warming up: one alignment only
            {
                // To the ground and back, a little off each time: a different alignment every time.
                const float k = static_cast<float>(i / 10 + 1);
                const b2Vec2 shift =
                    ((i / 10) % 2 == 1 ? 1.0f : -1.0f) * far + b2Vec2(0.0137f * k, -0.0291f * k);
                scene.world->ShiftOrigin(shift);
                particles.ShiftOrigin(shift);
                origin += shift;
            }
            scene.world->Step(1.0f / 60.0f, 8, 3);
            particles.Step(1.0f / 60.0f, scene.world->GetGravity());
        };
        for (int i = 0; i < 30; ++i)
        {
            step(i);
        }
        const long before = Allocations();
        for (int i = 30; i < 630; ++i)
        {
            step(i);
        }
        EXPECT_EQ(Allocations() - before, 0) << "allocations in 600 steps shifting the origin 60 times";
        EXPECT_EQ(particles.Count(), 300u);
        EXPECT_GT(std::abs(origin.x), 0.2f);
    }
}

// A game that first has enough particles to split a step long after its warm-up: the helper thread was
// started with the system, not in that step (a user's trial counted 2 allocations there).
TEST(ParticleAllocation, NoneInTheFirstStepSplitAcrossThreads)
{
    TestWorld scene;
    scene.CreateGround();
    std::vector<ParticleTypeDef> types(1);
    types[0].lifetime = 10.0f;
    ParticleSystemOptions options;
    options.threads = 2;
    options.minParticlesPerThread = 500;
    ParticleSystem particles(*scene.world, types, ParticleBudget{4000, RecyclePolicy::oldest}, options);
    auto spawn = [&](int count)
    {
        for (int k = 0; k < count; ++k)
        {
            particles.Spawn(ParticleSpawn{b2Vec2(-5.0f + 0.01f * static_cast<float>(k % 1000), 1.0f),
                                          b2Vec2(0.0f, 0.0f), 1.0f, ParticleTypeId{0}});
        }
    };
    spawn(100);
    for (int i = 0; i < 60; ++i)
    {
        particles.Step(1.0f / 60.0f, scene.world->GetGravity());
    }
    ASSERT_EQ(particles.ThreadsUsed(), 1u);
    spawn(2000);
    const long before = Allocations();
    particles.Step(1.0f / 60.0f, scene.world->GetGravity());
    EXPECT_EQ(Allocations() - before, 0);
    EXPECT_EQ(particles.ThreadsUsed(), 2u);
}

TEST(ParticleAllocation, TheCounterCounts)
{
    const long before = Allocations();
    auto* probe = new std::vector<int>(10);
    delete probe;
    EXPECT_EQ(Allocations() - before, 2);
}

} // namespace cfx::test
