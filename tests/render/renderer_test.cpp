// The Cairo renderer draws what it is given where it is given: tiny known scenes, pixels read back.
#include "contactfx/render/cairo_renderer.h"
#include "contactfx/render/frame.h"
#include "png_header.h"
#include "test_world.h"

#include <cstdlib>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

using render::CairoRenderer;
using render::Camera;
using render::Pixel;

constexpr int kSize = 100;

// A 100 x 100 image showing 10 m across, centred on the origin: 10 px per metre.
Camera TestCamera()
{
    return render::MakeCamera(kSize, kSize, 10.0f, b2Vec2(0.0f, 0.0f));
}

// The pixel a world point falls on.
Pixel PixelAtWorld(const CairoRenderer& renderer, b2Vec2 world)
{
    const b2Vec2 at = renderer.CurrentCamera().ToPixels(world);
    return renderer.PixelAt(static_cast<int>(at.x), static_cast<int>(at.y));
}

int To8(float channel)
{
    return static_cast<int>(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f));
}

void ExpectColor(const Pixel& pixel, float r, float g, float b, const char* what)
{
    constexpr int kTolerance = 2; // 8-bit rounding
    EXPECT_NEAR(pixel.r, To8(r), kTolerance) << what;
    EXPECT_NEAR(pixel.g, To8(g), kTolerance) << what;
    EXPECT_NEAR(pixel.b, To8(b), kTolerance) << what;
    EXPECT_EQ(pixel.a, 255) << what;
}

// Summed channel distance between two pixels: how much a particle shows over what was there.
int Contrast(const Pixel& pixel, const Pixel& background)
{
    return std::abs(pixel.r - background.r) + std::abs(pixel.g - background.g) +
           std::abs(pixel.b - background.b);
}

// The background as the renderer writes it.
Pixel Background()
{
    CairoRenderer empty(2, 2);
    empty.Begin(render::MakeCamera(2, 2, 1.0f, b2Vec2(0.0f, 0.0f)));
    return empty.PixelAt(0, 0);
}

struct SceneFixture : ::testing::Test
{
    SceneFixture()
    {
        ground = world.CreateGround();                                  // top at y = 0
        crate = world.CreateBox(b2Vec2(-3.0f, 2.0f), 0.5f, 0.5f, 0.5f); // no material
        world.Attach();
        world.effects->SetMaterial(ground, world.effects->FindMaterial("concrete"));
    }

    void Render(CairoRenderer& renderer, bool overlay = false)
    {
        render::FrameOptions options;
        options.overlay = overlay;
        render::RenderFrame(*world.effects, 0.0f, TestCamera(), options, renderer, scratch);
    }

    TestWorld world;
    b2Body* ground = nullptr;
    b2Body* crate = nullptr;
    render::FrameScratch scratch;
};

b2Color Find(const render::ShapePalette& palette, const std::string& material)
{
    for (const auto& entry : palette.materials)
    {
        if (entry.material == material)
        {
            return entry.color;
        }
    }
    ADD_FAILURE() << material << " not in the palette";
    return b2Color();
}

} // namespace

TEST_F(SceneFixture, GroundIsDrawnInItsMaterialsShadeAndSkyInTheBackground)
{
    CairoRenderer renderer(kSize, kSize);
    Render(renderer);
    const float shade = renderer.Style().fillShade;
    const b2Color concrete = Find(render::TutorialPalette(), "concrete");
    ExpectColor(PixelAtWorld(renderer, b2Vec2(2.0f, -1.0f)), concrete.r * shade, concrete.g * shade,
                concrete.b * shade, "inside the ground");
    const Color& sky = renderer.Style().background;
    ExpectColor(PixelAtWorld(renderer, b2Vec2(2.0f, 3.0f)), sky.r, sky.g, sky.b, "above the ground");
}

TEST_F(SceneFixture, FixturesWithoutMaterialTakeTheirBodyTypesColour)
{
    CairoRenderer renderer(kSize, kSize);
    Render(renderer);
    const float shade = renderer.Style().fillShade;
    const b2Color dynamic = render::TutorialPalette().dynamicBody;
    ExpectColor(PixelAtWorld(renderer, b2Vec2(-3.0f, 2.0f)), dynamic.r * shade, dynamic.g * shade,
                dynamic.b * shade, "inside the crate");
}

TEST_F(SceneFixture, SteelIsRedAndDirtIsOrangeAsInTheTutorial)
{
    world.effects->SetMaterial(crate, world.effects->FindMaterial("steel"));
    world.effects->SetMaterial(ground, world.effects->FindMaterial("dirt"));
    CairoRenderer renderer(kSize, kSize);
    Render(renderer);
    const float shade = renderer.Style().fillShade;
    ExpectColor(PixelAtWorld(renderer, b2Vec2(-3.0f, 2.0f)), 1.0f * shade, 0.0f, 0.0f, "steel crate");
    ExpectColor(PixelAtWorld(renderer, b2Vec2(0.0f, -1.0f)), 1.0f * shade, 0.6f * shade, 0.4f * shade,
                "dirt ground");
}

TEST_F(SceneFixture, ASparkIsAStreakOfItsColourAddedOntoTheBackgroundTrailingBehindIt)
{
    CairoRenderer renderer(kSize, kSize);
    renderer.Begin(TestCamera());
    const ParticleTypeDef& sparks =
        world.effects->Config().particleTypes[world.effects->Config().FindParticleType("sparks").index];
    ASSERT_GT(sparks.streak, 0.0f);
    ParticleSprite spark;
    spark.position = b2Vec2(1.05f, 1.05f); // the middle of a pixel
    spark.velocity = b2Vec2(50.0f, 0.0f);  // moving right: the streak trails to the left
    spark.color = LookAt(sparks, 1.0f).color;
    spark.size = 0.6f; // 6 px thick
    spark.streak = sparks.streak;
    renderer.DrawParticles(std::span(&spark, 1));

    const Pixel bg = Background();
    const Pixel head = PixelAtWorld(renderer, spark.position);
    const Color& c = spark.color;
    // At least the spark's colour is added at its head: yellow, red and green far above blue.
    EXPECT_GE(head.r, std::min(255, bg.r + To8(c.r * c.a)) - 2);
    EXPECT_GE(head.g, std::min(255, bg.g + To8(c.g * c.a)) - 2);
    EXPECT_GT(head.r - bg.r, 3 * (head.b - bg.b));
    EXPECT_GT(head.g - bg.g, 3 * (head.b - bg.b));
    // Along the streak behind the head it shows, fading; ahead of it nothing.
    const float trail = spark.velocity.x * spark.streak;
    const Pixel behind = PixelAtWorld(renderer, spark.position - b2Vec2(0.5f * trail, 0.0f));
    EXPECT_GT(Contrast(behind, bg), 0);
    EXPECT_LT(Contrast(behind, bg), Contrast(head, bg));
    EXPECT_EQ(Contrast(PixelAtWorld(renderer, spark.position + b2Vec2(spark.size, 0.0f)), bg), 0);
}

TEST_F(SceneFixture, AFadedParticleShowsLessThanAFreshOne)
{
    const ParticleTypeDef& smoke =
        world.effects->Config().particleTypes[world.effects->Config().FindParticleType("smoke").index];
    ParticleSprite fresh;
    fresh.position = b2Vec2(-2.0f, 2.0f);
    fresh.color = LookAt(smoke, 1.0f).color;
    fresh.size = 1.0f;
    ParticleSprite faded = fresh;
    faded.position = b2Vec2(2.0f, 2.0f);
    faded.color = LookAt(smoke, 0.2f).color;
    ASSERT_LT(faded.color.a, fresh.color.a);
    const ParticleSprite sprites[] = {fresh, faded};

    CairoRenderer renderer(kSize, kSize);
    renderer.Begin(TestCamera());
    renderer.DrawParticles(sprites);
    const Pixel bg = Background();
    const int freshShows = Contrast(PixelAtWorld(renderer, fresh.position), bg);
    const int fadedShows = Contrast(PixelAtWorld(renderer, faded.position), bg);
    EXPECT_GT(fadedShows, 0);
    EXPECT_GT(freshShows, fadedShows);
}

TEST_F(SceneFixture, ARoundPointIsSoftFromItsMiddleToItsEdge)
{
    ParticleSprite dot;
    dot.position = b2Vec2(0.0f, 2.0f);
    dot.color = Color{1.0f, 0.6f, 0.4f, 1.0f};
    dot.size = 4.0f; // 40 px across
    CairoRenderer renderer(kSize, kSize);
    renderer.Begin(TestCamera());
    renderer.DrawParticles(std::span(&dot, 1));
    const Pixel bg = Background();
    const int middle = Contrast(PixelAtWorld(renderer, dot.position), bg);
    const int halfway = Contrast(PixelAtWorld(renderer, dot.position + b2Vec2(1.0f, 0.0f)), bg);
    const int rim = Contrast(PixelAtWorld(renderer, dot.position + b2Vec2(1.8f, 0.0f)), bg);
    const int outside = Contrast(PixelAtWorld(renderer, dot.position + b2Vec2(2.5f, 0.0f)), bg);
    EXPECT_GT(middle, halfway);
    EXPECT_GT(halfway, rim);
    EXPECT_GT(rim, 0);
    EXPECT_EQ(outside, 0);
}

TEST_F(SceneFixture, LiveParticlesOfTheWorldAreDrawnInTheirTypesColour)
{
    // A rubber crate sliding fast over dirt throws dirt particles.
    world.effects->SetMaterial(ground, world.effects->FindMaterial("dirt"));
    world.effects->SetMaterial(crate, world.effects->FindMaterial("rubber"));
    crate->SetTransform(b2Vec2(0.0f, 0.5f), 0.0f);
    crate->SetLinearVelocity(b2Vec2(12.0f, 0.0f));
    for (int i = 0; i < 20 && world.effects->Particles().count == 0; ++i)
    {
        world.Step();
    }
    ASSERT_GT(world.effects->Particles().count, 0u);
    std::vector<ParticleSprite> sprites;
    CollectSprites(*world.effects, sprites);
    const ParticleSprite& newest = sprites.back();
    ASSERT_EQ(newest.type, world.effects->Config().FindParticleType("dirt"));

    CairoRenderer shapesOnly(kSize, kSize);
    shapesOnly.Begin(TestCamera());
    render::DrawShapes(*world.effects, shapesOnly, render::TutorialPalette());
    CairoRenderer full(kSize, kSize);
    Render(full);
    const Pixel before = PixelAtWorld(shapesOnly, newest.position);
    const Pixel after = PixelAtWorld(full, newest.position);
    // Dirt (1, 0.6, 0.4) laid over darker ground: red gains most, then green, then blue.
    const int dr = after.r - before.r;
    const int dg = after.g - before.g;
    const int db = after.b - before.b;
    EXPECT_GT(dr, dg);
    EXPECT_GT(dg, db);
    EXPECT_GT(db, 0);
}

TEST_F(SceneFixture, TheOverlayWritesTextInTheTopLeftCornerOnlyWhenAsked)
{
    CairoRenderer plain(200, 120);
    CairoRenderer annotated(200, 120);
    render::FrameOptions options;
    options.overlay = false;
    const Camera camera = render::MakeCamera(200, 120, 20.0f, b2Vec2(0.0f, 30.0f)); // sky only
    render::RenderFrame(*world.effects, 1.5f, camera, options, plain, scratch);
    options.overlay = true;
    render::RenderFrame(*world.effects, 1.5f, camera, options, annotated, scratch);
    int changed = 0;
    int bright = 0;
    for (int y = 0; y < 40; ++y)
    {
        for (int x = 0; x < 120; ++x)
        {
            const Pixel a = plain.PixelAt(x, y);
            const Pixel b = annotated.PixelAt(x, y);
            changed += (a.r != b.r || a.g != b.g || a.b != b.b) ? 1 : 0;
            bright += b.r > 180 && b.g > 180 && b.b > 180 ? 1 : 0; // light text
        }
    }
    EXPECT_GT(changed, 100);
    EXPECT_GT(bright, 10);
    const Pixel corner = annotated.PixelAt(190, 110);
    const Pixel same = plain.PixelAt(190, 110);
    EXPECT_EQ(corner.r, same.r);
}

TEST(Renderer, EncodesAPngOfItsSize)
{
    CairoRenderer renderer(37, 21);
    renderer.Begin(render::MakeCamera(37, 21, 5.0f, b2Vec2(0.0f, 0.0f)));
    const auto size = PngSize(renderer.EncodePng());
    ASSERT_TRUE(size.has_value());
    EXPECT_EQ(size->first, 37u);
    EXPECT_EQ(size->second, 21u);
}

TEST(Renderer, RefusesImpossibleSizes)
{
    EXPECT_THROW(CairoRenderer(0, 10), std::invalid_argument);
    EXPECT_THROW(CairoRenderer(10, -3), std::invalid_argument);
    EXPECT_THROW(CairoRenderer(100000, 10), std::invalid_argument);
}

} // namespace cfx::test
