// Effects::Step is allocation-free once warmed up: this binary counts every operator new
// (allocation_counter.h), runs a scene that exercises every path of the emitter (contacts handed from chain
// segment to segment, body pairs coming and going, rate and burst emission, scrapes and impacts, rejected
// starts in a crevice), warms it up, and asks for zero allocations over the same motion again. Box2D
// allocates with b2Alloc (malloc), which this does not count; contactfx allocates only with new.
#include "allocation_counter.h"
#include "test_world.h"

#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

b2Body* StaticBox(b2World& world, b2Vec2 center, float halfWidth, float halfHeight)
{
    b2BodyDef def;
    b2Body* body = world.CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(halfWidth, halfHeight, center, 0.0f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.friction = 0.8f;
    body->CreateFixture(&fixture);
    return body;
}

} // namespace

TEST(EmissionAllocation, NoneOnceWarmedUp)
{
    TestWorld scene;
    b2BodyDef groundDef;
    b2Body* ground = scene.world->CreateBody(&groundDef);
    std::vector<b2Vec2> points;
    for (int i = 0; i <= 160; ++i)
    {
        points.emplace_back(40.0f - 0.5f * static_cast<float>(i), 0.0f); // right to left: front up
    }
    b2ChainShape chain;
    chain.CreateChain(points.data(), static_cast<int>(points.size()), b2Vec2(41.0f, 0.0f),
                      b2Vec2(-41.0f, 0.0f));
    b2FixtureDef groundFixture;
    groundFixture.shape = &chain;
    groundFixture.friction = 0.8f;
    ground->CreateFixture(&groundFixture);

    b2Body* slider = scene.CreateBox(b2Vec2(-10.0f, 0.25f), 0.5f, 0.25f, 0.5f);
    b2Body* dropped = scene.CreateBox(b2Vec2(10.0f, 2.0f), 0.3f, 0.3f, 0.5f);
    b2Body* wheel = scene.CreateCircle(b2Vec2(20.0f, 0.4f), 0.4f, 0.9f);
    // A block held in a slot over a concrete slab running under it: walls 5 mm above the slab on both
    // sides leave no room for a spark, so its starts are rejected.
    b2BodyDef slabDef;
    slabDef.type = b2_kinematicBody;
    slabDef.position = b2Vec2(0.0f, -20.5f);
    b2Body* slab = scene.world->CreateBody(&slabDef);
    b2PolygonShape slabShape;
    slabShape.SetAsBox(30.0f, 0.5f);
    b2FixtureDef slabFixture;
    slabFixture.shape = &slabShape;
    slabFixture.friction = 0.8f;
    slab->CreateFixture(&slabFixture);
    b2Body* wedged = scene.CreateBox(b2Vec2(0.0f, -19.745f), 0.5f, 0.25f, 0.5f);
    StaticBox(*scene.world, b2Vec2(-2.51f, -19.495f), 2.0f, 0.5f);
    StaticBox(*scene.world, b2Vec2(2.51f, -19.495f), 2.0f, 0.5f);

    Effects& fx = scene.Attach();
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(slab, fx.FindMaterial("concrete"));
    for (b2Body* body : {slider, dropped, wedged})
    {
        fx.SetMaterial(body, fx.FindMaterial("steel"));
    }
    fx.SetMaterial(wheel, fx.FindMaterial("rubber"));

    int step = 0;
    auto run = [&](int steps)
    {
        for (int i = 0; i < steps; ++i, ++step)
        {
            const int phase = step % 120; // a 2 s cycle, repeated the same way
            slider->SetLinearVelocity(b2Vec2(phase < 60 ? 8.0f : -8.0f, slider->GetLinearVelocity().y));
            slider->SetAngularVelocity(0.0f);
            slab->SetLinearVelocity(b2Vec2(phase < 60 ? 6.0f : -6.0f, 0.0f));
            wheel->SetAngularVelocity(-25.0f);
            wheel->SetLinearVelocity(b2Vec2(0.0f, wheel->GetLinearVelocity().y));
            if (phase == 0)
            {
                dropped->SetTransform(b2Vec2(10.0f, 2.0f), 0.0f);
                dropped->SetLinearVelocity(b2Vec2(3.0f, 0.0f));
                dropped->SetAngularVelocity(0.0f);
                dropped->SetAwake(true);
            }
            scene.Step();
        }
    };
    run(480);
    const EffectsStats& stats = fx.Stats();
    ASSERT_GT(stats.spawnedByType[fx.Config().FindParticleType("sparks").index], 100u);
    ASSERT_GT(stats.spawnedByType[fx.Config().FindParticleType("smoke").index], 100u);
    ASSERT_GT(stats.spawnRejected, 0u);
    ASSERT_GE(stats.rules[0].contactsMax, 3u);

    const std::uint64_t rejectedBefore = stats.spawnRejected;
    const long before = Allocations();
    run(480);
    EXPECT_EQ(Allocations() - before, 0) << "allocations in 480 warmed-up steps";
    EXPECT_GT(stats.spawnRejected, rejectedBefore);
}

// budget.contacts is room for each rule: two rules, each touching fewer contacts than it at once but more
// than it together, allocate nothing from the first step on (the shared index, body pairs, events and the
// emitter's lists were once sized for budget.contacts in all).
TEST(EmissionAllocation, TheContactBudgetIsForEachRule)
{
    b2World world(b2Vec2(0.0f, -10.0f));
    EffectsConfig config;
    config.materials = {"ground", "steel", "rubber"};
    ParticleTypeDef type;
    type.name = "p";
    config.particleTypes = {type};
    RuleDef steel;
    steel.materialA = "steel";
    steel.materialB = "ground";
    steel.particleType = "p";
    steel.threshold = 1.0e6f; // contacts tracked, nothing emitted
    RuleDef rubber = steel;
    rubber.materialA = "rubber";
    config.rules = {steel, rubber};
    config.budget.contacts = 64;
    const long beforeEffects = Allocations();
    Effects fx(world, EffectsDef{config});
    ASSERT_GT(Allocations(), beforeEffects);
    b2BodyDef groundDef;
    b2Body* ground = world.CreateBody(&groundDef);
    b2PolygonShape groundShape;
    groundShape.SetAsBox(500.0f, 0.5f);
    fx.SetMaterial(ground->CreateFixture(&groundShape, 0.0f), fx.FindMaterial("ground"));
    const int perRule = 60; // of 64; 120 in all
    for (int i = 0; i < 2 * perRule; ++i)
    {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(-400.0f + 3.0f * static_cast<float>(i), 0.9f);
        b2Body* body = world.CreateBody(&def);
        b2PolygonShape box;
        box.SetAsBox(0.4f, 0.4f);
        fx.SetMaterial(body->CreateFixture(&box, 1.0f), fx.FindMaterial(i % 2 == 0 ? "steel" : "rubber"));
    }
    const long before = Allocations();
    for (int step = 0; step < 30; ++step)
    {
        world.Step(1.0f / 60.0f, 8, 3);
        fx.Step(1.0f / 60.0f);
    }
    EXPECT_EQ(Allocations() - before, 0) << "allocations in the first 30 steps";
    // Each box's two corner points are contacts of one body pair: one contact each.
    EXPECT_EQ(fx.Stats().rules[0].contactsMax, static_cast<std::uint32_t>(perRule));
    EXPECT_EQ(fx.Stats().rules[1].contactsMax, static_cast<std::uint32_t>(perRule));
}

} // namespace cfx::test
