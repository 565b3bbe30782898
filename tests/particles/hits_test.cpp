// Particle hits (ParticleSystem::Hits): a pool particle's hardest touch of a step, grouped per particle type
// and body in order of first appearance, capped to the largest groups, the same with any number of threads.
#include "contactfx/config.h"
#include "particles/motion.h"
#include "particles/particle_pool_fixture.h"

#include <algorithm>
#include <bit>
#include <gtest/gtest.h>
#include <tuple>

namespace cfx::test
{

namespace
{

constexpr float kDropSpeed = 3.0f; // m/s, downwards

// A static box with its top at y = top, centred at x.
b2Body* StaticBlock(Pool& scene, float x, float top)
{
    return scene.CreateBox(b2Vec2(x, top - 0.5f), 0.5f, 0.5f, 0.5f, b2_staticBody);
}

// Drops a particle of `type` onto the surface at height `top` under x: it touches it within the next step.
void DropOnto(Pool& scene, float x, float top, std::uint16_t type = 0)
{
    scene.Add(b2Vec2(x, top + 0.06f), b2Vec2(0.0f, -kDropSpeed), 1.0f, type);
}

// A ground with 20 particles resting on it, 0.2 m apart.
void LayOnGround(Pool& scene)
{
    scene.CreateGround();
    for (int i = 0; i < 20; ++i)
    {
        scene.Add(b2Vec2(-2.0f + 0.2f * static_cast<float>(i), scene.types[0].radius));
    }
}

// Where a hit's body is in `bodies` (bodies of two worlds compared by their place, never by address).
std::size_t IndexOf(const std::vector<const b2Body*>& bodies, const b2Body* body)
{
    return static_cast<std::size_t>(std::find(bodies.begin(), bodies.end(), body) - bodies.begin());
}

} // namespace

TEST(ParticleHits, ADropOntoAStaticBoxIsOneGroupWithItsApproachSpeedAndTouchPoint)
{
    Pool scene({Ball()});
    b2Body* ground = scene.CreateGround();
    DropOnto(scene, 0.3f, 0.0f);
    scene.StepAll();
    const auto hits = scene.system->Hits();
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].type, ParticleTypeId{0});
    EXPECT_EQ(hits[0].body, ground);
    EXPECT_EQ(hits[0].count, 1u);
    // The step's velocity as the system computes it: gravity first, no drag; the ground's normal is +y. The
    // approach is the velocity at the touch: the gravity of the part of the step before it.
    const float gravityDelta = (kDt * scene.types[0].gravityScale) * scene.world->GetGravity().y;
    const float stepSpeed = kDropSpeed - gravityDelta;
    const float touchedAt = (0.06f - scene.types[0].radius) / (stepSpeed * kDt); // fraction of the step
    EXPECT_NEAR(hits[0].meanSpeed, kDropSpeed - touchedAt * gravityDelta, 1.0e-5f);
    EXPECT_LT(hits[0].meanSpeed, stepSpeed - 0.5f * -gravityDelta) << "not the step's whole gravity";
    EXPECT_NEAR(hits[0].centre.x, 0.3f, 1e-6f);
    EXPECT_NEAR(hits[0].centre.y, 0.0f, 1e-5f); // the disc touches the ground's top, not its centre
    scene.StepAll();
    EXPECT_TRUE(scene.system->Hits().empty()) << "restitution 0: it stays on the ground, approaching slowly";
}

TEST(ParticleHits, RestingParticlesAreNotHits)
{
    Pool scene({Ball()});
    LayOnGround(scene);
    for (int step = 0; step < 120; ++step)
    {
        scene.StepAll();
        ASSERT_TRUE(scene.system->Hits().empty()) << "step " << step;
    }
    EXPECT_EQ(scene.system->Count(), 20u);
}

// A trial's game hitched: one step of 0.25 s gave each resting particle 2.5 m/s of gravity, and all 172 of a
// settled pile of dirt were hits (and a patter of sound). A particle touching at the start of the step had
// none of that gravity yet: however long the step, resting particles are not hits.
TEST(ParticleHits, RestingParticlesAreNotHitsAfterALongStep)
{
    for (const float hitch : {0.1f, 0.25f, 1.0f})
    {
        SCOPED_TRACE(hitch);
        Pool scene({Ball()});
        LayOnGround(scene);
        for (int step = 0; step < 30; ++step)
        {
            scene.StepAll();
        }
        scene.world->Step(hitch, 8, 3);
        scene.system->Step(hitch, scene.world->GetGravity());
        EXPECT_TRUE(scene.system->Hits().empty()) << scene.system->Hits().size() << " groups";
        EXPECT_EQ(scene.system->Count(), 20u);
    }
}

// The same hitch on bouncy particles: before, the bounce took the step's whole velocity, so each resting
// particle was thrown up by its restitution times the hitch's gravity (dirt after 0.25 s: 12 cm) and landed
// as a hit a few steps later. The bounce takes the speed at the touch: they stay on the ground, and no later
// step hears them.
TEST(ParticleHits, RestingParticlesNeitherBounceNorLandAsHitsAfterALongStep)
{
    for (const float hitch : {0.1f, 0.25f, 1.0f})
    {
        SCOPED_TRACE(hitch);
        Pool scene({Ball(0.5f)});
        LayOnGround(scene);
        for (int step = 0; step < 30; ++step)
        {
            scene.StepAll();
        }
        scene.world->Step(hitch, 8, 3);
        scene.system->Step(hitch, scene.world->GetGravity());
        for (int step = 0; step < 60; ++step)
        {
            ASSERT_TRUE(scene.system->Hits().empty()) << "step " << step << " after the hitch";
            const ParticleView view = scene.system->View();
            for (std::uint32_t i = 0; i < view.count; ++i)
            {
                ASSERT_NEAR(view.positionY[view.Slot(i)], scene.types[0].radius, 1.0e-4f)
                    << "particle " << i << ", step " << step;
            }
            scene.StepAll();
        }
        EXPECT_EQ(scene.system->Count(), 20u);
    }
}

// A long step sweeps a particle resting on a box that stands on the ground down through the box (the static
// sweep comes first and does not see bodies) to the ground, where it hit and bounced before the box pushed
// it back on top: 5 hits, and a bounce of up to 4 cm. The body met first, the static touches behind it
// never happened.
TEST(ParticleHits, ParticlesRestingOnABoxNeitherHitNorBounceAfterALongStep)
{
    for (const float half : {0.1f, 0.2f, 0.5f})
    {
        for (const float hitch : {0.1f, 0.15f, 0.25f, 0.5f})
        {
            SCOPED_TRACE(testing::Message() << "box " << 2.0f * half << " m, step " << hitch << " s");
            Pool scene({Ball(0.5f)});
            scene.CreateGround();
            scene.CreateBox(b2Vec2(0.0f, half), half, half, 1.0f, b2_dynamicBody);
            for (int i = 0; i < 5; ++i)
            {
                scene.Add(b2Vec2(half * (-0.8f + 0.4f * static_cast<float>(i)), 2.0f * half + 0.06f));
            }
            for (int step = 0; step < 60; ++step)
            {
                scene.StepAll();
            }
            const float rest = scene.Position(0).y;
            scene.world->Step(hitch, 8, 3);
            scene.system->Step(hitch, scene.world->GetGravity());
            for (int step = 0; step < 60; ++step)
            {
                ASSERT_TRUE(scene.system->Hits().empty()) << "step " << step << " after the long one";
                for (std::uint32_t i = 0; i < scene.system->Count(); ++i)
                {
                    ASSERT_NEAR(scene.Position(i).y, rest, 1.0e-4f) << "particle " << i << ", step " << step;
                }
                scene.StepAll();
            }
            EXPECT_EQ(scene.system->Count(), 5u);
        }
    }
}

TEST(ParticleHits, AreGroupedPerTypeAndBodyInOrderOfFirstAppearance)
{
    Pool scene({Ball(), Ball()});
    b2Body* ground = scene.CreateGround();
    b2Body* block = StaticBlock(scene, 5.0f, 1.0f);
    DropOnto(scene, 5.0f, 1.0f);     // block, type 0
    DropOnto(scene, -3.0f, 0.0f);    // ground, type 0
    DropOnto(scene, 5.2f, 1.0f);     // block, type 0 again
    DropOnto(scene, -2.0f, 0.0f, 1); // ground, type 1: a group of its own
    scene.StepAll();
    const auto hits = scene.system->Hits();
    ASSERT_EQ(hits.size(), 3u);
    EXPECT_EQ(std::make_tuple(hits[0].body, hits[0].type.index, hits[0].count),
              std::make_tuple(block, 0, 2u));
    EXPECT_EQ(std::make_tuple(hits[1].body, hits[1].type.index, hits[1].count),
              std::make_tuple(ground, 0, 1u));
    EXPECT_EQ(std::make_tuple(hits[2].body, hits[2].type.index, hits[2].count),
              std::make_tuple(ground, 1, 1u));
    EXPECT_NEAR(hits[0].centre.x, 5.1f, 1e-5f); // the mean of the two touch points
    EXPECT_NEAR(hits[0].centre.y, 1.0f, 1e-5f);
}

TEST(ParticleHits, TheCapKeepsTheLargestGroupsFirstToAppearOnTies)
{
    ParticleBudget budget{64, RecyclePolicy::oldest};
    budget.particleHits = 2;
    Pool scene({Ball()}, budget);
    const std::array<b2Body*, 4> blocks{StaticBlock(scene, 0.0f, 1.0f), StaticBlock(scene, 3.0f, 1.0f),
                                        StaticBlock(scene, 6.0f, 1.0f), StaticBlock(scene, 9.0f, 1.0f)};
    // Hits per block, in order of first appearance: 1, 3, 2, 2.
    for (const int block : {0, 1, 1, 2, 1, 3, 2, 3})
    {
        DropOnto(scene, 3.0f * static_cast<float>(block), 1.0f);
    }
    scene.StepAll();
    const auto hits = scene.system->Hits();
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits[0].body, blocks[1]);
    EXPECT_EQ(hits[0].count, 3u);
    EXPECT_EQ(hits[1].body, blocks[2]); // ties with blocks[3], and appeared first
    EXPECT_EQ(hits[1].count, 2u);
    EXPECT_EQ(scene.system->Counters().droppedHitGroups, 2u);
}

TEST(ParticleHits, NoneAreRecordedWhenTheBudgetIsZero)
{
    ParticleBudget budget{64, RecyclePolicy::oldest};
    budget.particleHits = 0;
    Pool scene({Ball()}, budget);
    scene.CreateGround();
    DropOnto(scene, 0.0f, 0.0f);
    const std::size_t withoutHits = scene.system->BytesPerSlot();
    scene.StepAll();
    EXPECT_TRUE(scene.system->Hits().empty());
    EXPECT_EQ(scene.system->Counters().droppedHitGroups, 0u);
    Pool recording({Ball()});
    EXPECT_EQ(recording.system->BytesPerSlot(),
              withoutHits + sizeof(particles::ParticleHit)); // the hit buffer
}

TEST(ParticleHits, AMovingBodyIsHitAtTheSpeedRelativeToIt)
{
    // Resting in the air (no gravity on it) just above the rising lift: only the lift moves.
    ParticleTypeDef floating = Ball();
    floating.gravityScale = 0.0f;
    Pool still({floating});
    b2Body* rising = still.CreateBox(b2Vec2(0.0f, 1.0f), 1.0f, 0.1f, 0.5f, b2_kinematicBody);
    rising->SetLinearVelocity(b2Vec2(0.0f, 2.0f));
    still.Add(b2Vec2(0.0f, 1.1f + floating.radius + 0.01f));
    for (int step = 0; step < 3 && still.system->Hits().empty(); ++step)
    {
        still.StepAll();
    }
    const auto hits = still.system->Hits();
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].body, rising);
    EXPECT_NEAR(hits[0].meanSpeed, 2.0f, 1e-4f); // the particle is still, the surface comes at 2 m/s
}

TEST(ParticleHits, AreTheSameBitsWithOneOrTwoThreads)
{
    using Groups = std::vector<
        std::tuple<std::uint16_t, std::size_t, std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>>;
    auto run = [](unsigned threads)
    {
        ParticleSystemOptions options;
        options.threads = threads;
        options.minParticlesPerThread = 1;
        ParticleTypeDef bouncy = Ball(0.5f);
        bouncy.hitSpeed = 0.5f;
        Pool scene({bouncy, Ball(0.1f, 0.9f)}, ParticleBudget{800, RecyclePolicy::oldest}, options);
        std::vector<const b2Body*> bodies{scene.CreateGround(), StaticBlock(scene, -2.0f, 1.0f),
                                          StaticBlock(scene, 2.0f, 0.5f)};
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 3.0f), 0.8f, 0.3f, 0.5f);
        box->SetAngularVelocity(2.0f);
        bodies.push_back(box);
        std::uint32_t seed = 5;
        auto next = [&]()
        {
            seed = seed * 1664525u + 1013904223u;
            return static_cast<float>(seed >> 8) / 16777216.0f;
        };
        std::vector<Groups> steps;
        std::uint32_t used = 1;
        for (int step = 0; step < 300; ++step)
        {
            for (int k = 0; k < 6; ++k)
            {
                scene.Add(b2Vec2(-4.0f + 8.0f * next(), 1.0f + 4.0f * next()),
                          b2Vec2(-4.0f + 8.0f * next(), -6.0f + 8.0f * next()), 0.3f + 0.7f * next(),
                          static_cast<std::uint16_t>(k % 2));
            }
            scene.StepAll();
            used = std::max(used, scene.system->ThreadsUsed());
            Groups groups;
            for (const ParticleHitGroup& group : scene.system->Hits())
            {
                groups.emplace_back(group.type.index, IndexOf(bodies, group.body), group.count,
                                    std::bit_cast<std::uint32_t>(group.meanSpeed),
                                    std::bit_cast<std::uint32_t>(group.centre.x),
                                    std::bit_cast<std::uint32_t>(group.centre.y));
            }
            steps.push_back(std::move(groups));
        }
        return std::make_pair(used, steps);
    };
    const auto [usedOne, one] = run(1);
    const auto [usedTwo, two] = run(2);
    EXPECT_EQ(usedOne, 1u);
    EXPECT_EQ(usedTwo, 2u);
    std::size_t groups = 0;
    std::uint32_t multiBody = 0;
    for (const Groups& step : one)
    {
        groups += step.size();
        multiBody += step.size() > 1 ? 1u : 0u;
    }
    ASSERT_GT(groups, 100u) << "a busy scene";
    ASSERT_GT(multiBody, 10u) << "steps with several groups";
    ASSERT_EQ(one.size(), two.size());
    for (std::size_t step = 0; step < one.size(); ++step)
    {
        ASSERT_EQ(one[step], two[step]) << "step " << step;
    }
}

TEST(ParticleHits, ConfigErrorsNameTheField)
{
    EffectsConfig config;
    config.particleTypes = {Ball(), Ball()};
    config.particleTypes[1].name = "second";
    config.particleTypes[1].hitSpeed = -1.0f;
    config.budget.particleHits = 5000;
    std::vector<std::string> paths;
    for (const Diagnostic& problem : Validate(config))
    {
        paths.push_back(problem.path);
    }
    EXPECT_NE(std::find(paths.begin(), paths.end(), "particleTypes[1].hitSpeed"), paths.end());
    EXPECT_NE(std::find(paths.begin(), paths.end(), "budget.particleHits"), paths.end());
}

} // namespace cfx::test
