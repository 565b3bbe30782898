#include "spawn_point.h"
#include "test_world.h"

#include <cmath>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

// Particles that stay where they start: their positions after a step are their spawn points.
EffectsConfig StillParticles()
{
    EffectsConfig config = OneRule("steel", "concrete");
    ParticleTypeDef& sparks = config.particleTypes[config.FindParticleType("sparks").index];
    sparks.spread = 0.0f;
    sparks.normalSpeed = 0.0f;
    sparks.slipFactor = 0.0f;
    sparks.gravityScale = 0.0f;
    sparks.collide = false;
    config.rules[0].threshold = 0.2f;
    return config;
}

// Whether `point` is on the solid side of (or inside) a fixture, tested shape by shape.
bool InsideOrBehind(const b2Fixture* fixture, b2Vec2 point)
{
    const b2Shape* shape = fixture->GetShape();
    const b2Transform& xf = fixture->GetBody()->GetTransform();
    if (shape->GetType() == b2Shape::e_circle || shape->GetType() == b2Shape::e_polygon)
    {
        return fixture->TestPoint(point);
    }
    // Edges and chains: the side of the nearest child edge decides.
    float nearest = 1e30f;
    bool behind = false;
    for (int child = 0; child < shape->GetChildCount(); ++child)
    {
        b2EdgeShape edge;
        if (shape->GetType() == b2Shape::e_chain)
        {
            static_cast<const b2ChainShape*>(shape)->GetChildEdge(&edge, child);
        }
        else
        {
            edge = *static_cast<const b2EdgeShape*>(shape);
        }
        b2Vec2 v1 = b2Mul(xf, edge.m_vertex1);
        b2Vec2 v2 = b2Mul(xf, edge.m_vertex2);
        b2Vec2 e = v2 - v1;
        float along = b2Clamp(b2Dot(point - v1, e) / e.LengthSquared(), 0.0f, 1.0f);
        float distance = b2Distance(point, v1 + along * e);
        if (distance < nearest)
        {
            nearest = distance;
            b2Vec2 front(e.y, -e.x); // Box2D's one-sided edges collide on their right side
            behind = edge.m_oneSided && b2Dot(point - v1, front) < 0.0f;
        }
    }
    return behind;
}

// Slides `mover` over `surface` and checks every start point against both fixtures.
void ExpectSpawnsOutside(TestWorld& scene, b2Body* surface, b2Body* mover, b2Vec2 velocity,
                         float angularVelocity = 0.0f)
{
    scene.particles.checkParticles = true; // audits every start (spawnedInsideSolid)
    Effects& fx = scene.Attach(StillParticles());
    const float radius = fx.Config().particleTypes[fx.Config().FindParticleType("sparks").index].radius;
    fx.SetMaterial(surface, fx.FindMaterial("concrete"));
    fx.SetMaterial(mover, fx.FindMaterial("steel"));
    std::uint32_t checked = 0;
    for (int i = 0; i < 90; ++i)
    {
        mover->SetLinearVelocity(b2Vec2(velocity.x, mover->GetLinearVelocity().y + velocity.y));
        mover->SetAngularVelocity(angularVelocity);
        scene.Step();
        // The particles started this step: the newest ones (the mover has not moved since).
        ParticleView view = fx.Particles();
        for (std::uint32_t k = view.count - fx.Stats().rules[0].spawnedLastStep; k < view.count; ++k)
        {
            // The particle's whole disc, not only its centre, starts outside both shapes.
            const b2Vec2 centre(view.positionX[view.Slot(k)], view.positionY[view.Slot(k)]);
            for (int around = 0; around <= 8; ++around)
            {
                const float angle = 0.785398f * static_cast<float>(around);
                const float reach = around == 8 ? 0.0f : 0.9f * radius;
                const b2Vec2 p = centre + reach * b2Vec2(std::cos(angle), std::sin(angle));
                ASSERT_FALSE(InsideOrBehind(surface->GetFixtureList(), p))
                    << "in the surface at " << p.x << "," << p.y;
                ASSERT_FALSE(InsideOrBehind(mover->GetFixtureList(), p))
                    << "in the mover at " << p.x << "," << p.y;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 20u);
    EXPECT_EQ(fx.Stats().spawnedInsideSolid, 0u);
}

b2Body* StaticBodyWith(b2World& world, const b2Shape& shape)
{
    b2BodyDef def;
    b2Body* body = world.CreateBody(&def);
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.friction = 0.8f;
    body->CreateFixture(&fixture);
    return body;
}

} // namespace

TEST(Spawn, PolygonOnPolygon)
{
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    ExpectSpawnsOutside(scene, ground, box, b2Vec2(4.0f, 0.0f));
}

TEST(Spawn, CircleOnPolygon)
{
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* wheel = scene.CreateCircle(b2Vec2(0.0f, 0.4f), 0.4f, 0.5f);
    ExpectSpawnsOutside(scene, ground, wheel, b2Vec2(0.0f, 0.0f), -20.0f);
}

TEST(Spawn, PolygonOnCircle)
{
    TestWorld scene;
    b2CircleShape circle;
    circle.m_radius = 3.0f;
    b2Body* drum = StaticBodyWith(*scene.world, circle);
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 3.25f), 0.25f, 0.25f, 0.5f);
    ExpectSpawnsOutside(scene, drum, box, b2Vec2(3.0f, 0.0f));
}

TEST(Spawn, PolygonOnTwoSidedEdge)
{
    TestWorld scene;
    b2EdgeShape edge;
    edge.SetTwoSided(b2Vec2(-40.0f, 0.0f), b2Vec2(40.0f, 0.0f));
    b2Body* ground = StaticBodyWith(*scene.world, edge);
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    ExpectSpawnsOutside(scene, ground, box, b2Vec2(4.0f, 0.0f));
}

TEST(Spawn, PolygonOnOneSidedEdge)
{
    TestWorld scene;
    b2EdgeShape edge;
    // Right side of v1 -> v2 is the front: v1 right of v2 makes the front face up.
    edge.SetOneSided(b2Vec2(50.0f, 0.0f), b2Vec2(40.0f, 0.0f), b2Vec2(-40.0f, 0.0f), b2Vec2(-50.0f, 0.0f));
    b2Body* ground = StaticBodyWith(*scene.world, edge);
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    ExpectSpawnsOutside(scene, ground, box, b2Vec2(4.0f, 0.0f));
}

TEST(Spawn, CircleOnOpenChain)
{
    TestWorld scene;
    std::vector<b2Vec2> points;
    for (int i = 0; i <= 40; ++i)
    {
        float x = 40.0f - 2.0f * static_cast<float>(i); // right to left: front faces up
        points.emplace_back(x, 0.3f * std::sin(0.2f * x));
    }
    b2ChainShape chain;
    chain.CreateChain(points.data(), static_cast<int>(points.size()), b2Vec2(42.0f, 0.0f),
                      b2Vec2(-42.0f, 0.0f));
    b2Body* ground = StaticBodyWith(*scene.world, chain);
    b2Body* wheel = scene.CreateCircle(b2Vec2(0.0f, 0.8f), 0.4f, 0.5f);
    ExpectSpawnsOutside(scene, ground, wheel, b2Vec2(3.0f, 0.0f), -20.0f);
}

TEST(Spawn, PolygonOnChainLoop)
{
    TestWorld scene;
    b2Vec2 square[4] = {b2Vec2(-20.0f, -2.0f), b2Vec2(20.0f, -2.0f), b2Vec2(20.0f, 0.0f),
                        b2Vec2(-20.0f, 0.0f)};
    b2ChainShape loop;
    loop.CreateLoop(square, 4); // counter-clockwise: the front is outside
    b2Body* ground = StaticBodyWith(*scene.world, loop);
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    ExpectSpawnsOutside(scene, ground, box, b2Vec2(4.0f, 0.0f));
}

TEST(Spawn, TutorialDropLandsOnTheHighestStaticFixture)
{
    TestWorld scene;
    scene.CreateGround();
    scene.CreateBox(b2Vec2(5.0f, 2.0f), 1.0f, 1.0f, 0.5f, b2_staticBody);
    SpawnPoint onBlock = TutorialDropPoint(*scene.world, b2Vec2(5.0f, 0.0f));
    EXPECT_TRUE(onBlock.outside);
    EXPECT_NEAR(onBlock.position.y, 3.05f, 1e-4f);
    SpawnPoint onGround = TutorialDropPoint(*scene.world, b2Vec2(0.0f, 0.3f));
    EXPECT_NEAR(onGround.position.y, 0.05f, 1e-4f);
}

TEST(Spawn, InsideMeansTheDiscOverlapsOrIsBehindAOneSidedEdge)
{
    TestWorld scene;
    scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f, b2_staticBody);
    // A disc whose centre is outside the box but whose rim (or the box's skin) reaches it is inside.
    EXPECT_FALSE(DiscIsClear(*scene.world, b2Vec2(0.515f, 0.5f), 0.01f, Solids{}));
    EXPECT_TRUE(DiscIsClear(*scene.world, b2Vec2(0.53f, 0.5f), 0.01f, Solids{}));

    // One-sided edge facing up at y = -5 (right of v1 -> v2): below it is inside even where the disc does
    // not touch the edge; a two-sided edge has no inside.
    b2EdgeShape oneSided;
    oneSided.SetOneSided(b2Vec2(12.0f, -5.0f), b2Vec2(10.0f, -5.0f), b2Vec2(6.0f, -5.0f),
                         b2Vec2(4.0f, -5.0f));
    StaticBodyWith(*scene.world, oneSided);
    EXPECT_TRUE(DiscIsClear(*scene.world, b2Vec2(8.0f, -4.95f), 0.01f, Solids{}));
    EXPECT_FALSE(DiscIsClear(*scene.world, b2Vec2(8.0f, -5.06f), 0.01f, Solids{})) << "behind";
    b2EdgeShape twoSided;
    twoSided.SetTwoSided(b2Vec2(10.0f, -8.0f), b2Vec2(6.0f, -8.0f));
    StaticBodyWith(*scene.world, twoSided);
    EXPECT_TRUE(DiscIsClear(*scene.world, b2Vec2(8.0f, -8.06f), 0.01f, Solids{}));
}

// The start audit (EffectsStats::spawnedInsideSolid) is Box2D's own overlap test, skins included, and
// skips sensors and ignored bodies.
TEST(Spawn, AuditFindsDiscsOverlappingSolidsByBox2DsOwnTest)
{
    TestWorld scene;
    b2Body* box = scene.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f, b2_staticBody);
    EXPECT_TRUE(DiscOverlapsSolid(*scene.world, b2Vec2(0.0f, 0.5f), 0.01f, Solids{})) << "centre inside";
    EXPECT_TRUE(DiscOverlapsSolid(*scene.world, b2Vec2(0.509f, 0.5f), 0.01f, Solids{})) << "rim in the core";
    EXPECT_TRUE(DiscOverlapsSolid(*scene.world, b2Vec2(0.5145f, 0.5f), 0.01f, Solids{})) << "rim in the skin";
    EXPECT_FALSE(DiscOverlapsSolid(*scene.world, b2Vec2(0.53f, 0.5f), 0.01f, Solids{}));
    // Touching is not overlapping: the disc's rim 1 micrometre off the skin, or 5 micrometres into it.
    EXPECT_FALSE(DiscOverlapsSolid(*scene.world, b2Vec2(0.520001f, 0.5f), 0.01f, Solids{}));
    EXPECT_FALSE(DiscOverlapsSolid(*scene.world, b2Vec2(0.519995f, 0.5f), 0.01f, Solids{}));
    EXPECT_TRUE(DiscOverlapsSolid(*scene.world, b2Vec2(0.51998f, 0.5f), 0.01f, Solids{}));
    EXPECT_FALSE(DiscOverlapsSolid(*scene.world, b2Vec2(3.0f, 3.0f), 0.01f, Solids{}));

    struct IgnoreBody final : BodyFilter
    {
        const b2Body* body;
        bool Ignore(const b2Body* candidate) const override { return candidate == body; }
    } ignoreBox;
    ignoreBox.body = box;
    EXPECT_FALSE(DiscOverlapsSolid(*scene.world, b2Vec2(0.0f, 0.5f), 0.01f, Solids{&ignoreBox}));
    box->GetFixtureList()->SetSensor(true);
    EXPECT_FALSE(DiscOverlapsSolid(*scene.world, b2Vec2(0.0f, 0.5f), 0.01f, Solids{})) << "a sensor";
}

TEST(Spawn, BehindAChainIsDecidedAtItsCornersToo)
{
    // A chain with a peak at (0, 1) and a valley at (4, 0), front up (listed right to left).
    TestWorld scene;
    b2Vec2 points[] = {b2Vec2(8.0f, 1.0f), b2Vec2(4.0f, 0.0f), b2Vec2(0.0f, 1.0f), b2Vec2(-4.0f, 0.0f)};
    b2ChainShape chain;
    chain.CreateChain(points, 4, b2Vec2(9.0f, 1.0f), b2Vec2(-5.0f, 0.0f));
    StaticBodyWith(*scene.world, chain);
    const float r = 0.01f;
    // Peak (convex): beside and above it is outside, just under it inside.
    EXPECT_TRUE(DiscIsClear(*scene.world, b2Vec2(0.0f, 1.05f), r, Solids{}));
    EXPECT_TRUE(DiscIsClear(*scene.world, b2Vec2(0.04f, 1.04f), r, Solids{}));
    EXPECT_TRUE(DiscIsClear(*scene.world, b2Vec2(-0.04f, 1.04f), r, Solids{}));
    EXPECT_FALSE(DiscIsClear(*scene.world, b2Vec2(0.0f, 0.95f), r, Solids{}));
    // Valley (concave): above it is outside, under it inside.
    EXPECT_TRUE(DiscIsClear(*scene.world, b2Vec2(4.0f, 0.06f), r, Solids{}));
    EXPECT_FALSE(DiscIsClear(*scene.world, b2Vec2(4.0f, -0.06f), r, Solids{}));
    EXPECT_FALSE(DiscIsClear(*scene.world, b2Vec2(4.05f, -0.03f), r, Solids{}));
}

TEST(Spawn, TutorialDropStepsAsideFromWhatStandsOnTheContact)
{
    TestWorld scene;
    scene.CreateGround();
    const b2Body* wheel = scene.CreateCircle(b2Vec2(0.0f, 0.4f), 0.4f, 0.9f);
    // The tutorial's own drop, 0.05 m above the ground under the wheel's contact, is inside the wheel.
    const SpawnPoint tutorial = TutorialDropPoint(*scene.world, b2Vec2(0.0f, 0.0f));
    ASSERT_TRUE(tutorial.outside);
    EXPECT_FALSE(DiscIsClear(*scene.world, tutorial.position, 0.01f, Solids{}));
    SpawnQuery query;
    query.point = b2Vec2(0.0f, 0.0f);
    query.leaving = b2Vec2(5.0f, 0.0f); // the particles go toward +x: that side first
    query.otherBody = wheel;            // the walk goes on past starts inside the wheel
    query.radius = 0.01f;
    const SpawnPoint drop = FindTutorialDropPoint(*scene.world, query, Solids{});
    ASSERT_TRUE(drop.outside);
    EXPECT_NEAR(drop.position.y, 0.05f, 1e-4f) << "still the tutorial's height over the ground";
    EXPECT_GT(drop.position.x, 0.2f) << "beside the wheel, on the side the particles leave to";
    EXPECT_LT(drop.position.x, 0.5f);
    EXPECT_TRUE(DiscIsClear(*scene.world, drop.position, 0.01f, Solids{}));
}

// The tutorial's car and wheels are filtered so that its particles pass through them (mask 0xFFFD against
// the particles' category 2), and its drop lands inside the wheel. The tutorial preset does the same: a
// trial measured all 781 of the demo's starts moved beside the wheels or the body, by up to 1 m.
TEST(Spawn, TheTutorialDropStartsInsideAWheelItsParticlesPassThrough)
{
    TestWorld scene;
    scene.CreateGround();
    b2Body* wheel = scene.CreateCircle(b2Vec2(0.0f, 0.4f), 0.4f, 0.9f);
    b2Filter tutorialCar;
    tutorialCar.maskBits = 0xFFFD;
    wheel->GetFixtureList()->SetFilterData(tutorialCar);
    SpawnQuery query;
    query.point = b2Vec2(0.0f, 0.0f);
    query.leaving = b2Vec2(5.0f, 0.0f);
    query.otherBody = wheel;
    query.radius = 0.01f;
    Solids tutorialParticles{nullptr, 0x0002, 0x0001};
    const SpawnPoint beside = FindTutorialDropPoint(*scene.world, query, tutorialParticles);
    ASSERT_TRUE(beside.outside);
    EXPECT_GT(beside.position.x, 0.2f) << "kept out of the contact's other body whatever the filter";
    tutorialParticles.otherBodyWhateverFilter = false;
    const SpawnPoint drop = FindTutorialDropPoint(*scene.world, query, tutorialParticles);
    ASSERT_TRUE(drop.outside);
    EXPECT_EQ(drop.position.x, 0.0f);
    EXPECT_NEAR(drop.position.y, 0.05f, 1e-6f);

    // Through the preset: every smoke particle of a wheel spinning in place starts under its contact.
    scene.particles.checkParticles = true;
    Effects& fx = scene.Attach(TutorialPreset());
    fx.SetMaterial(scene.world->GetBodyList()->GetNext(), fx.FindMaterial("concrete")); // the ground
    fx.SetMaterial(wheel, fx.FindMaterial("rubber"));
    int starts = 0;
    for (int i = 0; i < 60; ++i)
    {
        wheel->SetAngularVelocity(-25.0f);
        wheel->SetLinearVelocity(b2Vec2(0.0f, wheel->GetLinearVelocity().y));
        scene.Step();
        const ParticleView view = fx.Particles();
        for (std::uint32_t k = view.count - fx.Stats().rules[1].spawnedLastStep; k < view.count; ++k)
        {
            EXPECT_NEAR(view.positionX[view.Slot(k)], wheel->GetPosition().x, 0.01f) << "step " << i;
            EXPECT_NEAR(view.positionY[view.Slot(k)], 0.05f, 1e-4f) << "step " << i;
            ++starts;
        }
    }
    EXPECT_GE(starts, 55);
    EXPECT_EQ(fx.Stats().spawnedInsideSolid, 0u) << "the wheel is not solid to these particles";
    EXPECT_EQ(fx.Stats().spawnRejected, 0u);
}

TEST(Spawn, TutorialPresetDropsNothingInsideTheWheelOrTheBox)
{
    // The tutorial preset on a wheel spinning in place and a box sliding: the same one particle per
    // contact per step, none started inside.
    TestWorld scene;
    b2Body* ground = scene.CreateGround();
    b2Body* wheel = scene.CreateCircle(b2Vec2(0.0f, 0.4f), 0.4f, 0.9f);
    b2Body* box = scene.CreateBox(b2Vec2(-10.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    scene.particles.checkParticles = true; // audits every start (spawnedInsideSolid)
    Effects& fx = scene.Attach(TutorialPreset());
    fx.SetMaterial(ground, fx.FindMaterial("concrete"));
    fx.SetMaterial(wheel, fx.FindMaterial("rubber"));
    fx.SetMaterial(box, fx.FindMaterial("steel"));
    for (int i = 0; i < 120; ++i)
    {
        wheel->SetAngularVelocity(-25.0f);
        wheel->SetLinearVelocity(b2Vec2(0.0f, wheel->GetLinearVelocity().y));
        box->SetLinearVelocity(b2Vec2(4.0f, box->GetLinearVelocity().y));
        scene.Step();
    }
    EXPECT_GE(scene.Spawned("smoke"), 115u);
    EXPECT_GE(scene.Spawned("sparks"), 115u);
    EXPECT_EQ(fx.Stats().spawnedInsideSolid, 0u);
    EXPECT_EQ(fx.Stats().spawnRejected, 0u);
}

// A fixture the particles never collide with is not solid to their starts: a trial laid a static background
// fixture (decoration, a water zone) filtered to meet no spark over a slide, and every spark was refused
// (458 of 458). A steel box slides on concrete under a static box that the sparks' filter excludes, in two
// ways (a mask that takes nothing, a category the sparks' mask leaves out): it emits as it does without
// the box, none of it inside anything the sparks collide with.
TEST(Spawn, FixturesTheParticlesDoNotCollideWithCloseNoStart)
{
    const auto slide = [](int background)
    {
        TestWorld scene;
        scene.particles.checkParticles = true;
        b2Body* ground = scene.CreateGround();
        if (background > 0)
        {
            b2Body* decoration = scene.CreateBox(b2Vec2(0.0f, 1.0f), 20.0f, 2.0f, 0.5f, b2_staticBody);
            b2Filter filter;
            filter.categoryBits = background == 1 ? 0x0001 : 0x8000;
            filter.maskBits = background == 1 ? 0x0000 : 0x8000;
            decoration->GetFixtureList()->SetFilterData(filter);
        }
        b2Body* box = scene.CreateBox(b2Vec2(-5.0f, 0.25f), 0.5f, 0.25f, 0.6f);
        Effects& fx = scene.Attach();
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(box, fx.FindMaterial("steel"));
        box->SetLinearVelocity(b2Vec2(10.0f, 0.0f));
        for (int i = 0; i < 60; ++i)
        {
            scene.Step();
        }
        EXPECT_EQ(fx.Stats().spawnRejected, 0u) << "background " << background;
        EXPECT_EQ(fx.Stats().spawnedInsideSolid, 0u) << "background " << background;
        EXPECT_EQ(fx.Stats().particleStepsInside, 0u) << "background " << background;
        return scene.Spawned("sparks");
    };
    const std::uint64_t alone = slide(0);
    EXPECT_GT(alone, 100u);
    EXPECT_EQ(slide(1), alone) << "a background whose mask takes nothing";
    EXPECT_EQ(slide(2), alone) << "a background of a category the sparks leave out";
}

} // namespace cfx::test
