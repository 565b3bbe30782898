// Far from the origin a float's spacing grows (3.9 mm at 40 km, 7.8 mm at 100 km): rounding must never let a
// particle creep through the ground on its clearance.
#include "particles/particle_pool_fixture.h"
#include "particles/test_grounds.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <random>

namespace cfx::test
{

// A trial rained 1 cm particles onto a ground 40 km from the origin at 240 Hz: 53 of 2,000 at once ended
// below a two-sided edge (466 at 100 km), and the check counted no crossing. A particle sitting a few
// spacings above the ground had its position frozen (each step's move under half a spacing) while gravity
// built up its velocity, then moved a whole spacing a step, more than the clearance it was charged. The
// clearance now pays the move the floats made. Guaranteed while the radius is at least one float spacing of
// the coordinates (docs/particles.md): 1 cm holds to 131 km.
TEST(FarFromTheOrigin, ParticlesRainingOnTheGroundStayAboveIt)
{
    for (const float origin : {4.0e4f, 1.0e5f})
    {
        for (const Ground ground :
             {Ground::thickBox, Ground::splitBoxes, Ground::twoSidedEdge, Ground::chain})
        {
            SCOPED_TRACE(testing::Message() << "origin " << origin << ", ground " << GroundName(ground));
            ParticleTypeDef type = Ball(0.3f);
            type.radius = 0.01f;
            ParticleSystemOptions options;
            options.checkParticles = true;
            Pool scene({type}, {500, RecyclePolicy::oldest}, options);
            CreateGround(*scene.world, ground, 0.5f, b2Vec2(origin, origin));
            std::mt19937 random(7);
            std::uniform_real_distribution<float> unit(0.0f, 1.0f);
            constexpr float kHz = 240.0f;
            std::uint64_t below = 0;
            for (int step = 0; step < 720; ++step)
            {
                for (int k = 0; k < 10 && scene.system->Count() < 500; ++k)
                {
                    scene.Add(
                        b2Vec2(origin - 8.0f + 16.0f * unit(random), origin + 0.13f + 2.0f * unit(random)),
                        b2Vec2(2.0f * unit(random) - 1.0f, -5.0f * unit(random)), 100.0f);
                }
                scene.world->Step(1.0f / kHz, 8, 3);
                scene.system->Step(1.0f / kHz, scene.world->GetGravity());
                for (std::uint32_t i = 0; i < scene.system->Count(); ++i)
                {
                    const b2Vec2 p = scene.Position(i);
                    below += std::abs(p.x - origin) < 9.9f && p.y < origin ? 1u : 0u;
                }
            }
            EXPECT_EQ(scene.system->Count(), 500u);
            EXPECT_EQ(below, 0u);
            EXPECT_EQ(scene.system->Counters().crossings, 0u);
            EXPECT_EQ(scene.system->Counters().stepsInside, 0u);
            EXPECT_EQ(scene.system->Counters().crushed, 0u);
        }
    }
}

} // namespace cfx::test

namespace cfx::test
{

// Near the origin, but on a static edge whose ends are far: a trial rained 1 mm particles near the middle of
// one two-sided edge at 240 Hz and 676 of 12,000 fell through it at 50 km long, 5,443 at 200 km (5 mm: 1,941
// at 200 km), because a sweep measured them from the edge's first end, where a float's spacing is
// millimetres. Long static segments are swept as pieces of 256 m (at most 64 of them), and the particle check
// reads a side in doubles. Edges and chains of 50 and 200 km with 1 mm particles, and of 2,000 km (pieces of
// 31 km) with 1 cm ones, level and tilted, the rain 95 % along a piece (a re-check found a centred rain
// falling on a piece's first end, where the sweep is most precise).
TEST(FarFromTheOrigin, ParticlesStayAboveTheMiddleOfAVeryLongEdgeOrChain)
{
    for (const float length : {5.0e4f, 2.0e5f, 2.0e6f})
    {
        for (const float slope : {0.0f, 0.3f})
        {
            for (const bool chain : {false, true})
            {
                SCOPED_TRACE(testing::Message()
                             << length << " m, slope " << slope << (chain ? ", chain" : ", edge"));
                ParticleTypeDef type = Ball(0.3f);
                type.radius = length > 1.0e6f ? 0.01f : 0.001f;
                type.maskBits = 0xFFFF;
                ParticleSystemOptions options;
                options.checkParticles = true;
                Pool scene({type}, {2000, RecyclePolicy::oldest}, options);
                const b2Vec2 half(0.5f * length, 0.5f * length * slope);
                // The origin 95 % along the middle piece (the segment's middle is a piece's end).
                const float piece = length / std::min(64.0f, std::ceil(length / 256.0f));
                const b2Vec2 along = (1.0f / std::sqrt(1.0f + slope * slope)) * b2Vec2(1.0f, slope);
                const b2Vec2 shift = -0.95f * piece * along;
                b2BodyDef def;
                b2Body* ground = scene.world->CreateBody(&def);
                if (chain)
                {
                    const b2Vec2 points[] = {half + shift, -half + shift}; // front up: listed right to left
                    b2ChainShape shape;
                    shape.CreateChain(points, 2, half + half + shift, -half - half + shift);
                    ground->CreateFixture(&shape, 0.0f);
                }
                else
                {
                    b2EdgeShape shape;
                    shape.SetTwoSided(-half + shift, half + shift);
                    ground->CreateFixture(&shape, 0.0f);
                }
                std::mt19937 random(3);
                std::uniform_real_distribution<float> unit(0.0f, 1.0f);
                for (int step = 0; step < 480; ++step)
                {
                    for (int k = 0; k < 10; ++k)
                    {
                        const float x = 8.0f * unit(random) - 4.0f;
                        scene.Add(b2Vec2(x, slope * x + 0.5f + 0.5f * unit(random)), b2Vec2(0.0f, -5.0f),
                                  100.0f);
                    }
                    scene.world->Step(1.0f / 240.0f, 8, 3);
                    scene.system->Step(1.0f / 240.0f, scene.world->GetGravity());
                }
                std::uint32_t below = 0;
                for (std::uint32_t i = 0; i < scene.system->Count(); ++i)
                {
                    const b2Vec2 p = scene.Position(i);
                    below += p.y < slope * p.x ? 1u : 0u;
                }
                EXPECT_EQ(scene.system->Count(), 2000u);
                EXPECT_EQ(below, 0u);
                EXPECT_EQ(scene.system->Counters().crossings, 0u);
                EXPECT_EQ(scene.system->Counters().stepsInside, 0u);
            }
        }
    }
}

} // namespace cfx::test
