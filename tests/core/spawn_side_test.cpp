// Which side of a contact particles start on: the side they leave to, seen from the other body's
// footprint. A user's trial found a wheel spinning in place on dirt with 95 % of its dirt crushed at 60
// and 120 Hz (none at 30 and 240): it started where the rim comes down into the contact.
#include "test_world.h"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_polygon_shape.h>
#include <gtest/gtest.h>

namespace cfx::test
{
namespace
{

// Steps `scene` up to `steps` times, or until the first burst when `untilFirst`; for each impact of a step
// that spawned particles of rule 0, calls check(event, view, slot) for each of the step's new particles.
// Returns how many such impacts there were.
template <class Check> int EachBurst(TestWorld& scene, Effects& fx, int steps, bool untilFirst, Check&& check)
{
    int bursts = 0;
    for (int i = 0; i < steps && !(untilFirst && bursts > 0); ++i)
    {
        scene.Step();
        const std::uint32_t spawned = fx.Stats().rules[0].spawnedLastStep;
        for (const EffectEvent& event : fx.Events())
        {
            if (event.type != EffectEventType::impact || spawned == 0)
            {
                continue;
            }
            ++bursts;
            const ParticleView view = fx.Particles();
            for (std::uint32_t k = view.count - spawned; k < view.count; ++k)
            {
                check(event, view, view.Slot(k));
            }
        }
    }
    return bursts;
}

} // namespace

TEST(SpawnSide, AWheelSpinningInPlaceThrowsFromWhereItsRimRisesAtEveryStepRate)
{
    struct Case
    {
        const char* wheel;
        const char* ground;
        const char* particle;
    };
    for (const Case& pair : {Case{"rubber", "dirt", "dirt"}, Case{"steel", "concrete", "sparks"}})
    {
        for (const float hz : {30.0f, 60.0f, 120.0f, 240.0f})
        {
            SCOPED_TRACE(std::string(pair.wheel) + " on " + pair.ground + " at " + std::to_string(hz) +
                         " Hz");
            TestWorld scene;
            scene.particles.checkParticles = true;
            b2Body* ground = scene.CreateGround(0.3f);
            b2Body* wheel = scene.CreateCircle(b2Vec2(0.0f, 0.4f), 0.4f, 0.9f);
            Effects& fx = scene.Attach();
            fx.SetMaterial(ground, fx.FindMaterial(pair.ground));
            fx.SetMaterial(wheel, fx.FindMaterial(pair.wheel));
            int leftOfTheWheel = 0, rightOfTheWheel = 0;
            for (int step = 0; step < static_cast<int>(2.0f * hz); ++step)
            {
                wheel->SetAngularVelocity(-40.0f); // clockwise: the rim rises on the -x side
                wheel->SetLinearVelocity(b2Vec2(0.0f, wheel->GetLinearVelocity().y));
                scene.Step(1.0f / hz);
                const ParticleView view = fx.Particles();
                for (std::uint32_t i = 0; i < view.count; ++i)
                {
                    (view.positionX[view.Slot(i)] < 0.0f ? leftOfTheWheel : rightOfTheWheel) += 1;
                }
            }
            EXPECT_GT(scene.Spawned(pair.particle), 500u);
            EXPECT_EQ(fx.Stats().crushed, 0u);
            EXPECT_GT(leftOfTheWheel, 20 * rightOfTheWheel) << "thrown back, away from the wheel";
            EXPECT_EQ(fx.Stats().spawnedInsideSolid, 0u);
            EXPECT_EQ(fx.Stats().particleStepsInside, 0u);
        }
    }
}

TEST(SpawnSide, ASlidingBlockLeavesItsSparksBehindIt)
{
    // Whatever fixtures the block is made of, however long: the walk passes under the whole body, not one
    // fixture's length (a block of two 0.5 m fixtures started a third of its sparks ahead of its front face),
    // nor a bounded part of it (a re-check found 20 m blocks, and blocks of 80 fixtures, starting them
    // ahead).
    struct Block
    {
        float length; ///< m
        int fixtures;
    };
    for (const Block shape : {Block{1.0f, 1}, Block{1.0f, 2}, Block{1.0f, 4}, Block{1.0f, 8}, Block{1.0f, 80},
                              Block{20.0f, 1}, Block{20.0f, 100}})
    {
        const int fixtures = shape.fixtures;
        TestWorld scene;
        scene.particles.checkParticles = true;
        b2Body* ground = scene.CreateGround(0.5f);
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(-10.0f, 0.25f);
        b2Body* block = scene.world->CreateBody(&def);
        const float half = 0.5f * shape.length / static_cast<float>(fixtures);
        for (int k = 0; k < fixtures; ++k)
        {
            b2PolygonShape box;
            box.SetAsBox(half, 0.25f,
                         b2Vec2(-0.5f * shape.length + half * static_cast<float>(2 * k + 1), 0.0f), 0.0f);
            b2FixtureDef fixture;
            fixture.shape = &box;
            fixture.density = 1.0f;
            fixture.friction = 0.3f;
            block->CreateFixture(&fixture);
        }
        block->SetLinearVelocity(b2Vec2(14.0f, 0.0f));
        Effects& fx = scene.Attach();
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(block, fx.FindMaterial("steel"));
        std::uint32_t seen = 0;
        for (int step = 0; step < 20; ++step)
        {
            scene.Step();
            // Sparks fly at half the slip: none has caught up with the block's rear face yet.
            const float rear = block->GetPosition().x - 0.5f * shape.length;
            const ParticleView view = fx.Particles();
            for (std::uint32_t i = 0; i < view.count; ++i)
            {
                EXPECT_LT(view.positionX[view.Slot(i)], rear)
                    << shape.length << " m, " << fixtures << " fixtures, step " << step << ", particle " << i;
            }
            seen += view.count;
        }
        EXPECT_GT(seen, 200u) << shape.length << " m, " << fixtures << " fixtures";
        EXPECT_EQ(fx.Stats().crushed, 0u) << shape.length << " m, " << fixtures << " fixtures";
    }
}

// A long plank shoved into a wall: its sparks start on the wall above the plank. Walking down the wall face
// from the contact meets the floor the wall stands on, which ends that side: a re-check found them started
// under the floor, the free space beyond it (0 particle hits where there were 7).
TEST(SpawnSide, AWalkAlongTheSurfaceEndsAtWhatBlocksIt)
{
    TestWorld scene;
    scene.particles.checkParticles = true;
    b2Body* floor = scene.CreateGround(0.5f, 20.0f); // top at y = 0, 2 m thick
    b2Body* wall = scene.CreateBox(b2Vec2(-3.501f, 2.0f), 0.5f, 2.0f, 0.5f, b2_staticBody);
    b2Body* plank = scene.CreateBox(b2Vec2(0.0f, 0.1f), 3.0f, 0.1f, 0.3f);
    plank->SetLinearVelocity(b2Vec2(-8.0f, 0.0f));
    Effects& fx = scene.Attach();
    fx.SetMaterial(floor, fx.FindMaterial("concrete"));
    fx.SetMaterial(wall, fx.FindMaterial("concrete"));
    fx.SetMaterial(plank, fx.FindMaterial("steel"));
    std::uint32_t seen = 0;
    for (int step = 0; step < 30; ++step)
    {
        scene.Step();
        const ParticleView view = fx.Particles();
        for (std::uint32_t i = 0; i < view.count; ++i)
        {
            EXPECT_GT(view.positionY[view.Slot(i)], 0.0f) << "step " << step << ", particle " << i;
        }
        seen += view.count;
    }
    EXPECT_GT(scene.Spawned("sparks"), 10u);
    EXPECT_GT(seen, 100u);
    EXPECT_EQ(fx.Stats().spawnedInsideSolid, 0u);
}

// A trial laid a slab over a deep box, their tops level (y = 0), and slid a steel disc over the box's corner,
// which the slab covers. Sparks started under the slab: the walk projected a start onto the box's side
// face, below the slab, which is free but not reachable from the contact. Each start must now be reached
// from the last in a straight line that crosses no other solid.
TEST(SpawnSide, AFaceHiddenUnderAnotherFixtureIsNotReached)
{
    struct Run
    {
        float hz, speed, startX;
        bool circle;
    };
    for (const Run run :
         {Run{30.0f, 4.0f, -1.0f, true}, Run{60.0f, 4.0f, -1.0f, true}, Run{120.0f, 4.0f, -1.0f, true},
          Run{240.0f, 4.0f, -1.0f, true}, Run{120.0f, -4.0f, 1.5f, true}, Run{240.0f, -4.0f, 1.5f, true},
          Run{120.0f, 4.0f, -1.0f, false}, Run{240.0f, -4.0f, 1.5f, false}})
    {
        SCOPED_TRACE(testing::Message()
                     << run.hz << " Hz, " << run.speed << " m/s, " << (run.circle ? "disc" : "box"));
        TestWorld scene;
        scene.particles.checkParticles = true;
        b2BodyDef groundDef;
        b2Body* ground = scene.world->CreateBody(&groundDef);
        b2PolygonShape slab;
        slab.SetAsBox(3.0f, 0.075f, b2Vec2(0.0f, -0.075f), 0.0f); // x -3 .. 3, y -0.15 .. 0
        b2PolygonShape deep;
        deep.SetAsBox(0.5f, 0.4f, b2Vec2(0.5f, -0.4f), 0.0f); // x 0 .. 1, y -0.8 .. 0
        ground->CreateFixture(&slab, 0.0f)->SetFriction(0.6f);
        ground->CreateFixture(&deep, 0.0f)->SetFriction(0.6f);
        b2BodyDef slider;
        slider.type = b2_dynamicBody;
        slider.position.Set(run.startX, run.circle ? 0.11f : 0.1f);
        b2Body* body = scene.world->CreateBody(&slider);
        b2CircleShape disc;
        disc.m_radius = 0.11f;
        b2PolygonShape box;
        box.SetAsBox(0.15f, 0.1f);
        b2FixtureDef fixture;
        fixture.shape = run.circle ? static_cast<const b2Shape*>(&disc) : &box;
        fixture.density = 1.0f;
        fixture.friction = 0.6f;
        body->CreateFixture(&fixture);
        Effects& fx = scene.Attach();
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(body, fx.FindMaterial("steel"));
        const float dt = 1.0f / run.hz;
        std::uint32_t below = 0;
        for (int step = 0; step < static_cast<int>(run.hz); ++step) // 1 s
        {
            body->SetLinearVelocity(b2Vec2(run.speed, body->GetLinearVelocity().y));
            body->SetAngularVelocity(0.0f);
            scene.Step(dt);
            const ParticleView view = fx.Particles();
            for (std::uint32_t i = 0; i < view.count; ++i)
            {
                const std::uint32_t slot = view.Slot(i);
                below += view.life[slot] > 0.0f && view.positionY[slot] < 0.0f &&
                                 std::abs(view.positionX[slot]) < 3.0f
                             ? 1u
                             : 0u;
            }
        }
        EXPECT_GT(scene.Spawned("sparks"), 20u);
        EXPECT_EQ(below, 0u) << "particle steps below the ground's top";
        EXPECT_EQ(fx.Stats().spawnedInsideSolid, 0u);
        EXPECT_EQ(fx.Stats().particleStepsInside, 0u);
    }
}

// A trial dropped boxes flat on concrete: with no slip to tell a side, rounding picked one, and the burst
// started past the far edge (0.68 m from the corner that struck, for a 0.5 m box; 4.1 m for a 4 m slab), on
// a side that changed with gravity. With no motion along the surface, the walk goes outward from under the
// body, from the corner that struck.
TEST(SpawnSide, AFlatLandingsBurstStartsBesideTheCornerThatStruck)
{
    for (const float width : {0.5f, 2.0f, 4.0f})
    {
        for (const float gravity : {10.0f, 20.0f})
        {
            SCOPED_TRACE(testing::Message() << width << " m wide, gravity " << gravity);
            TestWorld scene(b2Vec2(0.0f, -gravity));
            b2Body* ground = scene.CreateGround();
            b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.25f + 2.0f), 0.5f * width, 0.25f, 0.5f);
            EffectsConfig config = DefaultPreset();
            TestWorld::StillSparks(config);
            Effects& fx = scene.AttachSteelOnConcrete(config, ground, box);
            const int bursts =
                EachBurst(scene, fx, 90, false,
                          [&](const EffectEvent& event, const ParticleView& view, std::uint32_t slot)
                          {
                              const float x = view.positionX[slot];
                              // Beside the corner, outside the box: within 5 cm of its side,
                              // on the corner's side.
                              EXPECT_LT(std::abs(x - event.point.x), 0.05f) << "corner at " << event.point.x;
                              EXPECT_GT(std::abs(x), 0.5f * width) << "outside the box";
                          });
            EXPECT_EQ(bursts, 1);
        }
    }
}

// A trial dropped tilted slabs: the burst of the slam (the second corner striking, the hardest impact)
// started at the slab's other end, 1 to 4 m from that corner, walked under the slab because the corner
// crept 0.24 m/s along the ground. An impact whose point slides slower than half its approach is a hit:
// every burst of a tilted landing starts beside its corner, outside the slab.
TEST(SpawnSide, ATiltedLandingsBurstsStartBesideTheCornersThatStruck)
{
    for (const float width : {1.0f, 4.0f})
    {
        for (const float degrees : {10.0f, 20.0f, 30.0f})
        {
            for (const float gravity : {0.0f, 10.0f}) // the trial's: thrown at 5 m/s without gravity
            {
                SCOPED_TRACE(testing::Message()
                             << width << " m wide, tilted " << degrees << " degrees, gravity " << gravity);
                TestWorld scene(b2Vec2(0.0f, -gravity));
                b2Body* ground = scene.CreateGround();
                b2Body* slab = scene.CreateBox(b2Vec2(0.0f, 0.5f * width + 0.5f), 0.5f * width, 0.25f, 0.5f);
                slab->SetTransform(slab->GetPosition(), degrees * b2_pi / 180.0f);
                slab->SetLinearVelocity(b2Vec2(0.0f, -5.0f));
                EffectsConfig config = DefaultPreset();
                // The bursts as a type of their own, told apart from the slide's sparks (which fall behind).
                ParticleTypeDef burst = TestWorld::StillSparks(config);
                burst.name = "burst";
                config.particleTypes.push_back(burst);
                config.rules[0].burstParticleType = "burst";
                Effects& fx = scene.AttachSteelOnConcrete(config, ground, slab);
                const std::uint16_t burstType = fx.Config().FindParticleType("burst").index;
                const int bursts =
                    EachBurst(scene, fx, 90, false,
                              [&](const EffectEvent& event, const ParticleView& view, std::uint32_t slot)
                              {
                                  if (view.type[slot] != burstType)
                                  {
                                      return;
                                  }
                                  const b2Vec2 start(view.positionX[slot], view.positionY[slot]);
                                  EXPECT_LT(std::abs(start.x - event.point.x), 0.1f)
                                      << "corner at " << event.point.x;
                                  const b2Vec2 local = slab->GetLocalPoint(start);
                                  EXPECT_TRUE(std::abs(local.x) > 0.5f * width || std::abs(local.y) > 0.25f)
                                      << "outside the slab: " << start.x << ", " << start.y;
                              });
                EXPECT_GE(bursts, 2) << "the first corner, then the slam";
            }
        }
    }
}

// The rule is on the slide of the point that struck, as documented: a slam sliding slower than half its
// approach bursts beside the corner, a faster one where its slide's own sparks start, behind it (a
// trial found the side flipping with the burst type's slipFactor, and the slip's side, ahead, between). A
// rolling wheel's landing, whose footprint is a point, bursts where its rim rises, as its dirt does.
TEST(SpawnSide, ASlidingSlamBurstsAsItsSlideAndARollingWheelsLandingWhereItsRimRises)
{
    // Where the first burst of a 4 m slab thrown at (vx, -3) m/s, tilted 5 degrees nose down, starts along x
    // from the corner that struck, and the slab's extent then.
    const auto slam = [](float vx) // (start - corner, rear end - corner)
    {
        TestWorld scene(b2Vec2(0.0f, 0.0f));
        b2Body* ground = scene.CreateGround();
        b2Body* slab = scene.CreateBox(b2Vec2(0.0f, 1.0f), 2.0f, 0.1f, 0.5f);
        slab->SetTransform(slab->GetPosition(), -5.0f * b2_pi / 180.0f);
        slab->SetLinearVelocity(b2Vec2(vx, -3.0f));
        EffectsConfig config = DefaultPreset();
        TestWorld::StillSparks(config);
        Effects& fx = scene.AttachSteelOnConcrete(config, ground, slab);
        for (int i = 0; i < 60; ++i)
        {
            scene.Step();
            for (const EffectEvent& event : fx.Events())
            {
                if (event.type == EffectEventType::impact && fx.Stats().rules[0].spawnedLastStep > 0)
                {
                    const ParticleView view = fx.Particles();
                    const std::uint32_t last = view.count - 1;
                    return std::pair{view.positionX[view.Slot(last)] - event.point.x,
                                     slab->GetWorldPoint(b2Vec2(-2.0f, 0.0f)).x - event.point.x};
                }
            }
        }
        ADD_FAILURE() << "no burst";
        return std::pair{0.0f, 0.0f};
    };
    const auto [slow, slowRear] = slam(1.0f);
    EXPECT_GT(slow, 0.0f) << "beside the front corner, outward";
    EXPECT_LT(slow, 0.1f);
    for (const float vx : {2.5f, 4.0f, 6.0f})
    {
        EXPECT_LT(slam(vx).first, 0.0f) << vx << " m/s: behind the corner";
    }
    const auto [fast, fastRear] = slam(10.0f);
    EXPECT_LT(fast, 0.0f) << "behind the corner, the side its slide's sparks start on (the first free place "
                             "under the slab, or past its rear at "
                          << fastRear << ")";

    // A wheel rolling at 5 m/s (no slip) dropped 0.5 m onto the ground: its burst behind the contact.
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* wheel = scene.CreateCircle(b2Vec2(0.0f, 1.0f), 0.5f, 0.9f);
    wheel->SetLinearVelocity(b2Vec2(5.0f, 0.0f));
    wheel->SetAngularVelocity(-10.0f);
    EffectsConfig config = DefaultPreset();
    TestWorld::StillSparks(config);
    Effects& fx = scene.AttachSteelOnConcrete(config, ground, wheel);
    const int bursts =
        EachBurst(scene, fx, 30, true,
                  [&](const EffectEvent& event, const ParticleView& view, std::uint32_t slot)
                  { EXPECT_LT(view.positionX[slot], event.point.x) << "behind the rolling wheel"; });
    EXPECT_EQ(bursts, 1);
}

} // namespace cfx::test
