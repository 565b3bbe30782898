// Misuse of the API that must be refused or survived (issue 15, items 3 and 5): a second Effects on one
// world, bad step times, the application destroying body-backed particles' bodies, DestroyFixture
// without ForgetFixture, and absurd or non-finite numbers reaching the emitter. Meant to run under ASan
// and UBSan (float-cast-overflow included) as well.
#include "contact_tracker.h"
#include "effects_access.h"
#include "emitter.h"
#include "events.h"
#include "fixture_materials.h"
#include "pointer_map.h"
#include "test_world.h"

#include <cmath>
#include <cstddef>
#include <gtest/gtest.h>
#include <limits>
#include <string>

namespace cfx::test
{

namespace
{

constexpr float kDt = 1.0f / 60.0f;
constexpr float kHuge = 3.4e38f;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// A steel box on concrete ground.
struct SlideScene : TestWorld
{
    explicit SlideScene(EffectsConfig config = DefaultPreset(), b2DestructionListener* destruction = nullptr)
    {
        ground = CreateGround();
        box = CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        EffectsDef def;
        def.config = std::move(config);
        def.destructionListener = destruction;
        effects = std::make_unique<Effects>(*world, def);
        effects->SetMaterial(ground, Material("concrete"));
        effects->SetMaterial(box, Material("steel"));
    }

    // Steps with the box held at `speed` along x.
    void Slide(float speed, int steps)
    {
        for (int i = 0; i < steps; ++i)
        {
            world->Step(kDt, 8, 3);
            box->SetLinearVelocity(b2Vec2(speed, box->GetLinearVelocity().y));
            box->SetAngularVelocity(0.0f);
            effects->Step(kDt);
        }
    }

    // The world's bodies counted along its list: Box2D's own count goes wrong when a body is destroyed
    // twice.
    int ListedBodies() const
    {
        int count = 0;
        for (const b2Body* body = world->GetBodyList(); body != nullptr; body = body->GetNext())
        {
            ++count;
        }
        return count;
    }

    b2Body* ground = nullptr;
    b2Body* box = nullptr;
};

struct CountingDestruction final : b2DestructionListener
{
    void SayGoodbye(b2Joint*) override {}
    void SayGoodbye(b2Fixture*) override { ++fixtures; }
    int fixtures = 0;
};

bool Finite(b2Vec2 v)
{
    return std::isfinite(v.x) && std::isfinite(v.y);
}

void ExpectFinite(const EffectEvent& event)
{
    EXPECT_TRUE(Finite(event.point)) << "event " << event.id;
    EXPECT_TRUE(Finite(event.normal)) << "event " << event.id;
    EXPECT_TRUE(std::isfinite(event.intensity)) << "event " << event.id;
    EXPECT_TRUE(std::isfinite(event.tangentialSpeed)) << "event " << event.id;
    EXPECT_TRUE(std::isfinite(event.normalImpulse)) << "event " << event.id;
    EXPECT_TRUE(std::isfinite(event.approachSpeed)) << "event " << event.id;
}

// The emitter as Effects drives it, without Effects' config validation: the emitter must stay defined
// for any numbers, whatever ranges validation enforces. (The pool gets the default preset's types, which
// the tests leave valid: a ParticleSystem refuses invalid ones itself.)
struct RawEmitter : TestWorld
{
    explicit RawEmitter(EffectsConfig effectsConfig)
        : config(std::move(effectsConfig)), rules(BuildRuleTable(config)), tracker(rules, materials),
          particles(*world, DefaultPreset().particleTypes, config.budget), emitter(config, 1),
          events(materials, config.budget.contacts)
    {
        stats.spawnedByType.assign(config.particleTypes.size(), 0);
        stats.rules.assign(config.rules.size(), RuleStats{});
        world->SetContactListener(&tracker);
        ground = CreateGround();
        box = CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
        SetMaterial(ground, "concrete");
        SetMaterial(box, "steel");
    }
    ~RawEmitter() { world->SetContactListener(nullptr); }

    void SetMaterial(b2Body* body, const char* name)
    {
        materials.Set(body->GetFixtureList(), config.FindMaterial(name));
    }
    void Emit()
    {
        tracker.Prune();
        events.BeginStep(tracker.Step(), kDt, tracker.EndedPairs());
        emitter.Emit(*world, config, tracker, events, particles, stats, kDt);
        tracker.EndStep(); // as Effects::Step does: before the particle step
        particles.Step(kDt, world->GetGravity());
    }
    void Slide(float speed, int steps)
    {
        for (int i = 0; i < steps; ++i)
        {
            world->Step(kDt, 8, 3);
            box->SetLinearVelocity(b2Vec2(speed, box->GetLinearVelocity().y));
            box->SetAngularVelocity(0.0f);
            Emit();
        }
    }
    RuleStats& Sparks() { return stats.rules[0]; }

    EffectsConfig config;
    FixtureMaterials materials;
    RuleTable rules;
    ContactTracker tracker;
    ParticleSystem particles; // destroyed before the world (a base)
    detail::Emitter emitter;
    detail::EventTracker events;
    EffectsStats stats;
    b2Body* ground = nullptr;
    b2Body* box = nullptr;
};

EffectsConfig SmallPool(EffectsConfig config, std::uint32_t capacity)
{
    config.budget.capacity = capacity;
    return config;
}

} // namespace

// --- one Effects per world ---------------------------------------------------------------------------

TEST(EffectsMisuse, SecondEffectsOnTheSameWorldThrowsAndTheFirstKeepsWorking)
{
    SlideScene scene;
    EffectsDef def;
    def.config = DefaultPreset();
    try
    {
        Effects second(*scene.world, def);
        FAIL() << "a second Effects on the same world was accepted";
    }
    catch (const InputError& error)
    {
        ASSERT_EQ(error.Diagnostics().size(), 1u);
        EXPECT_EQ(error.Diagnostics()[0].file, "<api>");
        EXPECT_EQ(error.Diagnostics()[0].path, "world");
        EXPECT_NE(std::string(error.what()).find("already has an Effects"), std::string::npos)
            << error.what();
    }
    // The refused one took nothing: the first still tracks contacts and emits.
    scene.Slide(6.0f, 30);
    EXPECT_GT(scene.Spawned("sparks"), 0u);
    EXPECT_EQ(detail::EffectsAccess::Tracker(*scene.effects).TrackedCount(), 1u);
}

TEST(EffectsMisuse, ReplacementAfterDestroyingTheOldOneAndOtherWorldsAreFine)
{
    SlideScene scene;
    scene.effects.reset();
    EffectsDef def;
    def.config = DefaultPreset();
    EXPECT_NO_THROW(scene.effects = std::make_unique<Effects>(*scene.world, def));
    TestWorld other;
    EXPECT_NO_THROW(other.effects = std::make_unique<Effects>(*other.world, def));
    // A refused second one does not release the world's claim either.
    EXPECT_THROW(Effects(*scene.world, def), InputError);
    EXPECT_THROW(Effects(*scene.world, def), InputError);
}

TEST(EffectsMisuse, InvalidConfigStillReportsTheConfig)
{
    SlideScene scene;
    EffectsDef def;
    def.config = DefaultPreset();
    def.config.rules[0].threshold = -1.0f;
    try
    {
        Effects second(*scene.world, def);
        FAIL();
    }
    catch (const InputError& error)
    {
        EXPECT_NE(error.Diagnostics()[0].path, "world");
    }
}

// --- step times ----------------------------------------------------------------------------------------

TEST(EffectsMisuse, StepRefusesZeroNegativeAndNonFiniteTimes)
{
    SlideScene scene;
    scene.Slide(6.0f, 10);
    const std::uint64_t steps = scene.effects->Stats().steps;
    const double time = scene.effects->Stats().time;
    const std::uint32_t live = scene.effects->Stats().live;
    for (float dt : {0.0f, -0.0f, -kDt, kNaN, kInf, -kInf})
    {
        scene.world->Step(kDt, 8, 3);
        try
        {
            scene.effects->Step(dt);
            ADD_FAILURE() << "Step(" << dt << ") was accepted";
        }
        catch (const InputError& error)
        {
            EXPECT_EQ(error.Diagnostics()[0].path, "dt");
            EXPECT_NE(std::string(error.what()).find("step time"), std::string::npos) << error.what();
            if (std::isnan(dt))
            {
                // Written as the config errors write it (FloatText), not as a stream does ("nan").
                EXPECT_NE(std::string(error.what()).find("found NaN"), std::string::npos) << error.what();
            }
        }
        EXPECT_EQ(scene.effects->Stats().steps, steps);
        EXPECT_EQ(scene.effects->Stats().time, time);
        EXPECT_EQ(scene.effects->Stats().live, live);
    }
    // Still usable afterwards.
    EXPECT_NO_THROW(scene.effects->Step(kDt));
    for (const EffectEvent& event : scene.effects->Events())
    {
        ExpectFinite(event);
    }
}

// A huge but finite step time is accepted. A trial's 3e38 s hung the step: a sliding body's start pose
// (its centre less dt times its velocity) overflowed, and so did the grid of moving shapes built from it.
// Such a body is skipped and counted like any other body beyond 1e7.
TEST(EffectsMisuse, AHugeFiniteStepTimeSkipsTheBodiesItThrowsOutOfTheWorld)
{
    for (const float dt : {1.0e30f, 3.0e38f, std::numeric_limits<float>::max()})
    {
        SlideScene scene;
        scene.Slide(12.0f, 30);
        ASSERT_GT(scene.effects->Stats().live, 0u);
        const std::uint64_t skipped = scene.effects->Stats().skippedBodies;
        scene.world->Step(kDt, 8, 3);
        scene.effects->Step(dt);
        EXPECT_EQ(scene.effects->Stats().skippedBodies, skipped + 1) << dt << ": the sliding box";
        const ParticleView view = scene.effects->Particles();
        for (std::uint32_t i = 0; i < view.count; ++i)
        {
            EXPECT_TRUE(std::isfinite(view.positionX[view.Slot(i)]) &&
                        std::isfinite(view.positionY[view.Slot(i)]));
        }
        for (const EffectEvent& event : scene.effects->Events())
        {
            ExpectFinite(event);
        }
        scene.Slide(12.0f, 2); // and it goes on
    }
}

TEST(EffectsMisuse, StepRefusesANonFiniteGravity)
{
    SlideScene scene;
    scene.world->SetGravity(b2Vec2(0.0f, kNaN));
    try
    {
        scene.effects->Step(kDt);
        FAIL();
    }
    catch (const InputError& error)
    {
        EXPECT_EQ(error.Diagnostics()[0].path, "gravity");
        EXPECT_NE(std::string(error.what()).find("(0, NaN)"), std::string::npos) << error.what();
    }
    EXPECT_EQ(scene.effects->Stats().steps, 0u);
}

TEST(ParticleSystemMisuse, StepRefusesBadTimesAndGravity)
{
    TestWorld scene;
    ParticleTypeDef type;
    type.name = "dust";
    ParticleSystem particles(*scene.world, std::span<const ParticleTypeDef>(&type, 1), ParticleBudget{8});
    particles.Spawn(ParticleSpawn{b2Vec2(0.0f, 1.0f), b2Vec2(1.0f, 0.0f), 1.0f, ParticleTypeId{0}});
    for (float dt : {0.0f, -kDt, kNaN, kInf})
    {
        EXPECT_THROW(particles.Step(dt, b2Vec2(0.0f, -10.0f)), InputError) << dt;
    }
    EXPECT_THROW(particles.Step(kDt, b2Vec2(kInf, 0.0f)), InputError);
    const ParticleView view = particles.View();
    EXPECT_EQ(view.positionX[view.Slot(0)], 0.0f); // nothing moved
    EXPECT_NO_THROW(particles.Step(kDt, b2Vec2(0.0f, -10.0f)));
}

// The first diagnostic of what `call` throws ("" when it throws nothing or something else).
template <typename Call> Diagnostic Refusal(Call&& call)
{
    try
    {
        call();
    }
    catch (const InputError& error)
    {
        return error.Diagnostics().front();
    }
    return Diagnostic{};
}

TEST(ParticleSystemMisuse, AnInvalidDefinitionOrSpawnTypeIsRefused)
{
    TestWorld scene;
    ParticleTypeDef type; // no name: a system alone never reads it
    const auto types = std::span<const ParticleTypeDef>(&type, 1);
    EXPECT_EQ(Refusal([&] { ParticleSystem(*scene.world, types, ParticleBudget{0}); }).path,
              "budget.capacity");
    ParticleTypeDef bad = type;
    bad.radius = kNaN;
    EXPECT_EQ(
        Refusal(
            [&]
            { ParticleSystem(*scene.world, std::span<const ParticleTypeDef>(&bad, 1), ParticleBudget{8}); })
            .path,
        "particleTypes[0].radius");

    ParticleSystem particles(*scene.world, types, ParticleBudget{8});
    for (const ParticleTypeId id : {ParticleTypeId{}, ParticleTypeId{1}, ParticleTypeId{200}})
    {
        const Diagnostic refused = Refusal(
            [&] {
                particles.Spawn(ParticleSpawn{b2Vec2(0.0f, 1.0f), b2Vec2(0.0f, 0.0f), 1.0f, id});
            });
        EXPECT_EQ(refused.file, "<api>") << id.index;
        EXPECT_EQ(refused.path, "type") << id.index;
    }
    EXPECT_EQ(particles.Count(), 0u);
    particles.Spawn(ParticleSpawn{b2Vec2(0.0f, 1.0f), b2Vec2(0.0f, 0.0f), 1.0f, ParticleTypeId{0}});
    EXPECT_EQ(particles.Count(), 1u);
}

TEST(EffectsMisuse, SetMaterialRefusesANullTargetAndAMaterialTheConfigLacks)
{
    SlideScene scene;
    Effects& effects = *scene.effects;
    const MaterialId steel = scene.Material("steel");
    const MaterialId unknown{static_cast<std::uint16_t>(effects.Config().materials.size())};
    EXPECT_EQ(Refusal([&] { effects.SetMaterial(static_cast<b2Fixture*>(nullptr), steel); }).path, "fixture");
    EXPECT_EQ(Refusal([&] { effects.SetMaterial(static_cast<b2Body*>(nullptr), steel); }).path, "body");
    const Diagnostic refused = Refusal([&] { effects.SetMaterial(scene.ground, unknown); });
    EXPECT_EQ(refused.path, "material");
    EXPECT_NE(refused.message.find("names no material of this config"), std::string::npos) << refused.message;
    EXPECT_EQ(Refusal([&] { effects.SetMaterial(scene.box->GetFixtureList(), MaterialId{60000}); }).path,
              "material");
    EXPECT_EQ(effects.Material(scene.ground->GetFixtureList()), scene.Material("concrete")); // unchanged
    EXPECT_EQ(effects.Material(scene.box->GetFixtureList()), steel);
    effects.SetMaterial(scene.box, MaterialId{}); // the invalid id still removes it
    EXPECT_FALSE(effects.Material(scene.box->GetFixtureList()).IsValid());
}

template <class Value>
concept CanSetMaterialWith = requires(Effects& effects, b2Fixture* fixture, Value value)
{
    effects.SetMaterial(fixture, value);
};

// A trial: SetMaterial(fixture, FindMaterial("steal")) removes the material without a word (FindMaterial
// gives an invalid id for an unknown name). By name, a misspelt material is refused with the nearest one.
TEST(EffectsMisuse, SetMaterialByNameRefusesAnUnknownNameAndNamesTheNearest)
{
    SlideScene scene;
    Effects& effects = *scene.effects;
    b2Fixture* box = scene.box->GetFixtureList();
    effects.SetMaterial(box, "rubber");
    EXPECT_EQ(effects.Material(box), scene.Material("rubber"));
    effects.SetMaterial(scene.box, "steel");
    EXPECT_EQ(effects.Material(box), scene.Material("steel"));
    const Diagnostic misspelt = Refusal([&] { effects.SetMaterial(box, "steal"); });
    EXPECT_EQ(misspelt.file, "<api>");
    EXPECT_EQ(misspelt.path, "material");
    EXPECT_NE(misspelt.message.find("unknown material \"steal\", did you mean \"steel\"?"), std::string::npos)
        << misspelt.message;
    const Diagnostic capital = Refusal([&] { effects.SetMaterial(scene.ground, "Concrete"); });
    EXPECT_NE(capital.message.find("did you mean \"concrete\"?"), std::string::npos) << capital.message;
    EXPECT_EQ(Refusal([&] { effects.SetMaterial(box, ""); }).path, "material");
    const char* noName = nullptr;
    EXPECT_EQ(Refusal([&] { effects.SetMaterial(box, noName); }).path, "material");
    const std::string rubber = "rubber";
    effects.SetMaterial(box, rubber);
    EXPECT_EQ(effects.Material(box), scene.Material("rubber"));
    effects.SetMaterial(box, std::string_view("steel"));
    // {} is still the id's overload (it removes the material); 0, NULL and nullptr do not compile (a trial:
    // they were taken for a null name and crashed).
    static_assert(CanSetMaterialWith<MaterialId> && CanSetMaterialWith<const char*> &&
                  CanSetMaterialWith<std::string>);
    static_assert(!CanSetMaterialWith<int> && !CanSetMaterialWith<long> &&
                  !CanSetMaterialWith<std::nullptr_t>);
    effects.SetMaterial(scene.ground, {});
    EXPECT_FALSE(effects.Material(scene.ground->GetFixtureList()).IsValid());
    effects.SetMaterial(scene.ground, "concrete");
    EXPECT_EQ(Refusal([&] { effects.SetMaterial(static_cast<b2Fixture*>(nullptr), "steel"); }).path,
              "fixture");
    EXPECT_EQ(Refusal([&] { effects.SetMaterial(static_cast<b2Body*>(nullptr), "steal"); }).path, "body");
    EXPECT_EQ(effects.Material(box), scene.Material("steel")); // unchanged by every refusal
    EXPECT_EQ(effects.Material(scene.ground->GetFixtureList()), scene.Material("concrete"));
}

// A trial: Material(nullptr) crashed once any material was set, and ForgetFixture(nullptr) erased another
// fixture's material (a null key matched the map's empty slots) and then lost later updates.
TEST(EffectsMisuse, ANullFixtureHasNoMaterialAndForgettingOneIsRefused)
{
    SlideScene scene;
    Effects& effects = *scene.effects;
    const MaterialId concrete = scene.Material("concrete");
    b2Fixture* ground = scene.ground->GetFixtureList();
    ASSERT_EQ(effects.Material(ground), concrete);
    EXPECT_FALSE(effects.Material(nullptr).IsValid());
    for (int i = 0; i < 3; ++i)
    {
        EXPECT_EQ(Refusal([&] { effects.ForgetFixture(nullptr); }).path, "fixture");
    }
    EXPECT_EQ(effects.Material(ground), concrete) << "no other fixture's material is touched";
    effects.SetMaterial(ground, scene.Material("steel"));
    EXPECT_EQ(effects.Material(ground), scene.Material("steel")) << "and later updates hold";
}

TEST(PointerMap, ANullKeyIsNeverFoundNorErased)
{
    detail::PointerMap map;
    int a = 0, b = 0;
    map.Set(&a, 1);
    map.Set(&b, 2);
    EXPECT_EQ(map.Find(nullptr), nullptr);
    EXPECT_FALSE(map.Erase(nullptr));
    EXPECT_EQ(map.Size(), 2u);
    ASSERT_NE(map.Find(&a), nullptr);
    EXPECT_EQ(*map.Find(&a), 1u);
    ASSERT_NE(map.Find(&b), nullptr);
    EXPECT_EQ(*map.Find(&b), 2u);
}

// --- body-backed particles destroyed by the application --------------------------------------------

TEST(EffectsMisuse, ApplicationDestroyingTutorialParticleBodiesIsNoticed)
{
    CountingDestruction application;
    SlideScene scene(TutorialPreset(), &application);
    scene.Slide(8.0f, 20);
    const std::uint32_t live = scene.effects->Stats().live;
    ASSERT_GT(live, 4u) << "the tutorial preset's sparks are Box2D bodies";
    ASSERT_EQ(scene.ListedBodies(), static_cast<int>(2 + live));

    // The application destroys every other particle body (say, in its own clean-up).
    std::vector<b2Body*> doomed;
    int index = 0;
    for (b2Body* body = scene.world->GetBodyList(); body != nullptr; body = body->GetNext())
    {
        if (body != scene.ground && body != scene.box && index++ % 2 == 0)
        {
            doomed.push_back(body);
        }
    }
    for (b2Body* body : doomed)
    {
        scene.world->DestroyBody(body);
    }
    EXPECT_EQ(application.fixtures, static_cast<int>(doomed.size()))
        << "the application's listener is chained";

    scene.effects->Step(kDt); // Box2D asserted (or corrupted its lists) here: the bodies destroyed again
    EXPECT_EQ(scene.ListedBodies(), scene.world->GetBodyCount());
    EXPECT_EQ(scene.world->GetBodyCount(), static_cast<int>(2 + scene.effects->Stats().live));

    // Keep going: new particles, the rest dying of age, the system destroyed with the world's bodies.
    scene.Slide(8.0f, 200);
    EXPECT_EQ(scene.ListedBodies(), scene.world->GetBodyCount());
    EXPECT_EQ(scene.world->GetBodyCount(), static_cast<int>(2 + scene.effects->Stats().live));
    scene.effects.reset();
    EXPECT_EQ(scene.world->GetBodyCount(), 2);
    EXPECT_EQ(scene.ListedBodies(), 2);
}

TEST(ParticleSystemMisuse, ForgottenBodiesLeaveThePoolInOrderAndAreNeverDestroyedAgain)
{
    TestWorld scene;
    ParticleTypeDef type;
    type.name = "pebble";
    type.backend = ParticleBackend::body;
    type.lifetime = 100.0f;
    type.gravityScale = 0.0f;
    ParticleSystem particles(*scene.world, std::span<const ParticleTypeDef>(&type, 1),
                             ParticleBudget{4, RecyclePolicy::oldest});
    for (int i = 0; i < 4; ++i)
    {
        particles.Spawn(
            ParticleSpawn{b2Vec2(static_cast<float>(i), 5.0f), b2Vec2(0.0f, 0.0f), 1.0f, ParticleTypeId{0}});
    }
    ASSERT_EQ(scene.world->GetBodyCount(), 4);
    // Particle 1's body, found by position; the application destroys it and tells the system.
    b2Body* second = nullptr;
    for (b2Body* body = scene.world->GetBodyList(); body != nullptr; body = body->GetNext())
    {
        if (body->GetPosition().x == 1.0f)
        {
            second = body;
        }
    }
    ASSERT_NE(second, nullptr);
    ASSERT_TRUE(particles.IsParticleBody(second));
    scene.world->DestroyBody(second);
    particles.ForgetBody(second);
    particles.ForgetBody(second); // twice, or for any other body: nothing
    EXPECT_FALSE(particles.IsParticleBody(second));

    // A body of the application's own, very likely at the freed address, is never taken for the particle's.
    b2BodyDef def;
    b2Body* own = scene.world->CreateBody(&def);
    particles.ForgetBody(own);

    scene.world->Step(kDt, 8, 3);
    particles.Step(kDt, scene.world->GetGravity());
    ASSERT_EQ(particles.Count(), 3u);
    const ParticleView view = particles.View();
    EXPECT_EQ(view.positionX[view.Slot(0)], 0.0f);
    EXPECT_EQ(view.positionX[view.Slot(1)], 2.0f);
    EXPECT_EQ(view.positionX[view.Slot(2)], 3.0f);
    EXPECT_EQ(scene.world->GetBodyCount(), 4); // 3 particles and the application's

    // Forgotten before a recycle: the oldest particle's body goes, then the pool fills and turns.
    b2Body* first = nullptr;
    for (b2Body* body = scene.world->GetBodyList(); body != nullptr; body = body->GetNext())
    {
        if (body->GetPosition().x == 0.0f && body != own)
        {
            first = body;
        }
    }
    ASSERT_NE(first, nullptr);
    particles.ForgetBody(first); // before destroying it: also fine
    scene.world->DestroyBody(first);
    for (int i = 0; i < 6; ++i)
    {
        particles.Spawn(ParticleSpawn{b2Vec2(10.0f + static_cast<float>(i), 5.0f), b2Vec2(0.0f, 0.0f), 1.0f,
                                      ParticleTypeId{0}});
    }
    EXPECT_EQ(particles.Count(), 4u);
    EXPECT_EQ(scene.world->GetBodyCount(), 5);
    EXPECT_TRUE(own->IsEnabled()); // still the application's, alive
}

TEST(ParticleSystemMisuse, ForgottenBodyIsNotDestroyedByTheSystemsDestructor)
{
    TestWorld scene;
    ParticleTypeDef type;
    type.name = "pebble";
    type.backend = ParticleBackend::body;
    auto particles =
        std::make_unique<ParticleSystem>(*scene.world, std::span<const ParticleTypeDef>(&type, 1),
                                         ParticleBudget{4, RecyclePolicy::lowestLife});
    particles->Spawn(ParticleSpawn{b2Vec2(0.0f, 5.0f), b2Vec2(0.0f, 0.0f), 1.0f, ParticleTypeId{0}});
    particles->Spawn(ParticleSpawn{b2Vec2(1.0f, 5.0f), b2Vec2(0.0f, 0.0f), 1.0f, ParticleTypeId{0}});
    b2Body* body = scene.world->GetBodyList();
    scene.world->DestroyBody(body);
    particles->ForgetBody(body);
    particles.reset();
    EXPECT_EQ(scene.world->GetBodyCount(), 0);
    EXPECT_EQ(scene.world->GetBodyList(), nullptr);
}

// --- DestroyFixture without ForgetFixture ----------------------------------------------------------------

TEST(EffectsMisuse, FixtureAtAFreedAddressOnAnotherBodyDoesNotInheritTheMaterial)
{
    SlideScene scene;
    b2Fixture* steel = scene.box->GetFixtureList();
    ASSERT_TRUE(scene.effects->Material(steel).IsValid());
    scene.box->DestroyFixture(steel); // the trap: no ForgetFixture first

    // A plain body with no material dropped on the ground; Box2D's block allocator hands it the address.
    b2Body* crate = scene.CreateBox(b2Vec2(3.0f, 0.5f), 0.4f, 0.4f, 0.5f);
    ASSERT_EQ(crate->GetFixtureList(), steel) << "premise: Box2D reuses the freed fixture's address";
    EXPECT_FALSE(scene.effects->Material(crate->GetFixtureList()).IsValid());
    for (int i = 0; i < 30; ++i)
    {
        scene.world->Step(kDt, 8, 3);
        crate->SetLinearVelocity(b2Vec2(6.0f, crate->GetLinearVelocity().y));
        scene.effects->Step(kDt);
    }
    EXPECT_EQ(scene.Spawned("sparks"), 0u) << "the crate is not steel";
    EXPECT_EQ(detail::EffectsAccess::Tracker(*scene.effects).TrackedCount(), 0u);
    EXPECT_EQ(scene.effects->Stats().staleMaterials, 1u);

    // Giving it a material works as ever.
    scene.effects->SetMaterial(crate, scene.Material("steel"));
    EXPECT_EQ(scene.effects->Material(crate->GetFixtureList()), scene.Material("steel"));
}

TEST(EffectsMisuse, FixtureReplacedWithAnotherShapeOnTheSameBodyDoesNotInheritTheMaterial)
{
    SlideScene scene;
    b2Fixture* steel = scene.box->GetFixtureList();
    scene.box->DestroyFixture(steel);
    b2PolygonShape smaller;
    smaller.SetAsBox(0.3f, 0.3f);
    b2Fixture* replacement = scene.box->CreateFixture(&smaller, 1.0f);
    ASSERT_EQ(replacement, steel) << "premise: Box2D reuses the freed fixture's address";
    EXPECT_FALSE(scene.effects->Material(replacement).IsValid());
    scene.Slide(6.0f, 30);
    EXPECT_EQ(scene.Spawned("sparks"), 0u);
    EXPECT_EQ(scene.effects->Stats().staleMaterials, 1u);
}

TEST(EffectsMisuse, ForgetFixtureBeforeDestroyFixtureCountsNothingStale)
{
    SlideScene scene;
    b2Fixture* steel = scene.box->GetFixtureList();
    scene.effects->ForgetFixture(steel);
    scene.box->DestroyFixture(steel);
    b2Body* crate = scene.CreateBox(b2Vec2(3.0f, 0.5f), 0.4f, 0.4f, 0.5f);
    EXPECT_FALSE(scene.effects->Material(crate->GetFixtureList()).IsValid());
    scene.Slide(6.0f, 10);
    EXPECT_EQ(scene.effects->Stats().staleMaterials, 0u);
}

TEST(FixtureMaterials, RecordedNeverReadsTheFixtureAndGetChecksWhoItIs)
{
    TestWorld scene;
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    FixtureMaterials materials;
    b2Fixture* fixture = box->GetFixtureList();
    materials.Set(fixture, MaterialId{3});
    EXPECT_EQ(materials.Get(fixture), MaterialId{3});
    EXPECT_EQ(materials.Recorded(fixture), MaterialId{3});
    // Another fixture of another body at the same address (the first one destroyed unannounced).
    box->DestroyFixture(fixture);
    b2Body* other = scene.CreateCircle(b2Vec2(2.0f, 0.5f), 0.5f, 0.5f);
    if (other->GetFixtureList() != fixture)
    {
        GTEST_SKIP() << "Box2D did not reuse the address";
    }
    EXPECT_EQ(materials.Recorded(fixture), MaterialId{3}); // what was recorded, unchecked
    EXPECT_FALSE(materials.Get(fixture).IsValid());
    EXPECT_EQ(materials.Stale(), 1u);
    EXPECT_EQ(materials.Size(), 0u); // the stale entry is dropped
}

// --- the emitter with absurd and non-finite numbers ----------------------------------------------------

TEST(EmitterBounds, HugeRateSpawnsAtMostThePoolPerStep)
{
    for (float rate : {1e9f, kHuge, kInf})
    {
        EffectsConfig config = SmallPool(DefaultPreset(), 64);
        config.rules[0].ratePerIntensity = rate;
        config.rules[0].maxRate = rate;
        RawEmitter scene(std::move(config));
        ASSERT_EQ(scene.config.rules[0].particleType, "sparks");
        for (int i = 0; i < 20; ++i)
        {
            scene.Slide(6.0f, 1);
            EXPECT_LE(scene.Sparks().spawnedLastStep, 64u) << rate;
            EXPECT_TRUE(std::isfinite(scene.emitter.EmissionCarry(0)));
        }
        EXPECT_EQ(scene.Sparks().spawnedLastStep, 64u) << rate;
        EXPECT_LE(scene.particles.Count(), 64u);
        for (const EffectEvent& event : scene.events.Events())
        {
            ExpectFinite(event);
        }
    }
}

TEST(EmitterBounds, NaNRateSpawnsNothing)
{
    EffectsConfig config = SmallPool(DefaultPreset(), 64);
    config.rules[0].ratePerIntensity = kNaN;
    config.rules[0].maxRate = kNaN;
    RawEmitter scene(std::move(config));
    scene.Slide(6.0f, 20);
    EXPECT_EQ(scene.Sparks().spawned, 0u);
    EXPECT_EQ(scene.emitter.EmissionCarry(0), 0.0f);
}

TEST(EmitterBounds, HugeBurstSpawnsAtMostThePool)
{
    for (float burst : {kHuge, kInf})
    {
        EffectsConfig config = SmallPool(DefaultPreset(), 32);
        config.rules[0].ratePerIntensity = 0.0f;
        config.rules[0].impactThreshold = 0.0f;
        config.rules[0].burstPerSpeed = burst;
        config.rules[0].burstMax = burst;
        RawEmitter scene(std::move(config));
        scene.box->SetTransform(b2Vec2(0.0f, 2.0f), 0.0f);
        scene.box->SetLinearVelocity(b2Vec2(0.0f, -5.0f));
        std::uint32_t mostInAStep = 0;
        for (int i = 0; i < 30; ++i)
        {
            scene.world->Step(kDt, 8, 3);
            scene.Emit();
            mostInAStep = std::max(mostInAStep, scene.Sparks().spawnedLastStep);
        }
        EXPECT_EQ(mostInAStep, 32u) << burst;
    }
}

TEST(EmitterBounds, OverflowingStartVelocityMakesNoParticle)
{
    EffectsConfig config = DefaultPreset();
    ParticleTypeDef& sparks = config.particleTypes[config.FindParticleType("sparks").index];
    sparks.inheritA = kHuge;
    sparks.inheritB = kHuge;
    sparks.slipFactor = kHuge;
    RawEmitter scene(std::move(config));
    scene.Slide(6.0f, 20);
    EXPECT_EQ(scene.Sparks().spawned, 0u);
    EXPECT_EQ(scene.particles.Count(), 0u);
    EXPECT_GT(scene.stats.nonFiniteSamples, 0u);
}

TEST(EmitterBounds, NonFiniteImpactMakesNoEvent)
{
    EffectsConfig config = DefaultPreset();
    config.rules[0].impactThreshold = 0.0f;
    config.rules[0].burstPerSpeed = 10.0f;
    RawEmitter scene(std::move(config));
    scene.box->SetTransform(b2Vec2(0.0f, 0.6f), 0.0f);
    scene.box->SetLinearVelocity(b2Vec2(0.0f, -3.0f));
    bool injected = false;
    for (int i = 0; i < 30 && !injected; ++i)
    {
        scene.world->Step(kDt, 8, 3);
        for (TrackedContact& tracked : scene.tracker.Contacts(RuleId{0}))
        {
            if (tracked.newTouch)
            {
                tracked.approachSpeed = kInf; // a body given an infinite velocity as it touched
                injected = true;
            }
        }
        scene.Emit();
        for (const EffectEvent& event : scene.events.Events())
        {
            EXPECT_NE(event.type, EffectEventType::impact);
            ExpectFinite(event);
        }
    }
    ASSERT_TRUE(injected);
    EXPECT_EQ(scene.Sparks().spawned, 0u);
    EXPECT_GE(scene.stats.nonFiniteSamples, 1u);
}

TEST(EffectsMisuse, NonFiniteBodyStateNeverReachesAnEvent)
{
    struct Corruption
    {
        const char* what;
        b2Vec2 velocity;
        float friction;
    };
    for (const Corruption& corruption : {Corruption{"infinite velocity", b2Vec2(kInf, 0.0f), 0.5f},
                                         Corruption{"NaN velocity", b2Vec2(kNaN, 0.0f), 0.5f},
                                         Corruption{"huge velocity", b2Vec2(kHuge, kHuge), 0.5f},
                                         Corruption{"NaN friction", b2Vec2(6.0f, 0.0f), kNaN},
                                         Corruption{"infinite friction", b2Vec2(6.0f, 0.0f), kInf}})
    {
        SCOPED_TRACE(corruption.what);
        // Particles that do not collide: what the particle step does with a body of non-finite state is
        // the particle system's business (its moving-body grid), not this test's.
        EffectsConfig config = DefaultPreset();
        for (ParticleTypeDef& type : config.particleTypes)
        {
            type.collide = false;
        }
        SlideScene scene(std::move(config));
        scene.Slide(6.0f, 20);
        const std::uint64_t sparks = scene.Spawned("sparks");
        ASSERT_GT(sparks, 0u);
        // After the world step, before effects look: the application's bug.
        scene.world->Step(kDt, 8, 3);
        scene.box->SetLinearVelocity(corruption.velocity);
        scene.box->GetFixtureList()->SetFriction(corruption.friction);
        scene.effects->Step(kDt);
        for (const EffectEvent& event : scene.effects->Events())
        {
            ExpectFinite(event);
        }
        EXPECT_TRUE(std::isfinite(scene.effects->Stats().rules[0].intensityMaxLastStep));
        EXPECT_EQ(scene.Spawned("sparks"), sparks) << "no particle from a non-finite sample";
        EXPECT_GE(scene.effects->Stats().nonFiniteSamples, 1u);
    }
}

} // namespace cfx::test
