// Emission does not depend on how the ground is cut up: one sliding contact between two bodies emits the
// same whether the ground is one box or a chain of short segments (issue 14, item 4).
#include "test_world.h"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>

namespace cfx::test
{

namespace
{

enum class Ground
{
    box,
    chain2m,
    chain05m,
};

// A static chain along y = 0 from x = -halfWidth to halfWidth, of segments `segment` m long.
b2Body* MakeChainGround(TestWorld& scene, float segment, float halfWidth)
{
    b2BodyDef def;
    b2Body* body = scene.world->CreateBody(&def);
    std::vector<b2Vec2> points;
    const int count = static_cast<int>(std::lround(2.0f * halfWidth / segment));
    for (int i = 0; i <= count; ++i)
    {
        points.emplace_back(halfWidth - segment * static_cast<float>(i), 0.0f); // right to left: front up
    }
    b2ChainShape chain;
    chain.CreateChain(points.data(), static_cast<int>(points.size()), b2Vec2(halfWidth + 1.0f, 0.0f),
                      b2Vec2(-halfWidth - 1.0f, 0.0f));
    b2FixtureDef fixture;
    fixture.shape = &chain;
    fixture.friction = 0.8f;
    body->CreateFixture(&fixture);
    return body;
}

// A static concrete ground whose top is y = 0, from x = -60 to 60.
b2Body* MakeGround(TestWorld& scene, Ground ground)
{
    if (ground == Ground::box)
    {
        return scene.CreateGround(0.8f, 60.0f);
    }
    return MakeChainGround(scene, ground == Ground::chain2m ? 2.0f : 0.5f, 60.0f);
}

struct SlideResult
{
    std::uint64_t sparks = 0;
    std::uint32_t contactsMax = 0;
    std::uint64_t rejected = 0;
    std::uint64_t overCapacity = 0;
    std::uint64_t inside = 0;
    std::uint32_t scrapes = 0; ///< scrapes that began
    std::uint32_t impacts = 0;
};

struct SlideSetup
{
    float hz = 60.0f;
    float seconds = 3.0f;
    float speed = 14.0f;     ///< m/s given at the start
    bool hold = false;       ///< hold the speed every step instead of letting friction slow the block
    float density = 1.0f;    ///< kg/m^2 of the 1 x 0.5 m block
    float dropHeight = 0.0f; ///< m above the ground
};

// A steel block 1 x 0.5 m given `speed` along concrete, left to slide (or held at that speed).
SlideResult Slide(EffectsConfig config, Ground ground, const SlideSetup& setup,
                  std::vector<float>* state = nullptr)
{
    TestWorld scene;
    b2Body* floor = MakeGround(scene, ground);
    b2Body* block = scene.CreateBox(b2Vec2(-20.0f, 0.25f + setup.dropHeight), 0.5f, 0.25f, 0.5f);
    block->GetFixtureList()->SetDensity(setup.density);
    block->ResetMassData();
    scene.particles.checkParticles = true; // audits every start (spawnedInsideSolid)
    Effects& fx = scene.Attach(std::move(config));
    fx.SetMaterial(floor, fx.FindMaterial("concrete"));
    fx.SetMaterial(block, fx.FindMaterial("steel"));
    block->SetLinearVelocity(b2Vec2(setup.speed, 0.0f));
    const float dt = 1.0f / setup.hz;
    const int steps = static_cast<int>(std::lround(setup.seconds * setup.hz));
    SlideResult result;
    for (int i = 0; i < steps; ++i)
    {
        scene.world->Step(dt, 8, 3);
        if (setup.hold)
        {
            block->SetLinearVelocity(b2Vec2(setup.speed, block->GetLinearVelocity().y));
            block->SetAngularVelocity(0.0f);
        }
        fx.Step(dt);
        for (const EffectEvent& event : fx.Events())
        {
            result.scrapes += event.type == EffectEventType::scrapeBegan ? 1 : 0;
            result.impacts += event.type == EffectEventType::impact ? 1 : 0;
        }
    }
    result.sparks = scene.Spawned("sparks");
    result.contactsMax = fx.Stats().rules[0].contactsMax;
    result.inside = fx.Stats().spawnedInsideSolid;
    result.rejected = fx.Stats().spawnRejected;
    result.overCapacity = fx.Stats().spawnOverCapacity;
    if (state != nullptr)
    {
        const ParticleView view = fx.Particles();
        for (std::uint32_t i = 0; i < view.count; ++i)
        {
            const std::uint32_t slot = view.Slot(i);
            state->insert(state->end(), {view.positionX[slot], view.positionY[slot], view.velocityX[slot],
                                         view.velocityY[slot], view.life[slot]});
        }
    }
    return result;
}

double Ratio(std::uint64_t a, std::uint64_t b)
{
    return static_cast<double>(a) / static_cast<double>(b);
}

} // namespace

// The numbers: 2,248 sparks on one box, 3,936 on 2 m segments, 9,003 on 0.5 m segments.
TEST(EmissionTessellation, BlockSlidingOnOneBoxOrOnChainsEmitsTheSame)
{
    for (float hz : {30.0f, 60.0f, 120.0f})
    {
        SCOPED_TRACE(std::to_string(hz) + " Hz");
        const SlideSetup setup{.hz = hz};
        const SlideResult box = Slide(DefaultPreset(), Ground::box, setup);
        const SlideResult chain2 = Slide(DefaultPreset(), Ground::chain2m, setup);
        const SlideResult chain05 = Slide(DefaultPreset(), Ground::chain05m, setup);
        ASSERT_GT(box.sparks, 300u);
        EXPECT_GE(chain05.contactsMax, 2u) << "the block spans several segments";
        EXPECT_NEAR(Ratio(chain2.sparks, box.sparks), 1.0, 0.1) << chain2.sparks << " vs " << box.sparks;
        EXPECT_NEAR(Ratio(chain05.sparks, box.sparks), 1.0, 0.1) << chain05.sparks << " vs " << box.sparks;
        for (const SlideResult* result : {&box, &chain2, &chain05})
        {
            EXPECT_EQ(result->inside, 0u);
            EXPECT_EQ(result->scrapes, 1u) << "one sliding contact, one scrape";
        }
    }
}

// A heavy block: the pressure term (impulseWeight) takes the pair's whole load, however many points share it.
TEST(EmissionTessellation, HeavyBlockEmitsTheSameToo)
{
    for (float hz : {30.0f, 60.0f, 120.0f})
    {
        SCOPED_TRACE(std::to_string(hz) + " Hz");
        const SlideSetup setup{.hz = hz, .density = 20.0f};
        const SlideResult box = Slide(DefaultPreset(), Ground::box, setup);
        const SlideResult chain05 = Slide(DefaultPreset(), Ground::chain05m, setup);
        ASSERT_GT(box.sparks, 300u);
        EXPECT_NEAR(Ratio(chain05.sparks, box.sparks), 1.0, 0.1) << chain05.sparks << " vs " << box.sparks;
    }
}

// The fraction of a particle owed is carried per body pair: at a rate of a third of a particle per step,
// a block handed from segment to segment emits what the rate integrates to, as on one box.
TEST(EmissionTessellation, CarryFollowsTheBlockFromSegmentToSegment)
{
    EffectsConfig slow = DefaultPreset();
    slow.rules[0].ratePerIntensity = 5.0f; // 6 m/s * 0.63 * (1 + pressure) ~ 4: about 15 per second
    for (float hz : {30.0f, 60.0f, 120.0f})
    {
        SCOPED_TRACE(std::to_string(hz) + " Hz");
        const SlideSetup setup{.hz = hz, .speed = 6.0f, .hold = true};
        const SlideResult box = Slide(slow, Ground::box, setup);
        const SlideResult chain05 = Slide(slow, Ground::chain05m, setup);
        ASSERT_GT(box.sparks, 30u);
        EXPECT_NEAR(static_cast<double>(chain05.sparks), static_cast<double>(box.sparks), 2.0);
    }
}

// The tutorial preset keeps the tutorial's one particle per contact per step: its count grows with the
// segments the block touches. (At 120 Hz Box2D keeps the block touching one segment most steps, so the
// growth shows at the tutorial's 60 Hz and below.)
TEST(EmissionTessellation, TutorialPresetStillEmitsPerContact)
{
    for (float hz : {30.0f, 60.0f})
    {
        SCOPED_TRACE(std::to_string(hz) + " Hz");
        const SlideSetup setup{.hz = hz};
        const SlideResult box = Slide(TutorialPreset(), Ground::box, setup);
        const SlideResult chain2 = Slide(TutorialPreset(), Ground::chain2m, setup);
        const SlideResult chain05 = Slide(TutorialPreset(), Ground::chain05m, setup);
        ASSERT_GT(box.sparks, 0u);
        // One box: one contact, one particle a step while the block is fast enough (3 s at most).
        EXPECT_LE(box.sparks, static_cast<std::uint64_t>(3.0f * hz));
        EXPECT_GT(Ratio(chain2.sparks, box.sparks), 1.3);
        EXPECT_GT(Ratio(chain05.sparks, box.sparks), 1.8);
        EXPECT_EQ(chain05.inside, 0u);
    }
}

// A block landing flat across several segments is one impact (and one burst), as on one box.
TEST(EmissionTessellation, LandingOnSegmentsIsOneImpact)
{
    for (float hz : {30.0f, 60.0f, 120.0f})
    {
        SCOPED_TRACE(std::to_string(hz) + " Hz");
        const SlideSetup setup{.hz = hz, .seconds = 1.5f, .speed = 0.0f, .dropHeight = 1.5f};
        const SlideResult box = Slide(DefaultPreset(), Ground::box, setup);
        const SlideResult chain05 = Slide(DefaultPreset(), Ground::chain05m, setup);
        EXPECT_EQ(box.impacts, 1u);
        EXPECT_EQ(chain05.impacts, 1u);
        EXPECT_GT(box.sparks, 0u) << "the burst";
        EXPECT_NEAR(static_cast<double>(chain05.sparks), static_cast<double>(box.sparks), 2.0);
    }
}

TEST(EmissionTessellation, ACircleRollingAlongAChainIsOneScrapeEitherWay)
{
    // A steel disc held at 6 m/s along a concrete chain of 0.1 m segments: Box2D hands the disc from one
    // segment's contact to the next, in one direction of the chain reporting the old one's end before the
    // new one's begin within the same world step. Either way it is one sliding contact: one scrape.
    for (const float direction : {-1.0f, 1.0f})
    {
        for (const float hz : {30.0f, 60.0f, 120.0f})
        {
            TestWorld scene;
            b2Body* floor = MakeChainGround(scene, 0.1f, 100.0f);
            b2Body* disc = scene.CreateCircle(b2Vec2(0.1f, 0.3f), 0.3f, 0.6f);
            disc->SetFixedRotation(true);
            Effects& fx = scene.Attach(DefaultPreset());
            fx.SetMaterial(floor, fx.FindMaterial("concrete"));
            fx.SetMaterial(disc, fx.FindMaterial("steel"));
            int began = 0;
            int ended = 0;
            const float dt = 1.0f / hz;
            for (int i = 0; i < static_cast<int>(2.0f * hz); ++i)
            {
                disc->SetLinearVelocity(b2Vec2(6.0f * direction, disc->GetLinearVelocity().y));
                scene.world->Step(dt, 8, 3);
                fx.Step(dt);
                for (const EffectEvent& event : fx.Events())
                {
                    began += event.type == EffectEventType::scrapeBegan ? 1 : 0;
                    ended += event.type == EffectEventType::scrapeEnded ? 1 : 0;
                }
            }
            EXPECT_EQ(began, 1) << "direction " << direction << ", " << hz << " Hz";
            EXPECT_EQ(ended, 0) << "direction " << direction << ", " << hz << " Hz";
            EXPECT_GT(scene.Spawned("sparks"), 0u);
        }
    }
}

// A box landing at a tilt hits with one corner, then slams down its other corner. On a chain the second
// corner meets another segment, a new contact; on one box it is a new manifold point of the same contact,
// and a trial found it reported on chains only (1 impact on a box, 2 on 0.5 m segments). A manifold point
// that begins touching is a new touch: one box hears the slam too. On chains the face coming down can touch
// a segment's vertex before the corner lands (an impact of its own at the face's speed there): the first
// impact is the same on every ground, the count is 2 or 3.
TEST(Impacts, ATiltedLandingHitsTwiceOnOneBoxAndOnChainSegments)
{
    for (const float hz : {30.0f, 60.0f, 120.0f})
    {
        std::vector<std::vector<float>> speedsByGround;
        for (const Ground ground : {Ground::box, Ground::chain05m, Ground::chain2m})
        {
            TestWorld scene;
            b2Body* floor = MakeGround(scene, ground);
            b2BodyDef def;
            def.type = b2_dynamicBody;
            def.position.Set(0.1f, 2.0f);
            def.angle = 0.3f;
            b2Body* box = scene.world->CreateBody(&def);
            b2PolygonShape shape;
            shape.SetAsBox(1.1f, 0.5f);
            box->CreateFixture(&shape, 4.0f)->SetFriction(0.6f);
            Effects& fx = scene.Attach();
            fx.SetMaterial(floor, fx.FindMaterial("concrete"));
            fx.SetMaterial(box, fx.FindMaterial("steel"));
            std::vector<float> speeds;
            for (int step = 0; step < static_cast<int>(2.0f * hz); ++step)
            {
                scene.Step(1.0f / hz);
                for (const EffectEvent& event : fx.Events())
                {
                    if (event.type == EffectEventType::impact)
                    {
                        speeds.push_back(event.approachSpeed);
                    }
                }
            }
            speedsByGround.push_back(speeds);
        }
        SCOPED_TRACE(testing::Message() << hz << " Hz");
        ASSERT_EQ(speedsByGround[0].size(), 2u) << "one box: the first corner, then the second";
        for (std::size_t ground = 1; ground < speedsByGround.size(); ++ground)
        {
            ASSERT_GE(speedsByGround[ground].size(), 2u) << "chain " << ground;
            EXPECT_LE(speedsByGround[ground].size(), 3u) << "chain " << ground;
            EXPECT_NEAR(speedsByGround[ground][0], speedsByGround[0][0], 0.01f * speedsByGround[0][0])
                << "chain " << ground << ": the first corner";
        }
        EXPECT_GT(speedsByGround[0][1], speedsByGround[0][0]) << "the slam is the harder hit";
    }
}

// Box2D renames the manifold points of a box at rest on a chain now and then; a re-check with impactThreshold
// 0 heard those as impacts at 0 m/s, one a step. A point added to a touching contact must approach to be a
// touch.
TEST(Impacts, ABoxAtRestOnAChainMakesNoImpactsAtAnyThreshold)
{
    for (const float hz : {30.0f, 60.0f, 120.0f, 240.0f})
    {
        TestWorld scene;
        b2Body* floor = MakeGround(scene, Ground::chain05m);
        b2Body* box = scene.CreateBox(b2Vec2(0.3f, 0.26f), 2.0f, 0.25f, 0.6f);
        EffectsConfig config = DefaultPreset();
        for (RuleDef& rule : config.rules)
        {
            rule.impactThreshold = 0.0f;
        }
        Effects& fx = scene.Attach(std::move(config));
        fx.SetMaterial(floor, fx.FindMaterial("concrete"));
        fx.SetMaterial(box, fx.FindMaterial("steel"));
        int impacts = 0;
        for (int step = 0; step < static_cast<int>(2.0f * hz); ++step)
        {
            scene.Step(1.0f / hz);
            for (const EffectEvent& event : fx.Events())
            {
                impacts += event.type == EffectEventType::impact ? 1 : 0;
            }
        }
        EXPECT_EQ(impacts, 0) << hz << " Hz: it starts 1 cm above and settles without approaching";
    }
}

TEST(EmissionBudget, AStepSpawnsAtMostTheCapacityAndCountsWhatItOwedBeyond)
{
    // A held slide whose rule always owes 600 sparks a second: 10 a step at 60 Hz (no bursts), and in its
    // first step also the pair's savings, 600 / 30 = 20 (RuleDef::maxRate). With room for 3, every emitting
    // step spawns 3 and counts the rest over capacity; with room for 100, all of them.
    EffectsConfig config = DefaultPreset();
    config.rules[0].ratePerIntensity = 1.0e6f;
    config.rules[0].maxRate = 600.0f;
    config.rules[0].burstPerSpeed = 0.0f;
    const SlideSetup setup{.seconds = 1.0f, .speed = 8.0f, .hold = true};
    for (const std::uint32_t capacity : {3u, 100u})
    {
        EffectsConfig capped = config;
        capped.budget.capacity = capacity;
        const SlideResult slide = Slide(capped, Ground::box, setup);
        ASSERT_GT(slide.sparks, 0u) << capacity;
        if (capacity == 3)
        {
            EXPECT_EQ(slide.sparks % 3, 0u);
            EXPECT_EQ(slide.overCapacity, slide.sparks / 3 * 7 + 20);
        }
        else
        {
            EXPECT_EQ(slide.sparks % 10, 0u);
            EXPECT_EQ(slide.overCapacity, 0u);
        }
        EXPECT_EQ(slide.rejected, 0u) << capacity;
    }
}

TEST(EmissionBudget, PerStepEmissionPastTheCapacityIsCountedToo)
{
    // The tutorial's per-contact emission, one particle per sample per step, on a chain of 0.5 m segments (a
    // 1 m block spans two or three): with room for 1, every particle a step owes past the first is counted.
    // Pool particles move no body, so the two runs slide alike and owe the same.
    EffectsConfig config = DefaultPreset();
    config.rules[0].emission = EmissionMode::perStep;
    config.rules[0].burstPerSpeed = 0.0f;
    const SlideSetup setup{.seconds = 1.0f, .speed = 8.0f, .hold = true};
    EffectsConfig roomy = config;
    roomy.budget.capacity = 1000;
    EffectsConfig tight = config;
    tight.budget.capacity = 1;
    const SlideResult all = Slide(roomy, Ground::chain05m, setup);
    const SlideResult capped = Slide(tight, Ground::chain05m, setup);
    EXPECT_EQ(all.overCapacity, 0u);
    EXPECT_GT(capped.overCapacity, 0u);
    EXPECT_LE(capped.sparks, 60u) << "at most one a step";
    EXPECT_EQ(capped.sparks + capped.overCapacity, all.sparks);
}

TEST(EmissionTessellation, SameSeedSameParticlesOnAChain)
{
    std::vector<float> first;
    std::vector<float> second;
    Slide(DefaultPreset(), Ground::chain05m, SlideSetup{.seconds = 1.0f}, &first);
    Slide(DefaultPreset(), Ground::chain05m, SlideSetup{.seconds = 1.0f}, &second);
    ASSERT_FALSE(first.empty());
    EXPECT_EQ(first, second);
}

} // namespace cfx::test
