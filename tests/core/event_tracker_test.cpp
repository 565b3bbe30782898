// The event tracker's decisions on their own (src/events.h): fed plain facts (ended pairs, new touches,
// pair measures) as the contact tracker and the emitter would, with no contact callback and no world
// step. The fixtures are real (so that materials can be recorded for them) but never touched by Box2D.
#include "events.h"
#include "test_world.h"

#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

using detail::LoudestPoint;
using detail::NewTouch;
using detail::PairMeasure;

constexpr float kDt = 0.25f; // s: sums of it are exact, so quiet times are compared without rounding

struct EventScene : TestWorld
{
    EventScene() : events(materials, 4)
    {
        rule.threshold = 1.0f;
        rule.scrapeEndDelay = 0.5f; // two quiet steps of kDt
        rule.impactThreshold = 2.0f;
        steel = CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f)->GetFixtureList();
        concrete = CreateGround()->GetFixtureList();
        otherSteel = CreateBox(b2Vec2(3.0f, 0.5f), 0.5f, 0.5f, 0.5f)->GetFixtureList();
        materials.Set(steel, kSteel);
        materials.Set(otherSteel, kSteel);
        materials.Set(concrete, kConcrete);
    }

    // Starts the next step with `ended` pairs; returns nothing, the events are read after the calls.
    void Begin(std::span<const EndedPair> ended = {}) { events.BeginStep(step++, kDt, ended); }

    LoudestPoint Loudest(b2Vec2 point, const b2Fixture* fixtureA = nullptr) const
    {
        LoudestPoint loudest;
        loudest.fixtureA = fixtureA != nullptr ? fixtureA : steel;
        loudest.fixtureB = concrete;
        loudest.point = point;
        loudest.normal = b2Vec2(0.0f, -1.0f);
        loudest.tangentialSpeed = 3.0f;
        return loudest;
    }

    void Measure(std::uint32_t slot, float intensity, const LoudestPoint* loudest)
    {
        PairMeasure measure;
        measure.rule = kRule;
        measure.intensity = intensity;
        measure.normalImpulse = 0.5f;
        measure.loudest = loudest;
        events.Scrape(rule, slot, measure);
    }

    // One step in which the pair in `slot` rubs at `intensity` with its loudest point at `point`.
    std::vector<EffectEvent> Rub(std::uint32_t slot, float intensity, b2Vec2 point)
    {
        Begin();
        const LoudestPoint loudest = Loudest(point);
        Measure(slot, intensity, &loudest);
        return {events.Events().begin(), events.Events().end()};
    }

    NewTouch Touch(float approachSpeed) const
    {
        NewTouch touch;
        touch.rule = kRule;
        touch.fixtureA = steel;
        touch.fixtureB = concrete;
        touch.point = b2Vec2(1.0f, 0.0f);
        touch.normal = b2Vec2(0.0f, -1.0f);
        touch.approachSpeed = approachSpeed;
        return touch;
    }

    static constexpr MaterialId kSteel{0};
    static constexpr MaterialId kConcrete{1};
    static constexpr RuleId kRule{2};

    FixtureMaterials materials;
    detail::EventTracker events;
    RuleDef rule;
    std::uint64_t step = 0;
    const b2Fixture* steel = nullptr;
    const b2Fixture* concrete = nullptr;
    const b2Fixture* otherSteel = nullptr;
};

} // namespace

TEST(EventTracker, ScrapeBeginsChangesAndEndsAfterTheQuietDelay)
{
    EventScene scene;
    const std::vector<EffectEvent> began = scene.Rub(0, 3.0f, b2Vec2(1.0f, 0.0f));
    ASSERT_EQ(began.size(), 1u);
    EXPECT_EQ(began[0].type, EffectEventType::scrapeBegan);
    EXPECT_NE(began[0].id, 0u);
    EXPECT_EQ(began[0].rule, EventScene::kRule);
    EXPECT_EQ(began[0].fixtureA, scene.steel);
    EXPECT_EQ(began[0].fixtureB, scene.concrete);
    EXPECT_EQ(began[0].materialA, EventScene::kSteel);
    EXPECT_EQ(began[0].materialB, EventScene::kConcrete);
    EXPECT_EQ(began[0].step, 0u);
    EXPECT_EQ(began[0].point.x, 1.0f);
    EXPECT_EQ(began[0].intensity, 3.0f);
    EXPECT_EQ(began[0].tangentialSpeed, 3.0f);
    EXPECT_EQ(began[0].normalImpulse, 0.5f);
    EXPECT_EQ(scene.events.ScrapeId(0), began[0].id);

    const std::vector<EffectEvent> changed = scene.Rub(0, 2.0f, b2Vec2(2.0f, 0.0f));
    ASSERT_EQ(changed.size(), 1u);
    EXPECT_EQ(changed[0].type, EffectEventType::scrapeChanged);
    EXPECT_EQ(changed[0].id, began[0].id);
    EXPECT_EQ(changed[0].point.x, 2.0f);
    EXPECT_EQ(changed[0].step, 1u);

    // At the threshold is quiet: one quiet step (0.25 s < 0.5 s) still changes, with the low intensity.
    const std::vector<EffectEvent> quiet = scene.Rub(0, scene.rule.threshold, b2Vec2(3.0f, 0.0f));
    ASSERT_EQ(quiet.size(), 1u);
    EXPECT_EQ(quiet[0].type, EffectEventType::scrapeChanged);
    EXPECT_EQ(quiet[0].intensity, scene.rule.threshold);

    // The second quiet step reaches the delay: ended, where it was last reported.
    const std::vector<EffectEvent> ended = scene.Rub(0, 0.0f, b2Vec2(4.0f, 0.0f));
    ASSERT_EQ(ended.size(), 1u);
    EXPECT_EQ(ended[0].type, EffectEventType::scrapeEnded);
    EXPECT_EQ(ended[0].end, ScrapeEnd::belowThreshold);
    EXPECT_EQ(ended[0].id, began[0].id);
    EXPECT_EQ(ended[0].point.x, 3.0f);
    EXPECT_EQ(ended[0].fixtureA, scene.steel);
    EXPECT_EQ(ended[0].intensity, 0.0f);
    EXPECT_EQ(scene.events.ScrapeId(0), 0u);

    // Quiet without a scrape: nothing.
    EXPECT_TRUE(scene.Rub(0, 0.5f, b2Vec2(5.0f, 0.0f)).empty());
}

TEST(EventTracker, LoudAgainDuringTheDelayKeepsTheScrape)
{
    EventScene scene;
    const std::uint32_t id = scene.Rub(0, 3.0f, b2Vec2(1.0f, 0.0f))[0].id;
    scene.Rub(0, 0.0f, b2Vec2(1.0f, 0.0f)); // quiet 0.25 s
    scene.Rub(0, 3.0f, b2Vec2(1.0f, 0.0f)); // loud: the quiet time starts again
    const std::vector<EffectEvent> quietAgain = scene.Rub(0, 0.0f, b2Vec2(1.0f, 0.0f));
    ASSERT_EQ(quietAgain.size(), 1u);
    EXPECT_EQ(quietAgain[0].type, EffectEventType::scrapeChanged) << "0.25 s quiet, not 0.5 s";
    EXPECT_EQ(quietAgain[0].id, id);
}

TEST(EventTracker, SilentPairReportsThePointLastHeard)
{
    EventScene scene;
    scene.Rub(0, 3.0f, b2Vec2(1.0f, 0.0f));
    scene.Begin();
    scene.Measure(0, 0.0f, nullptr); // no sampled point this step
    ASSERT_EQ(scene.events.Events().size(), 1u);
    const EffectEvent& changed = scene.events.Events()[0];
    EXPECT_EQ(changed.type, EffectEventType::scrapeChanged);
    EXPECT_EQ(changed.point.x, 1.0f);
    EXPECT_EQ(changed.fixtureA, scene.steel);
    EXPECT_EQ(changed.tangentialSpeed, 0.0f);
}

TEST(EventTracker, ImpactAtOrAboveItsThresholdWithAnIdFromTheSameCounter)
{
    EventScene scene;
    scene.Begin();
    const float below = scene.rule.impactThreshold * 0.5f;
    EXPECT_FALSE(scene.events.Impact(scene.rule, scene.Touch(below), 1.0f));
    EXPECT_TRUE(scene.events.Events().empty());

    EXPECT_TRUE(scene.events.Impact(scene.rule, scene.Touch(scene.rule.impactThreshold), 1.5f));
    const LoudestPoint loudest = scene.Loudest(b2Vec2(1.0f, 0.0f));
    scene.Measure(0, 3.0f, &loudest);
    ASSERT_EQ(scene.events.Events().size(), 2u);
    const EffectEvent& impact = scene.events.Events()[0];
    EXPECT_EQ(impact.type, EffectEventType::impact);
    EXPECT_EQ(impact.rule, EventScene::kRule);
    EXPECT_EQ(impact.fixtureA, scene.steel);
    EXPECT_EQ(impact.materialB, EventScene::kConcrete);
    EXPECT_EQ(impact.approachSpeed, scene.rule.impactThreshold);
    EXPECT_EQ(impact.normalImpulse, 1.5f);
    EXPECT_EQ(impact.normal.y, -1.0f);
    EXPECT_EQ(impact.intensity, 0.0f);
    const EffectEvent& began = scene.events.Events()[1];
    EXPECT_EQ(began.type, EffectEventType::scrapeBegan);
    EXPECT_NE(impact.id, 0u);
    EXPECT_GT(began.id, impact.id) << "one counter for impacts and scrapes, in the order they were made";
}

TEST(EventTracker, AsleepEndsAScrapeGoingOn)
{
    EventScene scene;
    const std::uint32_t id = scene.Rub(1, 3.0f, b2Vec2(1.0f, 0.0f))[0].id;
    scene.Begin();
    scene.events.Asleep(1);
    ASSERT_EQ(scene.events.Events().size(), 1u);
    EXPECT_EQ(scene.events.Events()[0].type, EffectEventType::scrapeEnded);
    EXPECT_EQ(scene.events.Events()[0].end, ScrapeEnd::asleep);
    EXPECT_EQ(scene.events.Events()[0].id, id);
    scene.Begin();
    scene.events.Asleep(1); // no scrape now
    scene.events.Asleep(3); // a slot never reported
    EXPECT_TRUE(scene.events.Events().empty());
}

TEST(EventTracker, EndedPairsEndTheirScrapesFirstInTheirOrder)
{
    EventScene scene;
    scene.Begin();
    const LoudestPoint first = scene.Loudest(b2Vec2(1.0f, 0.0f));
    const LoudestPoint second = scene.Loudest(b2Vec2(2.0f, 0.0f), scene.otherSteel);
    scene.Measure(0, 3.0f, &first);
    scene.Measure(1, 3.0f, &second);
    const std::uint32_t id0 = scene.events.ScrapeId(0);
    const std::uint32_t id1 = scene.events.ScrapeId(1);
    ASSERT_NE(id0, 0u);
    ASSERT_NE(id1, id0);

    // Slot 1 ended first (its fixture destroyed), then slot 0; slot 2 never had a scrape. The ended
    // pairs' own fixtures and materials are reported (those of the last contact, recorded as it left).
    EndedPair destroyed;
    destroyed.slot = 1;
    destroyed.reason = ScrapeEnd::destroyed;
    destroyed.fixtureA = scene.otherSteel;
    destroyed.fixtureB = scene.concrete;
    destroyed.materialA = MaterialId{7};
    EndedPair separated;
    separated.slot = 0;
    separated.fixtureA = scene.otherSteel;
    separated.fixtureB = scene.concrete;
    EndedPair silent;
    silent.slot = 2;
    const EndedPair ended[] = {destroyed, separated, silent};
    scene.Begin(ended);
    const LoudestPoint later = scene.Loudest(b2Vec2(5.0f, 0.0f));
    scene.Measure(3, 3.0f, &later); // another pair in the same step: after the ended ones

    const std::span<const EffectEvent> events = scene.events.Events();
    ASSERT_EQ(events.size(), 3u);
    EXPECT_EQ(events[0].type, EffectEventType::scrapeEnded);
    EXPECT_EQ(events[0].id, id1);
    EXPECT_EQ(events[0].end, ScrapeEnd::destroyed);
    EXPECT_EQ(events[0].materialA, MaterialId{7});
    EXPECT_EQ(events[0].point.x, 2.0f);
    EXPECT_EQ(events[1].id, id0);
    EXPECT_EQ(events[1].end, ScrapeEnd::contactEnded);
    EXPECT_EQ(events[1].fixtureA, scene.otherSteel) << "the last contact's fixture, not the last reported";
    EXPECT_EQ(events[1].point.x, 1.0f);
    EXPECT_EQ(events[2].type, EffectEventType::scrapeBegan);
    EXPECT_GT(events[2].id, id1);
}

TEST(EventTracker, ASlotTakenByANewPairStartsClean)
{
    EventScene scene;
    const std::uint32_t old = scene.Rub(0, 3.0f, b2Vec2(1.0f, 0.0f))[0].id;
    EndedPair ended;
    ended.slot = 0;
    scene.Begin(std::span<const EndedPair>(&ended, 1));
    // The new pair in slot 0 is silent at first: it has no scrape to change, so the only event is the
    // old scrape's end.
    scene.Measure(0, 0.0f, nullptr);
    ASSERT_EQ(scene.events.Events().size(), 1u);
    EXPECT_EQ(scene.events.Events()[0].type, EffectEventType::scrapeEnded);
    EXPECT_EQ(scene.events.Events()[0].id, old);
    EXPECT_EQ(scene.events.ScrapeId(0), 0u);

    // When it rubs it begins a scrape of its own.
    const std::vector<EffectEvent> began = scene.Rub(0, 3.0f, b2Vec2(9.0f, 0.0f));
    ASSERT_EQ(began.size(), 1u);
    EXPECT_EQ(began[0].type, EffectEventType::scrapeBegan);
    EXPECT_GT(began[0].id, old);
}

TEST(EventTracker, EachStepStartsAnEmptyList)
{
    EventScene scene;
    scene.Rub(0, 3.0f, b2Vec2(1.0f, 0.0f));
    ASSERT_EQ(scene.events.Events().size(), 1u);
    scene.Begin();
    EXPECT_TRUE(scene.events.Events().empty());
}

} // namespace cfx::test
