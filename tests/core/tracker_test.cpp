#include "contact_tracker.h"
#include "effects_access.h"
#include "fixture_materials.h"
#include "test_world.h"

#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

// A steel box resting on concrete ground.
struct BoxOnGround : TestWorld
{
    BoxOnGround()
    {
        ground = CreateGround();
        box = CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    }
    void Assign()
    {
        effects->SetMaterial(ground, Material("concrete"));
        effects->SetMaterial(box, Material("steel"));
    }
    std::size_t Tracked(int rule = 0) const
    {
        return detail::EffectsAccess::Tracker(*effects)
            .Contacts(RuleId{static_cast<std::uint16_t>(rule)})
            .size();
    }

    b2Body* ground = nullptr;
    b2Body* box = nullptr;
};

// The tracker alone, without Effects: the test plays Effects::Step's part (Prune ... EndStep).
struct RawTracker : TestWorld
{
    RawTracker()
        : config(OneRule("steel", "concrete")), rules(BuildRuleTable(config)), tracker(rules, materials)
    {
        world->SetContactListener(&tracker);
        ground = CreateGround();
        box = CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        materials.Set(Steel(), config.FindMaterial("steel"));
        materials.Set(Concrete(), config.FindMaterial("concrete"));
    }
    ~RawTracker() { world->SetContactListener(nullptr); }

    b2Fixture* Steel() const { return box->GetFixtureList(); }
    b2Fixture* Concrete() const { return ground->GetFixtureList(); }
    void WorldStep()
    {
        world->Step(1.0f / 60.0f, 8, 3);
        tracker.Prune();
    }
    void Lift()
    {
        box->SetTransform(b2Vec2(0.0f, 5.0f), 0.0f);
        box->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
        WorldStep();
        WorldStep();
    }
    void Land()
    {
        box->SetTransform(b2Vec2(0.0f, 0.5f), 0.0f);
        WorldStep();
    }

    EffectsConfig config;
    RuleTable rules;
    FixtureMaterials materials;
    ContactTracker tracker;
    b2Body* ground = nullptr;
    b2Body* box = nullptr;
};

// A box on the ground with a contact listener set on the world before Effects is attached.
void AttachAfterAWorldListener(BoxOnGround& scene, b2ContactListener& listener)
{
    scene.world->SetContactListener(&listener);
    scene.Attach();
    scene.Assign();
}

} // namespace

TEST(ContactTracker, EndedPairsListsOnlyPairsAStepHasSeen)
{
    RawTracker scene;
    scene.Land();
    ASSERT_EQ(scene.tracker.PairCount(), 1u);
    scene.Lift(); // touched and parted between two steps: no step saw the pair
    EXPECT_EQ(scene.tracker.PairCount(), 0u);
    EXPECT_TRUE(scene.tracker.EndedPairs().empty());

    scene.Land();
    const std::uint32_t slot = scene.tracker.Contacts(RuleId{0})[0].pair;
    scene.tracker.EndStep(); // a step saw it
    scene.Lift();
    ASSERT_EQ(scene.tracker.EndedPairs().size(), 1u);
    const EndedPair& ended = scene.tracker.EndedPairs()[0];
    EXPECT_EQ(ended.slot, slot);
    EXPECT_EQ(ended.reason, ScrapeEnd::contactEnded);
    EXPECT_EQ(ended.fixtureA, scene.Steel()) << "the rule's order: steel is its materialA";
    EXPECT_EQ(ended.fixtureB, scene.Concrete());
    EXPECT_EQ(ended.materialA, scene.config.FindMaterial("steel"));
    EXPECT_EQ(ended.materialB, scene.config.FindMaterial("concrete"));
    scene.tracker.EndStep();
    EXPECT_TRUE(scene.tracker.EndedPairs().empty());
}

TEST(ContactTracker, ForgottenFixtureEndsItsPairAsDestroyed)
{
    RawTracker scene;
    scene.Land();
    scene.tracker.EndStep();
    scene.tracker.ForgetFixture(scene.Steel());
    ASSERT_EQ(scene.tracker.EndedPairs().size(), 1u);
    EXPECT_EQ(scene.tracker.EndedPairs()[0].reason, ScrapeEnd::destroyed);
}

TEST(ContactTracker, DestroyedBodyMarksItsEndedPair)
{
    RawTracker scene;
    scene.Land();
    scene.tracker.EndStep();
    const b2Fixture* steel = scene.Steel();
    scene.world->DestroyBody(scene.box); // EndContact: the pair waits to end until the step reads it
    EXPECT_TRUE(scene.tracker.EndedPairs().empty());
    scene.tracker.MarkDestroyed(steel); // what Effects' destruction listener does next
    scene.tracker.Prune();
    ASSERT_EQ(scene.tracker.EndedPairs().size(), 1u);
    EXPECT_EQ(scene.tracker.EndedPairs()[0].reason, ScrapeEnd::destroyed);
}

TEST(ContactTracker, NewTouchLastsUntilEndStep)
{
    RawTracker scene;
    scene.box->SetTransform(b2Vec2(0.0f, 0.6f), 0.0f);
    scene.box->SetLinearVelocity(b2Vec2(0.0f, -3.0f));
    for (int i = 0; i < 30 && scene.tracker.TrackedCount() == 0; ++i)
    {
        scene.WorldStep();
        if (scene.tracker.TrackedCount() == 0)
        {
            scene.tracker.EndStep();
        }
    }
    ASSERT_EQ(scene.tracker.TrackedCount(), 1u);
    const TrackedContact& tracked = scene.tracker.Contacts(RuleId{0})[0];
    EXPECT_TRUE(tracked.newTouch);
    EXPECT_GT(tracked.approachSpeed, 2.0f) << "falling at 3 m/s when it touched, before the solver";
    scene.tracker.EndStep();
    EXPECT_FALSE(tracked.newTouch);
    scene.WorldStep();
    EXPECT_FALSE(scene.tracker.Contacts(RuleId{0})[0].newTouch) << "still touching is no new touch";
}

TEST(ContactTracker, TracksTouchingContactsOfARule)
{
    BoxOnGround scene;
    scene.Attach();
    scene.Assign();
    scene.Step();
    EXPECT_EQ(scene.Tracked(0), 1u);
    scene.box->SetTransform(b2Vec2(0.0f, 5.0f), 0.0f);
    scene.Step();
    scene.Step();
    EXPECT_EQ(scene.Tracked(0), 0u);
}

TEST(ContactTracker, FixtureWithoutMaterialIsNotTracked)
{
    BoxOnGround scene;
    scene.Attach();
    scene.effects->SetMaterial(scene.ground, scene.Material("concrete"));
    scene.Step();
    EXPECT_EQ(detail::EffectsAccess::Tracker(*scene.effects).TrackedCount(), 0u);
}

TEST(ContactTracker, DestroyedBodyLeavesNoTrackedContact)
{
    BoxOnGround scene;
    scene.Attach();
    scene.Assign();
    scene.Step();
    ASSERT_EQ(scene.Tracked(0), 1u);
    scene.world->DestroyBody(scene.box);
    EXPECT_EQ(detail::EffectsAccess::Tracker(*scene.effects).TrackedCount(), 0u);
    scene.Step(); // must not touch the destroyed contact
    EXPECT_EQ(scene.Tracked(0), 0u);
}

TEST(ContactTracker, DestroyedFixtureLeavesNoTrackedContactOrMaterial)
{
    BoxOnGround scene;
    scene.Attach();
    scene.Assign();
    scene.Step();
    b2Fixture* fixture = scene.box->GetFixtureList();
    scene.effects->ForgetFixture(fixture);
    scene.box->DestroyFixture(fixture);
    EXPECT_EQ(detail::EffectsAccess::Tracker(*scene.effects).TrackedCount(), 0u);
    EXPECT_FALSE(scene.effects->Material(fixture).IsValid());
    scene.Step();
}

TEST(ContactTracker, BodyDestructionForgetsTheFixturesMaterials)
{
    BoxOnGround scene;
    scene.Attach();
    scene.Assign();
    const b2Fixture* fixture = scene.box->GetFixtureList();
    ASSERT_TRUE(scene.effects->Material(fixture).IsValid());
    scene.world->DestroyBody(scene.box);
    EXPECT_FALSE(scene.effects->Material(fixture).IsValid());
}

TEST(ContactTracker, SensorLeavesTrackingAndSolidComesBack)
{
    BoxOnGround scene;
    scene.Attach();
    scene.Assign();
    scene.Step();
    ASSERT_EQ(scene.Tracked(0), 1u);
    scene.box->GetFixtureList()->SetSensor(true);
    scene.Step();
    EXPECT_EQ(scene.Tracked(0), 0u);
    scene.box->SetGravityScale(0.0f);
    scene.box->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
    scene.box->GetFixtureList()->SetSensor(false);
    scene.Step();
    EXPECT_EQ(scene.Tracked(0), 1u);
}

TEST(ContactTracker, FilterChangeEndsTracking)
{
    BoxOnGround scene;
    scene.Attach();
    scene.Assign();
    scene.Step();
    ASSERT_EQ(scene.Tracked(0), 1u);
    b2Filter filter;
    filter.maskBits = 0;
    scene.box->GetFixtureList()->SetFilterData(filter);
    scene.Step();
    EXPECT_EQ(scene.Tracked(0), 0u);
}

TEST(ContactTracker, ApplicationListenerReceivesEveryCallback)
{
    // The same scene with and without contactfx in between gives the same callback sequence.
    auto run = [](bool withEffects)
    {
        RecordingListener recorder;
        BoxOnGround scene;
        scene.box->SetLinearVelocity(b2Vec2(3.0f, -2.0f));
        if (withEffects)
        {
            scene.Attach(DefaultPreset(), 1, &recorder);
            scene.Assign();
        }
        else
        {
            scene.world->SetContactListener(&recorder);
        }
        for (int i = 0; i < 60; ++i)
        {
            scene.Step();
        }
        scene.world->DestroyBody(scene.box);
        scene.effects.reset();
        return recorder.calls;
    };
    std::vector<std::string> direct = run(false);
    std::vector<std::string> forwarded = run(true);
    ASSERT_GT(direct.size(), 50u);
    EXPECT_EQ(direct.front(), "begin");
    EXPECT_EQ(direct.back(), "end");
    EXPECT_EQ(forwarded, direct);
}

TEST(ContactTracker, RecordsPostSolveImpulses)
{
    BoxOnGround scene;
    scene.Attach();
    scene.Assign();
    for (int i = 0; i < 30; ++i)
    {
        scene.world->Step(1.0f / 60.0f, 8, 3);
        if (i < 29)
        {
            scene.effects->Step(1.0f / 60.0f);
        }
    }
    const TrackedContact& tracked = detail::EffectsAccess::Tracker(*scene.effects).Contacts(RuleId{0})[0];
    // A resting 1 kg box: the two points share its weight, 10 N * (1/60) s per step.
    EXPECT_NEAR(tracked.normalImpulse[0] + tracked.normalImpulse[1], 10.0f / 60.0f, 0.02f);
}

TEST(ContactTracker, EffectsRestoresTheApplicationListeners)
{
    RecordingListener recorder;
    TestWorld scene;
    scene.world->SetContactListener(&recorder);
    scene.Attach(DefaultPreset(), 1, &recorder);
    scene.effects.reset();
    scene.CreateGround();
    scene.CreateBox(b2Vec2(0.0f, 0.49f), 0.5f, 0.5f, 0.5f);
    scene.Step();
    EXPECT_FALSE(recorder.calls.empty());
}

// A listener the application set on the world before Effects was created was dropped: it is forwarded to,
// and put back when Effects goes. A world without one gets Box2D's own back.
TEST(ContactTracker, AListenerSetOnTheWorldBeforeEffectsIsKeptAndPutBack)
{
    const b2ContactListener* boxDefault = b2World(b2Vec2(0.0f, 0.0f)).GetContactManager().m_contactListener;
    RecordingListener recorder;
    {
        BoxOnGround scene;
        AttachAfterAWorldListener(scene, recorder);
        for (int i = 0; i < 10; ++i)
        {
            scene.Step();
        }
        EXPECT_EQ(scene.Tracked(), 1u);
        ASSERT_FALSE(recorder.calls.empty());
        EXPECT_EQ(recorder.calls.front(), "begin");
        scene.effects.reset();
        EXPECT_EQ(scene.world->GetContactManager().m_contactListener, &recorder);
        scene.world->SetContactListener(nullptr);
    }
    BoxOnGround plain;
    plain.Attach();
    plain.Step();
    plain.effects.reset();
    EXPECT_EQ(plain.world->GetContactManager().m_contactListener, boxDefault);
}

// SetContactListener(nullptr) removes the application's listener for good: a trial set one on the world,
// created Effects, removed it through Effects and deleted it, and the destructor put the deleted listener
// back (the next world step crashed in Box2D). The destructor puts back what it forwards to at that time.
TEST(ContactTracker, ARemovedListenerIsNotPutBack)
{
    const b2ContactListener* boxDefault = b2World(b2Vec2(0.0f, 0.0f)).GetContactManager().m_contactListener;
    RecordingListener recorder;
    BoxOnGround scene;
    AttachAfterAWorldListener(scene, recorder);
    scene.Step();
    ASSERT_FALSE(recorder.calls.empty());
    scene.effects->SetContactListener(nullptr);
    recorder.calls.clear();
    scene.Step();
    EXPECT_TRUE(recorder.calls.empty()) << "removed";
    scene.effects.reset();
    EXPECT_EQ(scene.world->GetContactManager().m_contactListener, boxDefault);
}

} // namespace cfx::test
