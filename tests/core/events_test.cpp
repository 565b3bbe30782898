#include "test_world.h"

#include <cmath>
#include <gtest/gtest.h>
#include <map>
#include <thread>
#include <utility>

namespace cfx::test
{

namespace
{

// Collects events through the listener, to check it sees what Events() says.
class EventLog final : public EffectEventListener
{
public:
    void OnEffectEvent(const EffectEvent& event) override { events.push_back(event); }
    std::vector<EffectEvent> events;
};

// A steel box on concrete; the test moves it and collects every event.
struct ScrapeScene : TestWorld
{
    explicit ScrapeScene(EffectsConfig config = DefaultPreset())
    {
        ground = CreateGround();
        box = CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        EffectsDef def;
        def.config = std::move(config);
        def.config.budget.particleHits = 0; // contact events only: no sparks landing among them
        def.eventListener = &log;
        effects = std::make_unique<Effects>(*world, def);
        effects->SetMaterial(ground, Material("concrete"));
        effects->SetMaterial(box, Material("steel"));
    }

    // Steps with the box held at `speed` along x; returns the events of all those steps.
    std::vector<EffectEvent> Slide(float speed, int steps)
    {
        std::vector<EffectEvent> out;
        for (int i = 0; i < steps; ++i)
        {
            world->Step(1.0f / 60.0f, 8, 3);
            box->SetLinearVelocity(b2Vec2(speed, box->GetLinearVelocity().y));
            box->SetAngularVelocity(0.0f);
            effects->Step(1.0f / 60.0f);
            out.insert(out.end(), effects->Events().begin(), effects->Events().end());
        }
        return out;
    }

    std::vector<EffectEvent> StepPlain(int steps)
    {
        std::vector<EffectEvent> out;
        for (int i = 0; i < steps; ++i)
        {
            Step();
            out.insert(out.end(), effects->Events().begin(), effects->Events().end());
        }
        return out;
    }

    EventLog log;
    b2Body* ground = nullptr;
    b2Body* box = nullptr;
};

std::vector<EffectEvent> OfType(const std::vector<EffectEvent>& events, EffectEventType type)
{
    std::vector<EffectEvent> out;
    for (const EffectEvent& event : events)
    {
        if (event.type == type)
        {
            out.push_back(event);
        }
    }
    return out;
}

} // namespace

// A box dropped at 6 m/s from 5 cm: at 30 and 60 Hz continuous collision finds the touch, after the solver
// has added the step's gravity, and the approach speed says so (docs/events.md, Impacts).
TEST(Events, ATouchFoundByContinuousCollisionIncludesTheStepsGravity)
{
    for (const float hz : {30.0f, 60.0f})
    {
        TestWorld scene;
        b2Body* ground = scene.CreateGround(0.8f);
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.3f), 0.5f, 0.25f, 0.5f);
        box->SetLinearVelocity(b2Vec2(0.0f, -6.0f));
        Effects& fx = scene.Attach();
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(box, fx.FindMaterial("steel"));
        const float dt = 1.0f / hz;
        std::vector<float> speeds;
        for (int i = 0; i < 10; ++i)
        {
            scene.world->Step(dt, 8, 3);
            fx.Step(dt);
            for (const EffectEvent& event : fx.Events())
            {
                if (event.type == EffectEventType::impact)
                {
                    speeds.push_back(event.approachSpeed);
                }
            }
        }
        ASSERT_EQ(speeds.size(), 1u) << hz << " Hz";
        EXPECT_NEAR(speeds[0], 6.0f + 10.0f * dt, 1.0e-3f) << hz << " Hz";
    }
}

TEST(Events, ScrapeBeginsChangesAndEndsBelowThreshold)
{
    ScrapeScene scene;
    std::vector<EffectEvent> events = scene.StepPlain(30); // settle: no scrape while resting
    EXPECT_TRUE(OfType(events, EffectEventType::scrapeBegan).empty());

    events = scene.Slide(4.0f, 30);
    std::vector<EffectEvent> began = OfType(events, EffectEventType::scrapeBegan);
    ASSERT_EQ(began.size(), 1u);
    const EffectEvent first = began[0]; // a copy: `began` is reassigned below
    EXPECT_EQ(first.rule, RuleId{0});
    EXPECT_EQ(first.materialA, scene.Material("steel"));
    EXPECT_EQ(first.materialB, scene.Material("concrete"));
    EXPECT_EQ(first.fixtureA, scene.box->GetFixtureList());
    EXPECT_EQ(first.fixtureB, scene.ground->GetFixtureList());
    EXPECT_GT(first.intensity, 1.0f);
    EXPECT_NEAR(first.tangentialSpeed, 4.0f, 0.01f);
    EXPECT_GT(first.normalImpulse, 0.0f);
    EXPECT_NEAR(first.point.y, 0.0f, 0.02f);
    EXPECT_NEAR(first.normal.y, -1.0f, 1e-4f) << "from the steel box toward the concrete";
    std::vector<EffectEvent> changed = OfType(events, EffectEventType::scrapeChanged);
    EXPECT_EQ(changed.size(), 29u);
    for (const EffectEvent& event : changed)
    {
        EXPECT_EQ(event.id, first.id);
    }

    // Stopped: the scrape lingers for scrapeEndDelay (0.1 s = 6 steps), then ends.
    events = scene.Slide(0.0f, 12);
    std::vector<EffectEvent> ended = OfType(events, EffectEventType::scrapeEnded);
    ASSERT_EQ(ended.size(), 1u);
    EXPECT_EQ(ended[0].id, first.id);
    EXPECT_EQ(ended[0].end, ScrapeEnd::belowThreshold);
    EXPECT_EQ(OfType(events, EffectEventType::scrapeChanged).size(), 5u);

    // A new scrape gets a new id.
    events = scene.Slide(4.0f, 5);
    began = OfType(events, EffectEventType::scrapeBegan);
    ASSERT_EQ(began.size(), 1u);
    EXPECT_NE(began[0].id, first.id);
}

TEST(Events, EndDelayIsPerRule)
{
    EffectsConfig config = DefaultPreset();
    config.rules[0].scrapeEndDelay = 0.5f;
    ScrapeScene scene(config);
    scene.StepPlain(30);
    scene.Slide(4.0f, 10);
    std::vector<EffectEvent> events = scene.Slide(0.0f, 20);
    EXPECT_TRUE(OfType(events, EffectEventType::scrapeEnded).empty());
    events = scene.Slide(0.0f, 12);
    EXPECT_EQ(OfType(events, EffectEventType::scrapeEnded).size(), 1u);
}

TEST(Events, ScrapeEndsWhenTheContactEnds)
{
    ScrapeScene scene;
    scene.StepPlain(30);
    scene.Slide(4.0f, 10);
    scene.box->SetTransform(b2Vec2(0.0f, 3.0f), 0.0f);
    std::vector<EffectEvent> events = scene.Slide(4.0f, 2);
    std::vector<EffectEvent> ended = OfType(events, EffectEventType::scrapeEnded);
    ASSERT_EQ(ended.size(), 1u);
    EXPECT_EQ(ended[0].end, ScrapeEnd::contactEnded);
    EXPECT_EQ(events.front().type, EffectEventType::scrapeEnded) << "ends from callbacks come first";
}

// An application that stops stepping ends its scrapes (Effects::EndScrapes): a scrapeEnded each, reason
// stopped, through Events() and the listener; a contact still scraping at the next Step begins anew.
TEST(Events, EndScrapesEndsEveryOpenScrapeOnceAndTheNextStepBeginsANewOne)
{
    ScrapeScene scene;
    scene.StepPlain(30);
    const std::vector<EffectEvent> sliding = scene.Slide(4.0f, 10);
    const std::vector<EffectEvent> began = OfType(sliding, EffectEventType::scrapeBegan);
    ASSERT_EQ(began.size(), 1u);
    const std::uint64_t lastStep = scene.effects->Stats().steps - 1;
    scene.log.events.clear();

    scene.effects->EndScrapes();
    const std::vector<EffectEvent> ended(scene.effects->Events().begin(), scene.effects->Events().end());
    ASSERT_EQ(ended.size(), 1u);
    EXPECT_EQ(ended[0].type, EffectEventType::scrapeEnded);
    EXPECT_EQ(ended[0].end, ScrapeEnd::stopped);
    EXPECT_EQ(ended[0].id, began[0].id);
    EXPECT_EQ(ended[0].step, lastStep);
    EXPECT_EQ(ended[0].materialA, began[0].materialA);
    EXPECT_EQ(ended[0].fixtureA, began[0].fixtureA);
    ASSERT_EQ(scene.log.events.size(), 1u) << "the listener gets them too";
    EXPECT_EQ(scene.log.events[0].id, began[0].id);

    scene.effects->EndScrapes(); // nothing open any more
    EXPECT_TRUE(scene.effects->Events().empty());

    const std::vector<EffectEvent> again = scene.Slide(4.0f, 1);
    const std::vector<EffectEvent> beganAgain = OfType(again, EffectEventType::scrapeBegan);
    ASSERT_EQ(beganAgain.size(), 1u);
    EXPECT_GT(beganAgain[0].id, began[0].id);
    EXPECT_TRUE(OfType(again, EffectEventType::scrapeEnded).empty());
}

// A trial's event listener ended the scrapes (EndScrapes) when it heard a scrapeChanged: it then heard a
// scrapeEnded twice and an event from beyond the end of Events(). Called from the listener, EndScrapes
// appends the scrape ends to the step's events, and the listener hears each event once, in that order.
TEST(Events, TheListenerMayEndTheScrapesAndHearsEachEventOnce)
{
    class Ending final : public EffectEventListener
    {
    public:
        void OnEffectEvent(const EffectEvent& event) override
        {
            heard.push_back(event);
            if (armed && event.type == EffectEventType::scrapeChanged)
            {
                armed = false;
                effects->EndScrapes();
            }
        }
        Effects* effects = nullptr;
        bool armed = false;
        std::vector<EffectEvent> heard;
    } ending;
    ScrapeScene scene;
    b2Body* second = scene.CreateBox(b2Vec2(4.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    scene.effects->SetMaterial(second, scene.Material("steel"));
    scene.StepPlain(30);
    ending.effects = scene.effects.get();
    scene.effects->SetEventListener(&ending);
    std::vector<EffectEvent> events;
    for (int i = 0; i < 12; ++i)
    {
        ending.armed = i == 10;
        ending.heard.clear();
        scene.world->Step(1.0f / 60.0f, 8, 3);
        for (b2Body* box : {scene.box, second})
        {
            box->SetLinearVelocity(b2Vec2(4.0f, box->GetLinearVelocity().y));
            box->SetAngularVelocity(0.0f);
        }
        scene.effects->Step(1.0f / 60.0f);
        events.assign(scene.effects->Events().begin(), scene.effects->Events().end());
        ASSERT_EQ(ending.heard.size(), events.size()) << "step " << i;
        for (std::size_t k = 0; k < events.size(); ++k)
        {
            EXPECT_EQ(ending.heard[k].type, events[k].type) << "step " << i << ", event " << k;
            EXPECT_EQ(ending.heard[k].id, events[k].id) << "step " << i << ", event " << k;
        }
        if (i == 10)
        {
            break;
        }
    }
    const std::vector<EffectEvent> ended = OfType(events, EffectEventType::scrapeEnded);
    ASSERT_EQ(ended.size(), 2u) << "both boxes' scrapes, once each";
    EXPECT_NE(ended[0].id, ended[1].id);
    EXPECT_EQ(ended[0].end, ScrapeEnd::stopped);
    EXPECT_EQ(ended[1].end, ScrapeEnd::stopped);
    EXPECT_EQ(events.back().type, EffectEventType::scrapeEnded) << "the ends follow the step's events";
    ASSERT_FALSE(OfType(events, EffectEventType::scrapeChanged).empty());
}

// A trial's listener ended the scrapes and then read the event it was handed: the ends appended to the
// step's events moved them (a budget of 0 contacts reserves no room), and the event it held was freed
// memory (type 23 in a release build, a use after free under AddressSanitizer).
TEST(Events, TheEventAListenerHoldsStaysValidWhenItEndsTheScrapes)
{
    class Ending final : public EffectEventListener
    {
    public:
        void OnEffectEvent(const EffectEvent& event) override
        {
            if (event.type != EffectEventType::scrapeChanged || effects == nullptr)
            {
                return;
            }
            const EffectEventType type = event.type;
            const std::uint32_t id = event.id;
            effects->EndScrapes();
            effects = nullptr;
            sameAfter = event.type == type && event.id == id;
            checked = true;
        }
        Effects* effects = nullptr;
        bool checked = false;
        bool sameAfter = false;
    } ending;
    EffectsConfig config = DefaultPreset();
    config.budget.contacts = 0;
    ScrapeScene scene(std::move(config));
    scene.Slide(4.0f, 10);
    ending.effects = scene.effects.get();
    scene.effects->SetEventListener(&ending);
    scene.Slide(4.0f, 3);
    ASSERT_TRUE(ending.checked);
    EXPECT_TRUE(ending.sameAfter);
}

// A trial's listener removed itself on the first event of a step with two: Effects::Step then called a
// null listener (a crash). The change takes effect from the next event.
TEST(Events, TheListenerMayReplaceOrRemoveItself)
{
    struct Counting final : public EffectEventListener
    {
        void OnEffectEvent(const EffectEvent&) override
        {
            ++heard;
            if (effects != nullptr)
            {
                effects->SetEventListener(next);
            }
        }
        Effects* effects = nullptr;
        EffectEventListener* next = nullptr;
        int heard = 0;
    };
    for (const bool replace : {false, true})
    {
        SCOPED_TRACE(replace ? "replaced" : "removed");
        ScrapeScene scene;
        b2Body* second = scene.CreateBox(b2Vec2(4.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        scene.effects->SetMaterial(second, scene.Material("steel"));
        Counting after;
        Counting first;
        first.effects = scene.effects.get();
        first.next = replace ? &after : nullptr;
        scene.effects->SetEventListener(&first);
        std::size_t events = 0;
        for (int i = 0; i < 10; ++i)
        {
            scene.world->Step(1.0f / 60.0f, 8, 3);
            for (b2Body* box : {scene.box, second})
            {
                box->SetLinearVelocity(b2Vec2(4.0f, box->GetLinearVelocity().y));
            }
            scene.effects->Step(1.0f / 60.0f);
            events += scene.effects->Events().size();
        }
        EXPECT_GE(events, 2u);
        EXPECT_EQ(first.heard, 1);
        EXPECT_EQ(after.heard, replace ? static_cast<int>(events) - 1 : 0);
    }
}

// A game tears a level down on an event: a trial's listener destroyed the Effects on a scrape's beginning,
// and the delivery loop went on reading the freed object (a use after free under AddressSanitizer). The
// listener hears no more events of the step, and Step returns without touching the destroyed Effects.
TEST(Events, TheListenerMayDestroyTheEffects)
{
    struct Destroying final : public EffectEventListener
    {
        void OnEffectEvent(const EffectEvent&) override
        {
            ++heard;
            owner->reset();
        }
        std::unique_ptr<Effects>* owner = nullptr;
        int heard = 0;
    } destroying;
    ScrapeScene scene;
    b2Body* second = scene.CreateBox(b2Vec2(4.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    scene.effects->SetMaterial(second, scene.Material("steel"));
    destroying.owner = &scene.effects;
    scene.effects->SetEventListener(&destroying);
    int steps = 0;
    while (scene.effects != nullptr && steps < 60)
    {
        scene.world->Step(1.0f / 60.0f, 8, 3);
        for (b2Body* box : {scene.box, second})
        {
            box->SetLinearVelocity(b2Vec2(4.0f, box->GetLinearVelocity().y));
        }
        scene.effects->Step(1.0f / 60.0f); // both boxes begin scraping in the same step: two events
        ++steps;
    }
    EXPECT_EQ(scene.effects, nullptr);
    EXPECT_EQ(destroying.heard, 1);
    for (int i = 0; i < 10; ++i)
    {
        scene.world->Step(1.0f / 60.0f, 8, 3); // the world's listeners are its own again
    }
}

// Stepping the effects from their own listener would hand on a step's events while the next one replaces
// them: refused.
TEST(Events, TheListenerMayNotStepTheEffects)
{
    struct Stepping final : public EffectEventListener
    {
        void OnEffectEvent(const EffectEvent&) override
        {
            if (effects != nullptr)
            {
                Effects* stepped = effects;
                effects = nullptr;
                stepped->Step(1.0f / 60.0f);
            }
        }
        Effects* effects = nullptr;
    } stepping;
    ScrapeScene scene;
    stepping.effects = scene.effects.get();
    scene.effects->SetEventListener(&stepping);
    try
    {
        scene.Slide(4.0f, 10);
        ADD_FAILURE() << "no InputError";
    }
    catch (const InputError& error)
    {
        EXPECT_NE(std::string(error.what()).find("listener"), std::string::npos) << error.what();
    }
    EXPECT_EQ(stepping.effects, nullptr) << "the listener was called";
    scene.effects->SetEventListener(nullptr);
    scene.Step(); // the effects still step afterwards

    // Nor from the delivery of EndScrapes' events (a trial's listener stepped the Effects from there: the
    // hold on Step was let go by EndScrapes, and a nested Step destroyed particle bodies twice).
    scene.Slide(4.0f, 10);
    stepping.effects = scene.effects.get();
    scene.effects->SetEventListener(&stepping);
    EXPECT_THROW(scene.effects->EndScrapes(), InputError);
    EXPECT_EQ(stepping.effects, nullptr) << "the listener was called";
    scene.effects->SetEventListener(nullptr);
    scene.Step();
}

// A trial's contact listener stepped the Effects inside b2World::Step, where Box2D's world is locked (no
// body may be created or destroyed, and the contacts are half updated): refused.
TEST(Events, AContactListenerMayNotStepTheEffects)
{
    class Stepping final : public b2ContactListener
    {
    public:
        void BeginContact(b2Contact*) override
        {
            if (effects == nullptr)
            {
                return;
            }
            try
            {
                std::exchange(effects, nullptr)->Step(1.0f / 60.0f);
            }
            catch (const InputError& error)
            {
                message = error.what();
            }
        }
        Effects* effects = nullptr;
        std::string message;
    } stepping;
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 2.0f), 0.5f, 0.5f, 0.5f);
    Effects& fx = scene.AttachSteelOnConcrete(DefaultPreset(), ground, box, &stepping);
    stepping.effects = &fx;
    for (int i = 0; i < 60; ++i)
    {
        scene.Step();
    }
    EXPECT_EQ(stepping.effects, nullptr) << "the box landed";
    EXPECT_NE(stepping.message.find("inside b2World::Step"), std::string::npos) << stepping.message;
    EXPECT_EQ(fx.Stats().steps, 60u);
}

// EndScrapes from the destruction listener as a particle body goes, inside a Step: the ends follow that
// step's events (a trial's listener ended the scrapes there and the events were handed on in the middle of
// the step).
TEST(Events, EndScrapesDuringAStepEndsThemWithThatStepsEvents)
{
    class Ending final : public b2DestructionListener
    {
    public:
        void SayGoodbye(b2Joint*) override {}
        void SayGoodbye(b2Fixture*) override
        {
            if (effects != nullptr)
            {
                std::exchange(effects, nullptr)->EndScrapes();
            }
        }
        Effects* effects = nullptr;
    } ending;
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    Effects& fx = scene.AttachSteelOnConcrete(TutorialPreset(), ground, box); // body-backed sparks
    fx.SetDestructionListener(&ending);
    bool ended = false;
    for (int i = 0; i < 600 && !ended; ++i)
    {
        box->SetLinearVelocity(b2Vec2(6.0f, box->GetLinearVelocity().y));
        box->SetAngularVelocity(0.0f);
        ending.effects = i == 60 ? &fx : ending.effects; // from the 60th step on, at the first goodbye
        scene.Step();
        for (const EffectEvent& event : fx.Events())
        {
            ended = ended || (event.type == EffectEventType::scrapeEnded && event.end == ScrapeEnd::stopped);
        }
    }
    EXPECT_TRUE(ended) << "the stopped scrape is among a step's events";
    EXPECT_EQ(ending.effects, nullptr) << "a particle body went";
    fx.SetDestructionListener(nullptr);
    scene.Step();
}

// A trial's job system stepped one Effects from two threads at once: with helper threads it deadlocked, with
// one it raced. A Step while another thread steps the same Effects is refused; one thread after another is
// fine.
TEST(Events, AnotherThreadMayNotStepTheEffectsDuringAStep)
{
    struct FromAnotherThread final : public EffectEventListener
    {
        void OnEffectEvent(const EffectEvent&) override
        {
            if (effects == nullptr)
            {
                return;
            }
            Effects* stepped = std::exchange(effects, nullptr);
            std::thread(
                [&]
                {
                    try
                    {
                        stepped->Step(1.0f / 60.0f);
                    }
                    catch (const InputError& error)
                    {
                        message = error.what();
                    }
                })
                .join();
        }
        Effects* effects = nullptr;
        std::string message;
    } other;
    ScrapeScene scene;
    other.effects = scene.effects.get();
    scene.effects->SetEventListener(&other);
    scene.Slide(4.0f, 10);
    EXPECT_EQ(other.effects, nullptr) << "the listener was called";
    EXPECT_NE(other.message.find("another thread steps the same Effects"), std::string::npos)
        << other.message;
    scene.effects->SetEventListener(nullptr);
    const std::uint64_t steps = scene.effects->Stats().steps;
    std::thread([&] { scene.Step(); }).join();
    scene.Step();
    EXPECT_EQ(scene.effects->Stats().steps, steps + 2) << "stepped by one thread, then another";
}

// A one-way platform: the application disables the platform's contacts while the block is below its top.
// A trial jumped a block up through one: the contact it disabled made an impact at 8 m/s and a burst of
// 36 sparks. A disabled contact has not touched; its first touch is the first step it is let through.
TEST(Events, AContactTheApplicationDisablesMakesNoImpactUntilItIsLetThrough)
{
    class OneWay final : public b2ContactListener
    {
    public:
        void PreSolve(b2Contact* contact, const b2Manifold*) override
        {
            const bool withPlatform =
                contact->GetFixtureA() == platform || contact->GetFixtureB() == platform;
            if (withPlatform && block->GetPosition().y - 0.5f < platformTop - 0.05f)
            {
                contact->SetEnabled(false);
            }
        }
        const b2Fixture* platform = nullptr;
        const b2Body* block = nullptr;
        float platformTop = 0.0f;
    } oneWay;
    for (const float hz : {30.0f, 60.0f, 120.0f})
    {
        SCOPED_TRACE(testing::Message() << hz << " Hz");
        TestWorld scene;
        b2Body* ground = scene.CreateGround();
        b2Body* platformBody = scene.CreateBox(b2Vec2(0.0f, 2.1f), 3.0f, 0.1f, 0.8f, b2_staticBody);
        b2Body* block = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.6f);
        oneWay.platform = platformBody->GetFixtureList();
        oneWay.block = block;
        oneWay.platformTop = 2.2f;
        EffectsDef def;
        def.config = DefaultPreset();
        def.contactListener = &oneWay;
        Effects fx(*scene.world, def);
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(platformBody, fx.FindMaterial("concrete"));
        fx.SetMaterial(block, fx.FindMaterial("steel"));
        block->SetLinearVelocity(b2Vec2(0.0f, 12.0f)); // up through the platform to 7.7 m, then down onto it
        std::vector<EffectEvent> platformImpacts;
        for (int step = 0; step < static_cast<int>(3.0f * hz); ++step)
        {
            scene.world->Step(1.0f / hz, 8, 3);
            fx.Step(1.0f / hz);
            for (const EffectEvent& event : fx.Events())
            {
                if (event.type == EffectEventType::impact &&
                    (event.fixtureA == oneWay.platform || event.fixtureB == oneWay.platform))
                {
                    platformImpacts.push_back(event);
                }
            }
        }
        EXPECT_GT(block->GetPosition().y, 2.2f) << "it landed on the platform";
        ASSERT_EQ(platformImpacts.size(), 1u) << "only the landing on top";
        EXPECT_GT(platformImpacts[0].approachSpeed, 9.0f) << "falling from 7.7 m onto 2.2 m: 10.5 m/s";
        const EffectEvent& landing = platformImpacts[0];
        const float upFromThePlatform =
            landing.fixtureA == oneWay.platform ? landing.normal.y : -landing.normal.y;
        EXPECT_GT(upFromThePlatform, 0.9f) << "from above";
    }
}

TEST(Events, ScrapeEndsWhenABodyFallsAsleep)
{
    ScrapeScene scene;
    scene.StepPlain(30);
    scene.Slide(4.0f, 10);
    scene.box->SetAwake(false);
    scene.effects->Step(1.0f / 60.0f);
    std::vector<EffectEvent> events(scene.effects->Events().begin(), scene.effects->Events().end());
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].type, EffectEventType::scrapeEnded);
    EXPECT_EQ(events[0].end, ScrapeEnd::asleep);
}

TEST(Events, ScrapeEndsWhenTheBodyIsDestroyed)
{
    ScrapeScene scene;
    scene.StepPlain(30);
    scene.Slide(4.0f, 10);
    const b2Fixture* boxFixture = scene.box->GetFixtureList();
    scene.world->DestroyBody(scene.box);
    scene.effects->Step(1.0f / 60.0f);
    ASSERT_EQ(scene.effects->Events().size(), 1u);
    const EffectEvent& ended = scene.effects->Events()[0];
    EXPECT_EQ(ended.type, EffectEventType::scrapeEnded);
    EXPECT_EQ(ended.end, ScrapeEnd::destroyed);
    EXPECT_EQ(ended.fixtureA, boxFixture);
}

TEST(Events, ScrapeEndsWhenTheFixtureIsDestroyed)
{
    ScrapeScene scene;
    scene.StepPlain(30);
    scene.Slide(4.0f, 10);
    b2Fixture* fixture = scene.box->GetFixtureList();
    scene.effects->ForgetFixture(fixture);
    scene.box->DestroyFixture(fixture);
    scene.effects->Step(1.0f / 60.0f);
    ASSERT_EQ(scene.effects->Events().size(), 1u);
    EXPECT_EQ(scene.effects->Events()[0].end, ScrapeEnd::destroyed);
}

TEST(Events, EveryScrapeEndsWhateverHappens)
{
    // Random pushes, lifts, sleeps and a destruction: every began gets exactly one ended.
    ScrapeScene scene;
    b2Body* second = scene.CreateBox(b2Vec2(3.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    scene.effects->SetMaterial(second, scene.Material("steel"));
    std::map<std::uint32_t, int> open;
    std::uint32_t state = 12345;
    auto next = [&state] { return (state = state * 1664525u + 1013904223u) >> 16; };
    for (int i = 0; i < 600; ++i)
    {
        const std::uint32_t roll = next() % 100;
        b2Body* body = (next() & 1) != 0 ? scene.box : second;
        if (body != nullptr && roll < 20)
        {
            body->SetLinearVelocity(b2Vec2(static_cast<float>(next() % 13) - 6.0f, 0.0f));
        }
        else if (body != nullptr && roll < 22)
        {
            body->SetAwake(false);
        }
        else if (body != nullptr && roll < 24)
        {
            body->SetTransform(body->GetPosition() + b2Vec2(0.0f, 1.0f), 0.0f);
        }
        if (i == 450)
        {
            scene.world->DestroyBody(second);
            second = nullptr;
        }
        scene.Step();
        for (const EffectEvent& event : scene.effects->Events())
        {
            if (event.type == EffectEventType::scrapeBegan)
            {
                EXPECT_EQ(open[event.id]++, 0);
            }
            else if (event.type == EffectEventType::scrapeChanged)
            {
                EXPECT_EQ(open[event.id], 1) << "change of a scrape that is not going on";
            }
            else if (event.type == EffectEventType::scrapeEnded)
            {
                EXPECT_EQ(open[event.id]--, 1);
            }
        }
    }
    scene.world->DestroyBody(scene.box);
    scene.Step();
    for (const EffectEvent& event : scene.effects->Events())
    {
        if (event.type == EffectEventType::scrapeEnded)
        {
            --open[event.id];
        }
    }
    int began = 0;
    for (const auto& [id, count] : open)
    {
        EXPECT_EQ(count, 0) << "scrape " << id << " never ended";
        ++began;
    }
    EXPECT_GT(began, 5);
}

TEST(Events, ImpactReportsApproachSpeedBeforeTheSolverAndItsImpulse)
{
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 5.5f), 0.5f, 0.5f, 0.5f);
    Effects& fx = scene.Attach();
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(box, fx.FindMaterial("steel"));
    std::vector<EffectEvent> impacts;
    float fastestFall = 0.0f;
    for (int i = 0; i < 120; ++i)
    {
        fastestFall = std::max(fastestFall, -box->GetLinearVelocity().y);
        scene.Step();
        for (const EffectEvent& event : fx.Events())
        {
            if (event.type == EffectEventType::impact)
            {
                impacts.push_back(event);
            }
        }
    }
    ASSERT_EQ(impacts.size(), 1u);
    // Falling 5 m: about sqrt(2 g h) = 10 m/s; what the step saw before the solver acted.
    EXPECT_NEAR(impacts[0].approachSpeed, fastestFall, 0.2f);
    EXPECT_GT(impacts[0].approachSpeed, 9.0f);
    EXPECT_GT(impacts[0].normalImpulse, 0.5f * impacts[0].approachSpeed) << "1 kg stopped: impulse ~ m v";
    EXPECT_NEAR(impacts[0].normal.y, -1.0f, 1e-3f);
    EXPECT_NEAR(impacts[0].point.y, 0.0f, 0.1f);
    // The default preset bursts sparks on a hard steel-on-concrete hit: 6 per m/s above 2, at most 40.
    EXPECT_GE(scene.Spawned("sparks"), 40u);
}

TEST(Events, GentleTouchIsNoImpactAndThresholdIsPerRule)
{
    auto impactsFor = [](float threshold, float height)
    {
        TestWorld scene;
        b2Body* ground = scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f + height), 0.5f, 0.5f, 0.5f);
        EffectsConfig config = DefaultPreset();
        config.rules[0].impactThreshold = threshold;
        Effects& fx = scene.Attach(config);
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(box, fx.FindMaterial("steel"));
        int impacts = 0;
        for (int i = 0; i < 90; ++i)
        {
            scene.Step();
            for (const EffectEvent& event : fx.Events())
            {
                impacts += event.type == EffectEventType::impact ? 1 : 0;
            }
        }
        return impacts;
    };
    EXPECT_EQ(impactsFor(2.0f, 0.01f), 0);
    EXPECT_EQ(impactsFor(2.0f, 1.0f), 1); // ~4.4 m/s
    EXPECT_EQ(impactsFor(6.0f, 1.0f), 0);
}

// The rule's stats carry each step's fastest new touch, impact or not, and count the impacts: what the
// tuning plot sets impactThreshold against (docs/rendering.md).
TEST(Events, RuleStatsCountImpactsAndKeepTheFastestNewTouchBelowTheThresholdToo)
{
    struct Touches
    {
        int impactEvents = 0;
        std::uint64_t impacts = 0;
        std::uint32_t impactsInSteps = 0;
        int stepsWithATouch = 0;
        float fastest = 0.0f;
    };
    auto touchesFrom = [](float height)
    {
        TestWorld scene;
        b2Body* ground = scene.CreateGround();
        b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f + height), 0.5f, 0.5f, 0.5f);
        Effects& fx = scene.Attach(); // steel on concrete: impactThreshold 2 m/s
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(box, fx.FindMaterial("steel"));
        Touches touches;
        for (int i = 0; i < 90; ++i)
        {
            scene.Step();
            const RuleStats& rule = fx.Stats().rules[0];
            for (const EffectEvent& event : fx.Events())
            {
                touches.impactEvents += event.type == EffectEventType::impact ? 1 : 0;
            }
            touches.impactsInSteps += rule.impactsLastStep;
            touches.stepsWithATouch += rule.approachMaxLastStep > 0.0f ? 1 : 0;
            touches.fastest = std::max(touches.fastest, rule.approachMaxLastStep);
            touches.impacts = rule.impacts;
        }
        return touches;
    };
    const Touches soft = touchesFrom(0.05f); // about 1 m/s: a new touch, no impact
    EXPECT_EQ(soft.impactEvents, 0);
    EXPECT_EQ(soft.impacts, 0u);
    EXPECT_GE(soft.stepsWithATouch, 1);
    EXPECT_GT(soft.fastest, 0.5f);
    EXPECT_LT(soft.fastest, 2.0f);
    const Touches hard = touchesFrom(1.0f); // about 4.4 m/s: one impact
    EXPECT_EQ(hard.impactEvents, 1);
    EXPECT_EQ(hard.impacts, 1u);
    EXPECT_EQ(hard.impactsInSteps, 1u);
    EXPECT_GT(hard.fastest, 4.0f);
    EXPECT_LT(hard.fastest, 5.0f);
}

// A scrape is one per body pair: a block sliding over a chain of short segments (several contacts at once,
// handed from segment to segment) is one scrape from start to stop.
TEST(Events, BlockSlidingOverChainSegmentsIsOneScrape)
{
    TestWorld scene;
    b2BodyDef def;
    b2Body* ground = scene.world->CreateBody(&def);
    std::vector<b2Vec2> points;
    for (int i = 0; i <= 80; ++i)
    {
        points.emplace_back(20.0f - 0.5f * static_cast<float>(i), 0.0f); // right to left: front up
    }
    b2ChainShape chain;
    chain.CreateChain(points.data(), static_cast<int>(points.size()), b2Vec2(21.0f, 0.0f),
                      b2Vec2(-21.0f, 0.0f));
    b2FixtureDef fixture;
    fixture.shape = &chain;
    fixture.friction = 0.8f;
    ground->CreateFixture(&fixture);
    b2Body* box = scene.CreateBox(b2Vec2(-10.0f, 0.25f), 0.5f, 0.25f, 0.5f);
    Effects& fx = scene.Attach();
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(box, fx.FindMaterial("steel"));
    std::vector<EffectEvent> events;
    std::uint32_t contactsMax = 0;
    for (int i = 0; i < 90; ++i)
    {
        scene.world->Step(1.0f / 60.0f, 8, 3);
        box->SetLinearVelocity(b2Vec2(i < 60 ? 4.0f : 0.0f, box->GetLinearVelocity().y));
        box->SetAngularVelocity(0.0f);
        fx.Step(1.0f / 60.0f);
        contactsMax = std::max(contactsMax, fx.Stats().rules[0].contacts);
        events.insert(events.end(), fx.Events().begin(), fx.Events().end());
    }
    EXPECT_GE(contactsMax, 2u);
    const std::vector<EffectEvent> began = OfType(events, EffectEventType::scrapeBegan);
    const std::vector<EffectEvent> ended = OfType(events, EffectEventType::scrapeEnded);
    ASSERT_EQ(began.size(), 1u);
    ASSERT_EQ(ended.size(), 1u);
    EXPECT_EQ(ended[0].id, began[0].id);
    EXPECT_EQ(ended[0].end, ScrapeEnd::belowThreshold);
    EXPECT_EQ(ended[0].fixtureA, box->GetFixtureList());
    EXPECT_EQ(ended[0].fixtureB, ground->GetFixtureList());
    for (const EffectEvent& event : OfType(events, EffectEventType::scrapeChanged))
    {
        EXPECT_EQ(event.id, began[0].id);
    }
    EXPECT_NEAR(began[0].tangentialSpeed, 4.0f, 0.01f);
    EXPECT_NEAR(began[0].normal.y, -1.0f, 1e-3f);
}

// A body of two fixtures scraping along: one scrape, which goes on while either fixture touches and ends
// when the last one goes.
TEST(Events, ScrapeOfABodyOfTwoFixturesEndsWithItsLastFixture)
{
    ScrapeScene scene;
    b2PolygonShape half;
    half.SetAsBox(0.5f, 0.25f, b2Vec2(1.0f, -0.25f), 0.0f); // a second foot beside the box, on the ground
    b2FixtureDef def;
    def.shape = &half;
    def.density = 1.0f;
    def.friction = 0.5f;
    b2Fixture* foot = scene.box->CreateFixture(&def);
    scene.effects->SetMaterial(foot, scene.Material("steel"));
    scene.StepPlain(30);
    std::vector<EffectEvent> events = scene.Slide(4.0f, 20);
    ASSERT_EQ(OfType(events, EffectEventType::scrapeBegan).size(), 1u);
    EXPECT_EQ(scene.effects->Stats().rules[0].contacts, 2u);

    scene.effects->ForgetFixture(foot);
    scene.box->DestroyFixture(foot);
    events = scene.Slide(4.0f, 10);
    EXPECT_TRUE(OfType(events, EffectEventType::scrapeEnded).empty()) << "the box still scrapes";
    EXPECT_TRUE(OfType(events, EffectEventType::scrapeBegan).empty());

    b2Fixture* last = scene.box->GetFixtureList();
    scene.effects->ForgetFixture(last);
    scene.box->DestroyFixture(last);
    scene.effects->Step(1.0f / 60.0f);
    ASSERT_EQ(scene.effects->Events().size(), 1u);
    EXPECT_EQ(scene.effects->Events()[0].type, EffectEventType::scrapeEnded);
    EXPECT_EQ(scene.effects->Events()[0].end, ScrapeEnd::destroyed);
    EXPECT_EQ(scene.effects->Events()[0].fixtureA, last);
}

TEST(Events, OrderIsDeterministicAndTheListenerSeesTheArray)
{
    auto run = []
    {
        ScrapeScene scene;
        b2Body* other = scene.CreateBox(b2Vec2(-3.0f, 2.5f), 0.5f, 0.5f, 0.5f);
        scene.effects->SetMaterial(other, scene.Material("steel"));
        std::vector<EffectEvent> all;
        for (int i = 0; i < 120; ++i)
        {
            other->SetLinearVelocity(b2Vec2(-5.0f, other->GetLinearVelocity().y));
            scene.box->SetLinearVelocity(b2Vec2(i < 60 ? 5.0f : 0.0f, scene.box->GetLinearVelocity().y));
            scene.Step();
            all.insert(all.end(), scene.effects->Events().begin(), scene.effects->Events().end());
        }
        EXPECT_EQ(scene.log.events.size(), all.size());
        for (std::size_t i = 0; i < all.size() && i < scene.log.events.size(); ++i)
        {
            EXPECT_EQ(scene.log.events[i].id, all[i].id);
            EXPECT_EQ(scene.log.events[i].type, all[i].type);
        }
        std::vector<std::tuple<int, std::uint32_t, std::uint64_t, float, float>> summary;
        for (const EffectEvent& event : all)
        {
            summary.emplace_back(static_cast<int>(event.type), event.id, event.step, event.intensity,
                                 event.point.x);
        }
        return summary;
    };
    auto first = run();
    EXPECT_GT(first.size(), 100u);
    EXPECT_EQ(first, run());
}

} // namespace cfx::test
