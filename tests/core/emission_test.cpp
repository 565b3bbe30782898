#include "effects_access.h"
#include "test_world.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <tuple>
#include <vector>

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
    TestWorld::StillSparks(still).slipFactor = 0.0f;
    Effects& fx = scene.AttachSteelOnConcrete(still, ground, box);
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

// A trial found sparks thrown against a grinding wheel's rim, and backwards on a moving platform: the start
// velocity added the slip to nothing, not to the surface's own velocity, so it depended on which body was
// still. In the surface's frame (the default), a block sliding over a moving platform throws what a block
// sliding as fast over still ground throws, carried along with the platform; the tutorial's world frame is
// kept for its preset.
TEST(Emission, SparksAreThrownInTheMovingSurfacesFrame)
{
    // The start velocity (x) of every spark of a steel block held at `block` m/s on a kinematic concrete
    // platform moving at `platform` m/s: the mean and how far any is from it.
    const auto sparkVelocity = [](float block, float platform, VelocityFrame frame)
    {
        TestWorld scene;
        b2Body* ground = scene.CreateBox(b2Vec2(0.0f, -0.5f), 50.0f, 0.5f, 0.8f, b2_kinematicBody);
        ground->SetLinearVelocity(b2Vec2(platform, 0.0f));
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        EffectsConfig config = DefaultPreset();
        TestWorld::StillSparks(config).velocityFrame = frame;
        Effects& fx = scene.AttachSteelOnConcrete(config, ground, box);
        double sum = 0.0;
        float low = 1e9f, high = -1e9f;
        std::uint32_t count = 0;
        for (int i = 0; i < 60; ++i)
        {
            scene.world->Step(1.0f / 60.0f, 8, 3);
            box->SetLinearVelocity(b2Vec2(block, box->GetLinearVelocity().y));
            box->SetAngularVelocity(0.0f);
            fx.Step(1.0f / 60.0f);
            const ParticleView view = fx.Particles();
            for (std::uint32_t k = view.count - fx.Stats().rules[0].spawnedLastStep; k < view.count; ++k)
            {
                const float vx = view.velocityX[view.Slot(k)];
                sum += vx;
                low = std::min(low, vx);
                high = std::max(high, vx);
                ++count;
            }
        }
        EXPECT_GT(count, 30u);
        EXPECT_LT(high - low, 1e-3f) << "every spark starts alike";
        return static_cast<float>(sum / std::max(count, 1u));
    };
    // slipFactor 0.5 of the block's slide over the concrete, plus the concrete's own velocity.
    EXPECT_NEAR(sparkVelocity(5.0f, 0.0f, VelocityFrame::surface), 2.5f, 1e-3f);
    EXPECT_NEAR(sparkVelocity(10.0f, 5.0f, VelocityFrame::surface), 7.5f, 1e-3f);
    EXPECT_NEAR(sparkVelocity(0.0f, 5.0f, VelocityFrame::surface), 2.5f, 1e-3f)
        << "the platform slides under";
    EXPECT_NEAR(sparkVelocity(0.0f, -5.0f, VelocityFrame::surface), -2.5f, 1e-3f);
    // The world frame: the slip alone.
    EXPECT_NEAR(sparkVelocity(5.0f, 0.0f, VelocityFrame::world), 2.5f, 1e-3f);
    EXPECT_NEAR(sparkVelocity(10.0f, 5.0f, VelocityFrame::world), 2.5f, 1e-3f);
    EXPECT_NEAR(sparkVelocity(0.0f, 5.0f, VelocityFrame::world), -2.5f, 1e-3f);
    EXPECT_EQ(TutorialPreset().particleTypes[0].velocityFrame, VelocityFrame::world);
}

// A trial's game made ice by setting its contacts' friction to 0 in PreSolve: the block slid on without
// slowing, yet threw 238 sparks a second, more than on plain concrete (the emission mixed the fixtures'
// frictions). A conveyor belt (b2Contact::SetTangentSpeed) carrying a block at its own speed is no slide at
// all. The emission now reads what Box2D's solver uses: the friction the application set on the contact,
// and the belt's tangent speed as a motion of its surface.
TEST(Emission, AContactsOwnFrictionAndTangentSpeedAreWhatTheSparksFollow)
{
    class Surface final : public b2ContactListener
    {
    public:
        void PreSolve(b2Contact* contact, const b2Manifold*) override
        {
            if (friction >= 0.0f)
            {
                contact->SetFriction(friction);
            }
            // The ground is fixture A or B: the belt moves its surface along +x either way.
            const bool groundIsA = contact->GetFixtureA()->GetBody()->GetType() == b2_staticBody;
            b2WorldManifold manifold;
            contact->GetWorldManifold(&manifold);
            const float along = b2Cross(manifold.normal, 1.0f).x; // the tangent's x, +-1 on flat ground
            contact->SetTangentSpeed((groundIsA ? 1.0f : -1.0f) * belt * along);
        }
        float friction = -1.0f; // < 0: left as mixed
        float belt = 0.0f;      // m/s along +x
    };
    // Sparks of a steel block held at `speed` (or left to the belt when `held` is false) for 2 s.
    const auto sparks = [](float friction, float belt, float speed, bool held)
    {
        Surface surface;
        surface.friction = friction;
        surface.belt = belt;
        TestWorld scene;
        b2Body* ground = scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        box->SetLinearVelocity(b2Vec2(speed, 0.0f));
        Effects& fx = scene.AttachSteelOnConcrete(DefaultPreset(), ground, box, &surface);
        for (int i = 0; i < 120; ++i)
        {
            scene.world->Step(1.0f / 60.0f, 8, 3);
            if (held)
            {
                box->SetLinearVelocity(b2Vec2(speed, box->GetLinearVelocity().y));
                box->SetAngularVelocity(0.0f);
            }
            fx.Step(1.0f / 60.0f);
        }
        return std::pair{scene.Spawned("sparks"), box->GetLinearVelocity().x};
    };
    const auto [concrete, concreteSpeed] = sparks(-1.0f, 0.0f, 6.0f, true);
    ASSERT_GT(concrete, 200u);
    // Ice: no friction, no sparks, and nothing slows the block.
    const auto [ice, iceSpeed] = sparks(0.0f, 0.0f, 6.0f, false);
    EXPECT_EQ(ice, 0u);
    EXPECT_FLOAT_EQ(iceSpeed, 6.0f);
    // A contact made rougher than its fixtures' mix (0.632; 0.9 keeps the 1 m block from tipping): an
    // intensity of 6 * 0.9 * 1.2 instead of 6 * 0.632 * 1.2 above the threshold of 1, 438 sparks a second
    // instead of 284.
    EXPECT_GT(sparks(0.9f, 0.0f, 6.0f, true).first, concrete + concrete / 3);
    // Carried by a belt at 6 m/s, the block does not slide over it: nothing. Held still on it, it slides at
    // 6 m/s over the belt: as many as on still concrete at 6 m/s.
    const auto [carried, carriedSpeed] = sparks(-1.0f, 6.0f, 6.0f, false);
    EXPECT_NEAR(carriedSpeed, 6.0f, 0.01f) << "the belt carries it";
    EXPECT_EQ(carried, 0u);
    EXPECT_EQ(sparks(-1.0f, 6.0f, 0.0f, true).first, concrete);
}

// A trial found the friction an application set lost where the contact began before the effects tracked
// it (effects created later, a material given later), and a belt that was the contact's fixture B moved
// the block instead of itself (a polygon belt created after the block is fixture B): its sparks went the
// wrong way. The contact's own friction is now whatever differs from Box2D's mix, however it came to differ.
TEST(Emission, AnIcyContactMadeBeforeTheEffectsAndABeltAsFixtureBAreTakenAsBox2DTakesThem)
{
    class Icy final : public b2ContactListener
    {
    public:
        void BeginContact(b2Contact* contact) override { contact->SetFriction(0.0f); }
    };
    // Ice set once, in BeginContact, 10 steps before the effects exist: no sparks from a sliding block.
    for (const bool late : {false, true})
    {
        Icy icy;
        TestWorld scene;
        scene.world->SetContactListener(&icy);
        b2Body* ground = scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        box->SetLinearVelocity(b2Vec2(6.0f, 0.0f));
        for (int i = 0; late && i < 10; ++i)
        {
            scene.Step();
        }
        scene.AttachSteelOnConcrete(DefaultPreset(), ground, box, &icy);
        for (int i = 0; i < 60; ++i)
        {
            scene.Step();
        }
        EXPECT_FLOAT_EQ(box->GetLinearVelocity().x, 6.0f) << "ice, late " << late;
        EXPECT_EQ(scene.Spawned("sparks"), 0u) << "late " << late;
    }

    // A fixture's friction changed while touching: Box2D's contact keeps the old one until ResetFriction,
    // and so do the sparks; after ResetFriction, the new mix (0: none).
    {
        TestWorld scene;
        b2Body* ground = scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        scene.AttachSteelOnConcrete(DefaultPreset(), ground, box);
        const auto slide = [&](int steps)
        {
            const std::uint64_t before = scene.Spawned("sparks");
            for (int i = 0; i < steps; ++i)
            {
                box->SetLinearVelocity(b2Vec2(6.0f, box->GetLinearVelocity().y));
                box->SetAngularVelocity(0.0f);
                scene.Step();
            }
            return scene.Spawned("sparks") - before;
        };
        const std::uint64_t rough = slide(30);
        ASSERT_GT(rough, 100u);
        ground->GetFixtureList()->SetFriction(0.0f);
        EXPECT_NEAR(static_cast<double>(slide(30)), static_cast<double>(rough),
                    0.1 * static_cast<double>(rough))
            << "the contact still has its old friction";
        for (b2Contact* c = scene.world->GetContactList(); c != nullptr; c = c->GetNext())
        {
            c->ResetFriction();
        }
        EXPECT_EQ(slide(30), 0u) << "after ResetFriction";
    }

    // A block held still on a polygon belt moving at 6 m/s along +x, the belt created before the block
    // (fixture A) or after it (fixture B): the start velocity of its sparks.
    class Belt final : public b2ContactListener
    {
    public:
        void PreSolve(b2Contact* contact, const b2Manifold*) override
        {
            // The solver drives B over A to the tangent speed (Box2D's testbed conveyor sets +- its speed).
            const bool beltIsA = contact->GetFixtureA()->GetBody()->GetType() == b2_staticBody;
            b2WorldManifold manifold;
            contact->GetWorldManifold(&manifold);
            const float along = b2Cross(manifold.normal, 1.0f).x;
            contact->SetTangentSpeed((beltIsA ? 6.0f : -6.0f) * along);
        }
    };
    const auto sparkVelocity = [](bool beltFirst, VelocityFrame frame)
    {
        Belt belt;
        TestWorld scene;
        b2Body* ground =
            beltFirst ? scene.CreateBox(b2Vec2(0.0f, -0.5f), 50.0f, 0.5f, 0.8f, b2_staticBody) : nullptr;
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        ground = beltFirst ? ground : scene.CreateBox(b2Vec2(0.0f, -0.5f), 50.0f, 0.5f, 0.8f, b2_staticBody);
        EffectsConfig config = DefaultPreset();
        TestWorld::StillSparks(config).velocityFrame = frame;
        Effects& fx = scene.AttachSteelOnConcrete(config, ground, box, &belt);
        double sum = 0.0;
        std::uint32_t count = 0;
        bool beltWasA = false;
        for (int i = 0; i < 60; ++i)
        {
            scene.world->Step(1.0f / 60.0f, 8, 3);
            box->SetLinearVelocity(b2Vec2(0.0f, box->GetLinearVelocity().y));
            box->SetAngularVelocity(0.0f);
            fx.Step(1.0f / 60.0f);
            for (const b2Contact* c = scene.world->GetContactList(); c != nullptr; c = c->GetNext())
            {
                beltWasA = c->GetFixtureA()->GetBody() == ground;
            }
            const ParticleView view = fx.Particles();
            for (std::uint32_t k = view.count - fx.Stats().rules[0].spawnedLastStep; k < view.count; ++k)
            {
                sum += view.velocityX[view.Slot(k)];
                ++count;
            }
        }
        EXPECT_EQ(beltWasA, beltFirst) << "the scene has the fixture order it means to";
        EXPECT_GT(count, 30u);
        return static_cast<float>(sum / std::max(count, 1u));
    };
    for (const bool beltFirst : {true, false})
    {
        // The block slides at -6 m/s over the belt: slipFactor 0.5 of it, plus the belt's 6 m/s in the
        // surface's frame; the slip alone in the world's.
        EXPECT_NEAR(sparkVelocity(beltFirst, VelocityFrame::surface), 3.0f, 1e-3f)
            << "belt first " << beltFirst;
        EXPECT_NEAR(sparkVelocity(beltFirst, VelocityFrame::world), -3.0f, 1e-3f)
            << "belt first " << beltFirst;
    }
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

// A box landing while it slides presses the ground with a spike of force for one step: its rate, above
// maxRate in that step, was cut to maxRate * dt, so the landing's share fell with the step rate (a trial:
// 49, 35, 29 and 26 sparks at 30, 60, 120 and 240 Hz, 26, 13, 6 and 3 of them in the landing step). The cap
// now holds over time: a spike within what the pair saved of its allowance is not cut at all.
std::uint64_t LandSlidingBox(float hz, float maxRate)
{
    TestWorld scene;
    b2Body* ground = scene.CreateGround(0.8f);
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 1.25f), 0.5f, 0.25f, 0.5f);
    box->GetFixtureList()->SetDensity(4.0f);
    box->ResetMassData();
    box->SetLinearVelocity(b2Vec2(6.0f, 0.0f));
    EffectsConfig config = DefaultPreset();
    for (RuleDef& rule : config.rules)
    {
        rule.burstPerSpeed = 0.0f; // rate emission only
        rule.maxRate = maxRate;
    }
    Effects& fx = scene.Attach(std::move(config));
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(box, fx.FindMaterial("steel"));
    for (int i = 0; i < static_cast<int>(2.0f * hz); ++i)
    {
        scene.Step(1.0f / hz);
    }
    return scene.Spawned("sparks");
}

// A trial's artist wanted bursts on hard impacts only: raising impactThreshold also removed the softer
// impacts' events and sound. burstThreshold above impactThreshold keeps them, without particles; at or
// below it, it changes nothing.
TEST(Emission, ABurstThresholdKeepsSoftImpactsAsEventsWithoutParticles)
{
    struct Drop
    {
        float approach = 0.0f; ///< the impact event's, m/s (0: none)
        std::uint64_t sparks = 0;
    };
    const auto drop = [](float speed, float burstThreshold)
    {
        TestWorld scene;
        b2Body* ground = scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.56f), 0.5f, 0.5f, 0.5f);
        box->SetLinearVelocity(b2Vec2(0.0f, -speed));
        EffectsConfig config = DefaultPreset();
        config.budget.capacity = 100000;
        RuleDef& rule = config.rules[0]; // steel on concrete
        rule.ratePerIntensity = 0.0f;    // bursts only
        rule.impactThreshold = 2.0f;
        rule.burstPerSpeed = 10.0f;
        rule.burstMax = 1000.0f;
        rule.burstThreshold = burstThreshold;
        Effects& fx = scene.Attach(std::move(config));
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(box, fx.FindMaterial("steel"));
        Drop result;
        for (int i = 0; i < 30; ++i)
        {
            scene.Step();
            for (const EffectEvent& event : fx.Events())
            {
                result.approach =
                    event.type == EffectEventType::impact ? event.approachSpeed : result.approach;
            }
        }
        result.sparks = scene.Spawned("sparks");
        return result;
    };
    for (const float burstThreshold : {0.0f, 1.0f, 2.0f, 6.0f})
    {
        SCOPED_TRACE(burstThreshold);
        const Drop soft = drop(4.0f, burstThreshold);
        const Drop hard = drop(9.0f, burstThreshold);
        ASSERT_GT(soft.approach, 2.0f) << "an impact event either way";
        ASSERT_LT(soft.approach, 6.0f);
        ASSERT_GT(hard.approach, 6.0f);
        const float from = std::max(2.0f, burstThreshold);
        EXPECT_EQ(soft.sparks,
                  soft.approach > from ? static_cast<std::uint64_t>(10.0f * (soft.approach - from)) : 0u);
        EXPECT_EQ(hard.sparks, static_cast<std::uint64_t>(10.0f * (hard.approach - from)));
    }
}

// A trial's artist wanted wood on stone to scrape dust and burst splinters: one rule per pair, and a burst
// was always of the rule's type. burstParticleType names the type its impacts burst.
TEST(Emission, ARulesImpactsBurstItsBurstTypeWhileItsScrapesEmitItsOwn)
{
    const auto drop = [](const std::string& burstType)
    {
        TestWorld scene;
        b2Body* ground = scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.56f), 0.5f, 0.5f, 0.5f);
        box->SetLinearVelocity(b2Vec2(0.0f, -9.0f)); // lands hard, then is pushed along
        EffectsConfig config = DefaultPreset();
        config.budget.capacity = 100000;
        RuleDef& rule = config.rules[0]; // steel on concrete: sparks
        rule.burstPerSpeed = 10.0f;
        rule.burstMax = 1000.0f;
        rule.burstParticleType = burstType;
        Effects& fx = scene.AttachSteelOnConcrete(std::move(config), ground, box);
        float approach = 0.0f;
        std::uint64_t sparksAfterLanding = 0;
        for (int i = 0; i < 60; ++i)
        {
            scene.world->Step(1.0f / 60.0f, 8, 3);
            if (i >= 10) // after the landing, pushed along the ground
            {
                box->SetLinearVelocity(b2Vec2(5.0f, box->GetLinearVelocity().y));
                box->SetAngularVelocity(0.0f);
            }
            fx.Step(1.0f / 60.0f);
            for (const EffectEvent& event : fx.Events())
            {
                if (event.type == EffectEventType::impact)
                {
                    approach = event.approachSpeed;
                    sparksAfterLanding = scene.Spawned("sparks");
                }
            }
        }
        return std::tuple{approach, scene.Spawned("sparks"), scene.Spawned("dirt"), sparksAfterLanding};
    };
    const auto [approach, sparks, dirt, sparksAtLanding] = drop("dirt");
    ASSERT_GT(approach, 6.0f) << "one hard landing";
    const auto burst = static_cast<std::uint64_t>(10.0f * (approach - 2.0f));
    EXPECT_EQ(dirt, burst) << "the burst is of the burst type";
    EXPECT_GT(sparks, sparksAtLanding) << "the slide after it scrapes the rule's own type";
    // Empty: the rule's own type, as before.
    const auto [sameApproach, ownSparks, ownDirt, ownAtLanding] = drop("");
    EXPECT_EQ(sameApproach, approach);
    EXPECT_EQ(ownDirt, 0u);
    EXPECT_EQ(ownSparks, sparks + burst);
    (void)ownAtLanding;
}

TEST(Emission, ALandingsPressureSpikeIsNotCutByTheCapAtAnyStepRate)
{
    // 1,000 a second saves 33 particles, more than this landing's spike asks (about 30).
    for (const float hz : {30.0f, 60.0f, 120.0f, 240.0f})
    {
        const std::uint64_t uncapped = LandSlidingBox(hz, 1.0e5f);
        ASSERT_GT(uncapped, 30u);
        EXPECT_EQ(LandSlidingBox(hz, 1000.0f), uncapped) << hz << " Hz";
    }
}

// A pair that starts above its cap gets its savings once, then maxRate: the same count at any step rate. A
// re-check found the count growing with the step rate (a box sliding half a second and resting half a
// second, 8 times: 3,200, 3,306, 3,360 and 3,386 sparks at 30 to 240 Hz under a cap of 800).
TEST(Emission, APairStartingAboveItsCapEmitsTheSameAtEveryStepRate)
{
    for (const float maxRate : {100.0f, 800.0f})
    {
        std::vector<double> counts;
        for (const float hz : {30.0f, 60.0f, 120.0f, 240.0f})
        {
            TestWorld scene;
            b2Body* ground = scene.CreateGround();
            b2Body* box = scene.CreateBox(b2Vec2(-10.0f, 0.5f), 0.5f, 0.5f, 0.5f);
            EffectsConfig config = DefaultPreset();
            config.budget.capacity = 100000;
            config.rules[0].maxRate = maxRate;
            config.rules[0].ratePerIntensity = 1000.0f; // far above either cap at 10 m/s
            config.rules[0].burstPerSpeed = 0.0f;
            Effects& fx = scene.Attach(std::move(config));
            fx.SetMaterial(ground, fx.FindMaterial("concrete"));
            fx.SetMaterial(box, fx.FindMaterial("steel"));
            const int half = static_cast<int>(std::lround(0.5f * hz));
            for (int step = 0; step < 8 * 2 * half; ++step)
            {
                scene.world->Step(1.0f / hz, 8, 3);
                const float speed = (step / half) % 2 == 0 ? 10.0f : 0.0f;
                box->SetLinearVelocity(b2Vec2(speed, box->GetLinearVelocity().y));
                box->SetAngularVelocity(0.0f);
                fx.Step(1.0f / hz);
            }
            counts.push_back(static_cast<double>(scene.Spawned("sparks")));
        }
        // 8 half seconds at maxRate, and the savings once per start.
        const double expected = maxRate * (4.0 + 8.0 * static_cast<double>(kMaxRateWindow));
        for (std::size_t k = 0; k < counts.size(); ++k)
        {
            EXPECT_NEAR(counts[k], expected, 0.01 * expected) << maxRate << " a second, rate " << k;
        }
    }
}

// Held above its cap, a pair emits maxRate particles a second, at every step rate, and at most the window's
// worth more than that over the run. A re-check found the first token bucket losing the allowance's
// fraction every step at 30 Hz (780 a second for 800) and emitting nothing under a cap of 30 a second.
TEST(Emission, APairHeldAboveItsCapEmitsMaxRate)
{
    for (const float maxRate : {10.0f, 45.0f, 300.0f})
    {
        for (const float hz : {20.0f, 30.0f, 60.0f, 120.0f, 240.0f})
        {
            EffectsConfig config = DefaultPreset();
            config.budget.capacity = 100000;
            config.rules[0].maxRate = maxRate; // steel on concrete; 14 m/s asks for about 900 a second
            config.rules[0].burstPerSpeed = 0.0f;
            const double count = static_cast<double>(SlideBox(std::move(config), 14.0f, hz, 4.0f));
            const double window = std::max(static_cast<double>(kMaxRateWindow), 1.0 / hz);
            EXPECT_GE(count, maxRate * 4.0 - 1.0) << maxRate << " a second at " << hz << " Hz";
            EXPECT_LE(count, maxRate * (4.0 + window) + 1.0) << maxRate << " a second at " << hz << " Hz";
        }
    }
}

// Below its cap a pair emits what it asks for, exactly as without a cap (the re-check: 30 a second where 40
// were asked, under a cap of 45, at 30 Hz).
TEST(Emission, APairBelowItsCapEmitsAsWithoutOne)
{
    for (const float hz : {20.0f, 30.0f, 60.0f, 240.0f})
    {
        EffectsConfig uncapped = DefaultPreset();
        uncapped.rules[0].maxRate = 1.0e5f;
        uncapped.rules[0].burstPerSpeed = 0.0f;
        const std::uint64_t asked = SlideBox(uncapped, 4.0f, hz, 4.0f);
        ASSERT_GT(asked, 40u);
        for (const float above : {1.05f, 1.1f, 1.5f})
        {
            EffectsConfig capped = uncapped;
            capped.rules[0].maxRate = above * static_cast<float>(asked) / 4.0f;
            EXPECT_EQ(SlideBox(capped, 4.0f, hz, 4.0f), asked) << hz << " Hz, cap " << above << " x the rate";
        }
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
