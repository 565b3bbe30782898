// Spawn never inside: in piles and crevices, where no free start point exists near a contact, the
// particle is not spawned and is counted as rejected (issue 14, item 2).
#include "spawn_point.h"
#include "test_world.h"

#include <cmath>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

b2Body* StaticBox(b2World& world, b2Vec2 center, float halfWidth, float halfHeight, float angle = 0.0f)
{
    b2BodyDef def;
    b2Body* body = world.CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox(halfWidth, halfHeight, center, angle);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.friction = 0.8f;
    body->CreateFixture(&fixture);
    return body;
}

struct PileResult
{
    std::uint64_t sparks = 0;
    std::uint64_t inside = 0;
    std::uint64_t rejected = 0;
    std::uint64_t checked = 0; ///< starts checked independently (still particles only)
};

// Sparks that stay where they start: after a step, the newest particles' positions are their starts.
EffectsConfig StillSparks()
{
    EffectsConfig config = DefaultPreset();
    ParticleTypeDef& sparks = config.particleTypes[config.FindParticleType("sparks").index];
    sparks.spread = sparks.normalSpeed = sparks.slipFactor = sparks.gravityScale = 0.0f;
    sparks.collide = false;
    return config;
}

// An independent check of one start: points of the particle's disc (its centre and eight at 0.95 of its
// radius) tested against every solid fixture of the world with Box2D's own point test, and against the
// skin of polygons by their distance.
bool StartsInside(const b2World& world, b2Vec2 centre, float radius)
{
    for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
    {
        for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr;
             fixture = fixture->GetNext())
        {
            for (int around = 0; around <= 8; ++around)
            {
                const float angle = 0.785398f * static_cast<float>(around);
                const float reach = around == 8 ? 0.0f : 0.95f * radius;
                if (fixture->TestPoint(centre + reach * b2Vec2(std::cos(angle), std::sin(angle))))
                {
                    return true;
                }
            }
        }
    }
    return false;
}

// 200 steel boxes dropped onto a steep concrete ramp that ends at a concrete wall: they slide, tumble and
// pile up in the corner, boxes wedged against the contacts of others.
PileResult DropPile(EffectsConfig config, float hz, float seconds, bool checkStarts = false)
{
    TestWorld scene;
    b2Body* floor = scene.CreateGround(0.8f, 30.0f);
    const float angle = 0.75f; // rad, 43 degrees: steeper than steel on concrete holds (atan 0.63)
    b2Body* ramp = StaticBox(*scene.world, b2Vec2(-7.0f, 5.0f), 7.0f, 0.3f, -angle);
    b2Body* wall = StaticBox(*scene.world, b2Vec2(4.0f, 3.0f), 0.5f, 3.0f);
    std::vector<b2Body*> boxes;
    for (int i = 0; i < 200; ++i)
    {
        const int column = i % 20;
        const int row = i / 20;
        const float x = -12.0f + 0.45f * static_cast<float>(column) + 0.07f * static_cast<float>(row % 3);
        const float y = 19.0f + 0.6f * static_cast<float>(row) - 0.35f * static_cast<float>(column);
        boxes.push_back(scene.CreateBox(b2Vec2(x, y), 0.18f, 0.18f, 0.5f));
    }
    scene.particles.checkParticles = true; // audits every start (spawnedInsideSolid)
    Effects& fx = scene.Attach(std::move(config));
    const float radius = fx.Config().particleTypes[fx.Config().FindParticleType("sparks").index].radius;
    for (b2Body* body : {floor, ramp, wall})
    {
        fx.SetMaterial(body, fx.FindMaterial("concrete"));
    }
    for (b2Body* box : boxes)
    {
        fx.SetMaterial(box, fx.FindMaterial("steel"));
    }
    const float dt = 1.0f / hz;
    const int steps = static_cast<int>(std::lround(seconds * hz));
    PileResult result;
    for (int i = 0; i < steps; ++i)
    {
        scene.Step(dt);
        if (checkStarts)
        {
            const ParticleView view = fx.Particles();
            for (std::uint32_t k = view.count - fx.Stats().rules[0].spawnedLastStep; k < view.count; ++k)
            {
                const b2Vec2 centre(view.positionX[view.Slot(k)], view.positionY[view.Slot(k)]);
                EXPECT_FALSE(StartsInside(*scene.world, centre, radius)) << centre.x << ", " << centre.y;
                ++result.checked;
            }
        }
    }
    result.sparks = scene.Spawned("sparks");
    result.inside = fx.Stats().spawnedInsideSolid;
    result.rejected = fx.Stats().spawnRejected;
    return result;
}

// A steel block held in a slot: walls on both sides and a ceiling above leave gaps narrower than a spark,
// and a concrete slab runs under it at 8 m/s. The block rubs hard, but along the slab there is no place a
// spark fits within the search distance: under the block, or in the 5 mm under the walls.
PileResult Crevice(float hz)
{
    TestWorld scene;
    b2Body* slab = scene.CreateBox(b2Vec2(0.0f, -0.5f), 60.0f, 0.5f, 0.8f, b2_kinematicBody);
    slab->SetLinearVelocity(b2Vec2(8.0f, 0.0f));
    const float gap = 0.005f; // m between cores: less than a spark's diameter plus the skins
    b2Body* block = scene.CreateBox(b2Vec2(0.0f, 0.25f + gap), 0.5f, 0.25f, 0.5f);
    StaticBox(*scene.world, b2Vec2(-0.5f - 2.0f * gap - 2.0f, 0.5f + gap), 2.0f, 0.5f);  // left wall
    StaticBox(*scene.world, b2Vec2(0.5f + 2.0f * gap + 2.0f, 0.5f + gap), 2.0f, 0.5f);   // right wall
    StaticBox(*scene.world, b2Vec2(0.0f, 0.5f + 2.0f * gap + 0.02f + 0.5f), 0.6f, 0.5f); // ceiling
    scene.particles.checkParticles = true; // audits every start (spawnedInsideSolid)
    Effects& fx = scene.Attach();
    fx.SetMaterial(slab, fx.FindMaterial("concrete"));
    fx.SetMaterial(block, fx.FindMaterial("steel"));
    const float dt = 1.0f / hz;
    const int steps = static_cast<int>(std::lround(2.0f * hz));
    for (int i = 0; i < steps; ++i)
    {
        scene.Step(dt);
        // Keep the slab under the block.
        if (slab->GetPosition().x > 20.0f)
        {
            slab->SetTransform(b2Vec2(0.0f, -0.5f), 0.0f);
        }
    }
    PileResult result;
    result.sparks = scene.Spawned("sparks");
    result.inside = fx.Stats().spawnedInsideSolid;
    result.rejected = fx.Stats().spawnRejected;
    EXPECT_GT(fx.Stats().rules[0].intensityMaxLastStep, 3.0f) << "the block rubs hard";
    return result;
}

} // namespace

TEST(SpawnPile, DroppedBoxesNeverStartSparksInsideAndCrowdedContactsAreRejected)
{
    for (float hz : {30.0f, 60.0f, 120.0f})
    {
        SCOPED_TRACE(std::to_string(hz) + " Hz");
        const PileResult pile = DropPile(DefaultPreset(), hz, 6.0f);
        EXPECT_GT(pile.sparks, 1000u);
        EXPECT_EQ(pile.inside, 0u);
        EXPECT_GT(pile.rejected, 0u);
    }
}

TEST(SpawnPile, EveryStartInThePileIsOutsideByAnIndependentCheck)
{
    const PileResult pile = DropPile(StillSparks(), 30.0f, 6.0f, true);
    EXPECT_GT(pile.checked, 1000u);
    EXPECT_EQ(pile.inside, 0u);
    EXPECT_GT(pile.rejected, 0u);
}

TEST(SpawnPile, NoFreeStartInACreviceMeansNoSpark)
{
    for (float hz : {30.0f, 60.0f, 120.0f})
    {
        SCOPED_TRACE(std::to_string(hz) + " Hz");
        const PileResult crevice = Crevice(hz);
        EXPECT_EQ(crevice.sparks, 0u);
        EXPECT_EQ(crevice.inside, 0u);
        EXPECT_GT(crevice.rejected, static_cast<std::uint64_t>(100));
    }
}

// A large steel wheel landing hard on dirt: its gap to the ground is narrower than a dirt particle for more
// than a metre either side of the contact (a 7.7 m wheel lifts by 0.1 m only 1.2 m out), so a search of
// one metre found no start and its whole impact burst was rejected. The search reaches as far as the
// wheel does: the dirt starts at its rim, outside everything.
TEST(SpawnPile, ALargeWheelLandingThrowsItsDirtFromItsRim)
{
    for (float radius : {3.0f, 7.7f, 20.0f})
    {
        SCOPED_TRACE("radius " + std::to_string(radius));
        TestWorld scene;
        b2Body* ground = scene.CreateGround(0.6f, 100.0f);
        b2Body* wheel = scene.CreateCircle(b2Vec2(0.0f, radius + 0.3f), radius, 0.6f);
        wheel->SetLinearVelocity(b2Vec2(0.0f, -27.0f));
        scene.particles.checkParticles = true; // audits every start (spawnedInsideSolid)
        Effects& fx = scene.Attach();
        fx.SetMaterial(ground, fx.FindMaterial("dirt"));
        fx.SetMaterial(wheel, fx.FindMaterial("steel"));
        const float dirtRadius = fx.Config().particleTypes[fx.Config().FindParticleType("dirt").index].radius;
        std::uint64_t checked = 0;
        for (int i = 0; i < 30; ++i)
        {
            const std::uint32_t before = fx.Particles().count;
            scene.Step();
            const ParticleView view = fx.Particles();
            for (std::uint32_t k = std::min(before, view.count); k < view.count; ++k)
            {
                const b2Vec2 centre(view.positionX[view.Slot(k)], view.positionY[view.Slot(k)]);
                EXPECT_FALSE(StartsInside(*scene.world, centre, dirtRadius)) << centre.x << ", " << centre.y;
                ++checked;
            }
        }
        EXPECT_GT(scene.Spawned("dirt"), 20u);
        EXPECT_EQ(fx.Stats().spawnRejected, 0u);
        EXPECT_EQ(fx.Stats().spawnedInsideSolid, 0u);
        EXPECT_GT(checked, 0u);
    }
}

} // namespace cfx::test
