// The drawing layer (contactfx/draw/) without a backend: a world, its particles and a camera become the
// expected primitives, in palette colours, where the camera puts them.
#include "contactfx/draw/frame_builder.h"
#include "contactfx/effects.h"
#include "contactfx/presets.h"
#include "dirt_slide.h"
#include "test_world.h"

#include <box2d/b2_polygon_shape.h>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

Color Shaded(const b2Color& color, float shade)
{
    return Color{color.r * shade, color.g * shade, color.b * shade, color.a};
}

Color Full(const b2Color& color)
{
    return Color{color.r, color.g, color.b, color.a};
}

b2Color PaletteColor(const std::string& material)
{
    for (const ShapePalette::Entry& entry : TutorialPalette().materials)
    {
        if (entry.material == material)
        {
            return entry.color;
        }
    }
    ADD_FAILURE() << material << " not in the palette";
    return b2Color(0.0f, 0.0f, 0.0f, 1.0f); // b2Color() leaves its members uninitialised
}

// The world corners of a body's one polygon fixture.
std::vector<b2Vec2> Corners(const b2Body& body)
{
    const auto& polygon = *static_cast<const b2PolygonShape*>(body.GetFixtureList()->GetShape());
    std::vector<b2Vec2> corners;
    for (int32 i = 0; i < polygon.m_count; ++i)
    {
        corners.push_back(b2Mul(body.GetTransform(), polygon.m_vertices[i]));
    }
    return corners;
}

std::vector<b2Vec2> Points(const DrawList& list, const ShapeCommand& shape)
{
    return {list.vertices.begin() + shape.first, list.vertices.begin() + shape.first + shape.count};
}

void ExpectPoints(const std::vector<b2Vec2>& actual, const std::vector<b2Vec2>& expected)
{
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < actual.size(); ++i)
    {
        EXPECT_EQ(actual[i].x, expected[i].x) << i;
        EXPECT_EQ(actual[i].y, expected[i].y) << i;
    }
}

struct DrawFixture : ::testing::Test
{
    DrawFixture()
    {
        ground = world.CreateGround();
        crate = world.CreateBox(b2Vec2(-3.0f, 2.0f), 0.5f, 0.5f, 0.5f); // no material
        world.Attach();
        world.effects->SetMaterial(ground, world.effects->FindMaterial("concrete"));
    }

    TestWorld world;
    b2Body* ground = nullptr;
    b2Body* crate = nullptr;
    Camera camera = MakeCamera(200, 100, 20.0f, b2Vec2(1.0f, 2.0f));
    FrameScratch scratch;
};

} // namespace

TEST_F(DrawFixture, TheGroundIsOutlinedThenFilledAndWhatMovesIsSolidInPaletteColours)
{
    FrameOptions options;
    options.overlay = false;
    const DrawList& list = BuildFrame(*world.effects, 0.0f, camera, options, scratch);
    const DrawStyle& style = options.style;

    EXPECT_EQ(list.camera.center.x, camera.center.x);
    EXPECT_EQ(list.camera.pixelsPerMetre, camera.pixelsPerMetre);
    EXPECT_EQ(list.background, style.background);
    ASSERT_EQ(list.shapes.size(), 3u);
    const b2Color concrete = PaletteColor("concrete");

    const ShapeCommand& outline = list.shapes[0];
    EXPECT_EQ(outline.kind, ShapeKind::polygon);
    EXPECT_FALSE(outline.filled);
    EXPECT_EQ(outline.stroke, Full(concrete));
    EXPECT_EQ(outline.strokeWidth, 2.0f * style.outlineWidth + 1.0f);
    ExpectPoints(Points(list, outline), Corners(*ground));

    const ShapeCommand& fill = list.shapes[1];
    EXPECT_TRUE(fill.filled);
    EXPECT_EQ(fill.fill, Shaded(concrete, style.fillShade));
    EXPECT_EQ(fill.stroke, fill.fill) << "widened by a stroke of its own colour";
    EXPECT_EQ(fill.strokeWidth, 1.0f);
    ExpectPoints(Points(list, fill), Corners(*ground));

    const ShapeCommand& box = list.shapes[2];
    const b2Color dynamic = TutorialPalette().dynamicBody; // no material: by body type
    EXPECT_TRUE(box.filled);
    EXPECT_EQ(box.fill, Shaded(dynamic, style.fillShade));
    EXPECT_EQ(box.stroke, Full(dynamic));
    EXPECT_EQ(box.strokeWidth, style.outlineWidth);
    ExpectPoints(Points(list, box), Corners(*crate));
    EXPECT_TRUE(list.sprites.empty());
    EXPECT_FALSE(list.overlay.shown);
}

// The tutorial preset's particles are Box2D bodies: they are drawn as particles (sprites), never also as
// shapes in the body-type colour (--hide-particles hid the sprites and left those).
TEST(DrawShapes, BodyBackedParticlesAreNotDrawnAsShapes)
{
    TestWorld world;
    b2Body* ground = world.CreateGround();
    b2Body* crate = world.CreateBox(b2Vec2(0.0f, 0.5f), 0.5f, 0.5f, 0.5f);
    world.Attach(TutorialPreset());
    SlideRubberOverDirt(world, ground, crate);
    int particleBodies = 0;
    for (const b2Body* body = world.world->GetBodyList(); body != nullptr; body = body->GetNext())
    {
        particleBodies += world.effects->IsParticleBody(body) ? 1 : 0;
    }
    ASSERT_GT(particleBodies, 0);

    const Camera camera = MakeCamera(200, 100, 20.0f, b2Vec2(0.0f, 0.0f));
    FrameScratch scratch;
    FrameOptions options;
    options.overlay = false;
    const DrawList& list = BuildFrame(*world.effects, 0.0f, camera, options, scratch);
    for (const ShapeCommand& shape : list.shapes)
    {
        EXPECT_NE(shape.kind, ShapeKind::circle) << "a particle's body drawn as a shape";
    }
    EXPECT_EQ(list.shapes.size(), 3u) << "the ground's outline and fill, the crate";
    EXPECT_FALSE(list.sprites.empty()) << "the particles, as particles";
}

TEST_F(DrawFixture, ASolidCircleHasASpokeOnlyWhenSolidAndFillsSkipWhatIsOpen)
{
    DrawList list;
    list.Begin(camera, DrawStyle{}.background);
    const DrawStyle style;
    ShapeRecorder recorder(list, style);
    const b2Color red(1.0f, 0.0f, 0.0f);
    const b2Vec2 center(1.0f, 2.0f);
    recorder.DrawSolidCircle(center, 0.5f, b2Vec2(0.0f, 1.0f), red);
    ASSERT_EQ(list.shapes.size(), 2u);
    EXPECT_EQ(list.shapes[0].kind, ShapeKind::circle);
    EXPECT_EQ(list.shapes[0].radius, 0.5f);
    ExpectPoints(Points(list, list.shapes[0]), {center});
    EXPECT_EQ(list.shapes[1].kind, ShapeKind::segment);
    ExpectPoints(Points(list, list.shapes[1]), {center, center + 0.5f * b2Vec2(0.0f, 1.0f)});

    recorder.SetPass(ShapePass::fills);
    recorder.DrawSolidCircle(center, 0.5f, b2Vec2(0.0f, 1.0f), red);
    recorder.DrawSegment(center, b2Vec2(3.0f, 3.0f), red);
    recorder.DrawCircle(center, 0.5f, red);
    ASSERT_EQ(list.shapes.size(), 3u) << "only the filled circle";
    EXPECT_TRUE(list.shapes[2].filled);
}

TEST_F(DrawFixture, SpritesArePlacedInPixelsByTheCameraAndOffImageOnesAreLeftOut)
{
    DrawList list;
    list.Begin(camera, DrawStyle{}.background);
    DrawStyle style;
    ParticleSprite smoke;
    smoke.position = b2Vec2(2.0f, 3.0f);
    smoke.size = 0.5f;
    smoke.color = Color{0.5f, 0.5f, 0.5f, 0.8f};
    ParticleSprite spark = smoke;
    spark.position = b2Vec2(0.0f, 1.0f);
    spark.velocity = b2Vec2(4.0f, -2.0f);
    spark.streak = 0.05f;
    spark.size = 0.001f; // below the smallest size
    ParticleSprite far = smoke;
    far.position = b2Vec2(500.0f, 2.0f);
    ParticleSprite invisible = smoke;
    invisible.color.a = 0.0f;
    const ParticleSprite sprites[] = {smoke, spark, far, invisible};
    AddParticles(list, sprites, style);

    ASSERT_EQ(list.sprites.size(), 3u) << "the smoke, the spark's glow and the spark";
    const float ppm = camera.pixelsPerMetre;
    const SpriteCommand& point = list.sprites[0];
    EXPECT_EQ(point.kind, SpriteKind::soft);
    EXPECT_EQ(point.head.x, camera.ToPixels(smoke.position).x);
    EXPECT_EQ(point.head.y, camera.ToPixels(smoke.position).y);
    EXPECT_EQ(point.size, smoke.size * ppm);
    EXPECT_EQ(point.color, smoke.color);
    EXPECT_EQ(list.sprites[1].kind, SpriteKind::glow);

    const SpriteCommand& streak = list.sprites[2];
    EXPECT_EQ(streak.kind, SpriteKind::streak);
    const b2Vec2 head = camera.ToPixels(spark.position);
    EXPECT_EQ(streak.head.x, head.x);
    EXPECT_EQ(streak.size, std::max(0.5f * style.minSpriteSize, 0.75f * style.minSpriteSize));
    // The tail lies where the spark was `streak` seconds ago, in pixels (y runs down).
    const b2Vec2 before = camera.ToPixels(spark.position - spark.streak * spark.velocity);
    EXPECT_NEAR(streak.tail.x, before.x, 1e-3f);
    EXPECT_NEAR(streak.tail.y, before.y, 1e-3f);
    EXPECT_LT(streak.tail.x, streak.head.x);
    EXPECT_LT(streak.tail.y, streak.head.y);
}

TEST_F(DrawFixture, TheOverlayCountsLiveParticlesByTypeUnderTheTime)
{
    SlideRubberOverDirt(world, ground, crate);
    ASSERT_GT(world.effects->Particles().count, 0u);
    FrameOptions options;
    options.caption = "tuned";
    const DrawList& list = BuildFrame(*world.effects, 1.5f, camera, options, scratch);
    ASSERT_TRUE(list.overlay.shown);
    EXPECT_EQ(list.overlay.title, "t = 1.50 s   tuned");
    const std::vector<ParticleTypeDef>& types = world.effects->Config().particleTypes;
    ASSERT_EQ(list.overlay.legend.size(), types.size());
    std::uint64_t counted = 0;
    for (std::size_t i = 0; i < types.size(); ++i)
    {
        EXPECT_EQ(list.overlay.legend[i].name, types[i].name);
        EXPECT_EQ(list.overlay.legend[i].color, types[i].colorStart);
        counted += list.overlay.legend[i].count;
    }
    EXPECT_EQ(counted, world.effects->Particles().count);
    const ParticleTypeId dirt = world.effects->Config().FindParticleType("dirt");
    EXPECT_GT(list.overlay.legend[dirt.index].count, 0u);
}

TEST_F(DrawFixture, BeginEmptiesTheListForTheNextFrame)
{
    BuildFrame(*world.effects, 0.0f, camera, FrameOptions{}, scratch);
    ASSERT_FALSE(scratch.list.shapes.empty());
    const Camera other = MakeCamera(50, 50, 5.0f, b2Vec2(9.0f, 9.0f));
    scratch.list.Begin(other, Color{1.0f, 0.0f, 0.0f, 1.0f});
    EXPECT_TRUE(scratch.list.shapes.empty());
    EXPECT_TRUE(scratch.list.vertices.empty());
    EXPECT_TRUE(scratch.list.sprites.empty());
    EXPECT_FALSE(scratch.list.overlay.shown);
    EXPECT_EQ(scratch.list.camera.center.x, 9.0f);
}

} // namespace cfx::test
