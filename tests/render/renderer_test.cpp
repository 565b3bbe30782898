// The Cairo renderer draws the draw list it is given where it is given: tiny known scenes, pixels read
// back.
#include "contactfx/render/cairo_renderer.h"
#include "contactfx/render/frame.h"
#include "dirt_slide.h"
#include "png_header.h"
#include "test_world.h"

#include <cstdlib>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

using render::CairoRenderer;
using render::Pixel;

constexpr int kSize = 100;

// A 100 x 100 image showing 10 m across, centred on the origin: 10 px per metre.
Camera TestCamera()
{
    return MakeCamera(kSize, kSize, 10.0f, b2Vec2(0.0f, 0.0f));
}

// The pixel a world point falls on, seen through TestCamera().
Pixel PixelAtWorld(const CairoRenderer& renderer, b2Vec2 world)
{
    const b2Vec2 at = TestCamera().ToPixels(world);
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
    DrawList list;
    list.Begin(MakeCamera(2, 2, 1.0f, b2Vec2(0.0f, 0.0f)), DrawStyle{}.background);
    CairoRenderer empty(2, 2);
    empty.Render(list);
    return empty.PixelAt(0, 0);
}

// `sprites` alone on the background, seen through TestCamera().
void RenderSprites(CairoRenderer& renderer, std::span<const ParticleSprite> sprites)
{
    DrawList list;
    list.Begin(TestCamera(), DrawStyle{}.background);
    AddParticles(list, sprites, DrawStyle{});
    renderer.Render(list);
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
        FrameOptions options;
        options.overlay = overlay;
        render::RenderFrame(*world.effects, 0.0f, TestCamera(), options, renderer, scratch);
    }

    TestWorld world;
    b2Body* ground = nullptr;
    b2Body* crate = nullptr;
    FrameScratch scratch;
};

b2Color Find(const ShapePalette& palette, const std::string& material)
{
    for (const auto& entry : palette.materials)
    {
        if (entry.material == material)
        {
            return entry.color;
        }
    }
    ADD_FAILURE() << material << " not in the palette";
    return b2Color(0.0f, 0.0f, 0.0f, 1.0f); // b2Color() leaves its members uninitialised
}

} // namespace

TEST_F(SceneFixture, GroundIsDrawnInItsMaterialsShadeAndSkyInTheBackgroundGradient)
{
    CairoRenderer renderer(kSize, kSize);
    Render(renderer);
    const DrawStyle style;
    const float shade = style.fillShade;
    const b2Color concrete = Find(TutorialPalette(), "concrete");
    ExpectColor(PixelAtWorld(renderer, b2Vec2(2.0f, -1.0f)), concrete.r * shade, concrete.g * shade,
                concrete.b * shade, "inside the ground");
    // The sky blends from the top colour at the top row to the bottom colour at the bottom row.
    const b2Vec2 skyPoint(2.0f, 3.0f);
    const float t = (std::floor(TestCamera().ToPixels(skyPoint).y) + 0.5f) / static_cast<float>(kSize);
    const Color& top = style.background;
    const Color& bottom = style.backgroundBottom;
    ASSERT_NE(top, bottom);
    ExpectColor(PixelAtWorld(renderer, skyPoint), top.r + t * (bottom.r - top.r),
                top.g + t * (bottom.g - top.g), top.b + t * (bottom.b - top.b), "above the ground");
}

TEST_F(SceneFixture, FixturesWithoutMaterialTakeTheirBodyTypesColour)
{
    CairoRenderer renderer(kSize, kSize);
    Render(renderer);
    const float shade = DrawStyle{}.fillShade;
    const b2Color dynamic = TutorialPalette().dynamicBody;
    ExpectColor(PixelAtWorld(renderer, b2Vec2(-3.0f, 2.0f)), dynamic.r * shade, dynamic.g * shade,
                dynamic.b * shade, "inside the crate");
}

TEST_F(SceneFixture, SteelIsRedAndDirtIsOrangeAsInTheTutorial)
{
    world.effects->SetMaterial(crate, world.effects->FindMaterial("steel"));
    world.effects->SetMaterial(ground, world.effects->FindMaterial("dirt"));
    CairoRenderer renderer(kSize, kSize);
    Render(renderer);
    const float shade = DrawStyle{}.fillShade;
    ExpectColor(PixelAtWorld(renderer, b2Vec2(-3.0f, 2.0f)), 1.0f * shade, 0.0f, 0.0f, "steel crate");
    ExpectColor(PixelAtWorld(renderer, b2Vec2(0.0f, -1.0f)), 1.0f * shade, 0.6f * shade, 0.4f * shade,
                "dirt ground");
}

TEST_F(SceneFixture, AFreshSparkIsAWhiteHotStreakTrailingBehindItWithAGlowAroundIt)
{
    const ParticleTypeDef& sparks =
        world.effects->Config().particleTypes[world.effects->Config().FindParticleType("sparks").index];
    ASSERT_GT(sparks.streak, 0.0f);
    ParticleSprite spark;
    spark.position = b2Vec2(1.05f, 1.05f); // the middle of a pixel
    spark.velocity = b2Vec2(50.0f, 0.0f);  // moving right: the streak trails to the left
    spark.color = LookAt(sparks, 1.0f).color;
    spark.size = 0.6f; // 6 px: a streak 3 px thick
    spark.streak = sparks.streak;
    spark.life = 1.0f;
    CairoRenderer glowing(kSize, kSize);
    RenderSprites(glowing, std::span(&spark, 1));
    DrawStyle noGlow;
    noGlow.glowSize = 0.0f;
    CairoRenderer bare(kSize, kSize);
    {
        DrawList list;
        list.Begin(TestCamera(), noGlow.background);
        AddParticles(list, std::span(&spark, 1), noGlow);
        bare.Render(list);
    }

    const Pixel bg = Background();
    const Pixel head = PixelAtWorld(glowing, spark.position);
    const Color hot = HeatColor(spark.life);
    // White hot at its head: every channel gains at least the heat colour's share.
    EXPECT_GE(head.r, std::min(255, bg.r + To8(hot.r * spark.color.a)) - 2);
    EXPECT_GE(head.g, std::min(255, bg.g + To8(hot.g * spark.color.a)) - 2);
    EXPECT_GE(head.b, std::min(255, bg.b + To8(hot.b * spark.color.a)) - 2);
    // Along the streak behind the head it shows, fading.
    const float trail = spark.velocity.x * spark.streak;
    const Pixel behind = PixelAtWorld(bare, spark.position - b2Vec2(0.5f * trail, 0.0f));
    EXPECT_GT(Contrast(behind, bg), 0);
    EXPECT_LT(Contrast(behind, bg), Contrast(PixelAtWorld(bare, spark.position), bg));
    // Beside the core, where the bare streak leaves the background as it was, the glow brightens it.
    const float thickness = 0.5f * spark.size * 10.0f;                // px
    const float glowRadius = 0.5f * DrawStyle{}.glowSize * thickness; // px
    const b2Vec2 beside = spark.position + b2Vec2(0.0f, 0.1f * (0.5f * thickness + 0.5f * glowRadius));
    EXPECT_EQ(Contrast(PixelAtWorld(bare, beside), bg), 0);
    const Pixel glow = PixelAtWorld(glowing, beside);
    EXPECT_GT(glow.r + glow.g + glow.b, bg.r + bg.g + bg.b + 10);
    // Past the glow, ahead of the spark, nothing.
    EXPECT_EQ(Contrast(PixelAtWorld(glowing, spark.position + b2Vec2(0.1f * glowRadius + 0.2f, 0.0f)), bg),
              0);
}

TEST_F(SceneFixture, SparksCoolFromWhiteThroughYellowToRedAsTheyAge)
{
    ParticleSprite spark;
    spark.velocity = b2Vec2(50.0f, 0.0f);
    spark.color = Color{1.0f, 1.0f, 1.0f, 1.0f};
    spark.size = 0.6f;
    spark.streak = 0.03f;
    const float lives[] = {1.0f, 0.6f, 0.2f};
    std::vector<ParticleSprite> sprites;
    for (int i = 0; i < 3; ++i)
    {
        spark.position = b2Vec2(-3.0f + 3.0f * static_cast<float>(i) + 0.05f, 3.05f);
        spark.life = lives[i];
        sprites.push_back(spark);
    }
    CairoRenderer renderer(kSize, kSize);
    RenderSprites(renderer, sprites);
    const Pixel white = PixelAtWorld(renderer, sprites[0].position);
    const Pixel yellow = PixelAtWorld(renderer, sprites[1].position);
    const Pixel red = PixelAtWorld(renderer, sprites[2].position);
    EXPECT_GT(white.b, 200);
    EXPECT_GT(yellow.r, 200);
    EXPECT_GT(yellow.g, 150);
    EXPECT_LT(yellow.b, white.b - 80);
    EXPECT_GT(red.r, 150);
    EXPECT_LT(red.g, yellow.g - 80);
}

TEST_F(SceneFixture, DirtGrainsStandOutFromDirtGround)
{
    world.effects->SetMaterial(ground, world.effects->FindMaterial("dirt"));
    const ParticleTypeDef& dirt =
        world.effects->Config().particleTypes[world.effects->Config().FindParticleType("dirt").index];
    ASSERT_EQ(LookOf(dirt), SpriteLook::grain);
    CairoRenderer bare(kSize, kSize);
    Render(bare);
    // Grains of fresh dirt lying in the ground's fill and on its outline (the top edge, y = 0).
    ParticleSprite grain;
    grain.color = LookAt(dirt, 1.0f).color;
    grain.size = 1.0f; // 10 px; centred on a pixel corner across, so its 1 px rim covers whole pixels
    grain.look = SpriteLook::grain;
    grain.position = b2Vec2(2.0f, -1.05f);
    ParticleSprite onEdge = grain; // on the ground's outline
    onEdge.position = b2Vec2(-2.0f, 0.05f);
    const ParticleSprite grains[] = {grain, onEdge};
    CairoRenderer drawn(kSize, kSize);
    FrameOptions options;
    options.overlay = false;
    DrawList& list = scratch.list;
    BuildFrame(*world.effects, 0.0f, TestCamera(), options, scratch);
    AddParticles(list, grains, options.style);
    drawn.Render(list);
    for (const ParticleSprite& sprite : grains)
    {
        const Pixel under = PixelAtWorld(bare, sprite.position);
        const Pixel core = PixelAtWorld(drawn, sprite.position);
        const Pixel rim = PixelAtWorld(drawn, sprite.position + b2Vec2(0.45f, 0.0f));
        EXPECT_GT(Contrast(core, under), 60) << "its core is lighter than the ground under it";
        EXPECT_GT(Contrast(rim, under), 60) << "its rim is darker than the ground under it";
        EXPECT_LT(rim.r + rim.g + rim.b, under.r + under.g + under.b);
    }
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
    RenderSprites(renderer, sprites);
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
    RenderSprites(renderer, std::span(&dot, 1));
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
    SlideRubberOverDirt(world, ground, crate);
    ASSERT_GT(world.effects->Particles().count, 0u);
    std::vector<ParticleSprite> sprites;
    CollectSprites(*world.effects, sprites);
    const ParticleSprite& newest = sprites.back();
    ASSERT_EQ(newest.type, world.effects->Config().FindParticleType("dirt"));

    DrawList shapes;
    shapes.Begin(TestCamera(), DrawStyle{}.background);
    shapes.backgroundBottom = DrawStyle{}.backgroundBottom;
    ShapeRecorder recorder(shapes, DrawStyle{});
    RecordWorldShapes(*world.effects, TutorialPalette(), recorder);
    CairoRenderer shapesOnly(kSize, kSize);
    shapesOnly.Render(shapes);
    CairoRenderer full(kSize, kSize);
    FrameOptions options;
    options.overlay = false;
    options.style.minGrainSize = 8.0f; // a core of several pixels inside the rim
    render::RenderFrame(*world.effects, 0.0f, TestCamera(), options, full, scratch);
    const Pixel before = PixelAtWorld(shapesOnly, newest.position);
    const Pixel after = PixelAtWorld(full, newest.position);
    // Dirt (1, 0.6, 0.4), lifted towards white: its hue (red above green above blue), and clearly not what
    // was there (it lies on the ground's outline, which is dirt's full colour).
    EXPECT_GT(after.r, after.g);
    EXPECT_GT(after.g, after.b);
    EXPECT_GT(Contrast(after, before), 60);
}

TEST_F(SceneFixture, TheOverlayWritesTextInTheTopLeftCornerOnlyWhenAsked)
{
    CairoRenderer plain(200, 120);
    CairoRenderer annotated(200, 120);
    FrameOptions options;
    options.overlay = false;
    const Camera camera = MakeCamera(200, 120, 20.0f, b2Vec2(0.0f, 30.0f)); // sky only
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

// A trial's 160x90 picture had its overlay cut at the right edge ("dirt 4..."), and a 200x400 one too; a
// re-check found short pictures (100x30: the legend's third line below the bottom) and narrow ones (40x40)
// cut as well. The panel fits the picture: its font shrinks, its legend wraps, and a picture without room for
// text of 5 px gets no overlay rather than a cut or unreadable one.
TEST(Renderer, TheOverlayFitsPicturesOfEverySize)
{
    std::vector<std::pair<int, int>> sizes = {{160, 90}, {200, 400}, {100, 30},  {50, 20},
                                              {200, 20}, {300, 10},  {400, 30},  {40, 40},
                                              {80, 45},  {2, 2},     {1280, 720}};
    for (int width = 11; width <= 83; width += 3)
    {
        sizes.emplace_back(width, 200);
    }
    for (const auto& [width, height] : sizes)
    {
        for (const char* title :
             {"t = 10.60 s   default effects", "t = 10.60 s   a much longer effects name here"})
        {
            SCOPED_TRACE(testing::Message() << width << "x" << height << ", " << title);
            DrawList list;
            list.Begin(MakeCamera(width, height, 1.0f, b2Vec2(0.0f, 0.0f)), DrawStyle{}.background);
            list.backgroundBottom = list.background;
            CairoRenderer plain(width, height);
            plain.Render(list);
            list.overlay.shown = true;
            list.overlay.title = title;
            list.overlay.legend = {LegendEntry{"smoke", {0.5f, 0.5f, 0.5f, 1.0f}, 2},
                                   LegendEntry{"sparks", {0.9f, 1.0f, 0.1f, 1.0f}, 451},
                                   LegendEntry{"dirt", {1.0f, 0.6f, 0.4f, 1.0f}, 413}};
            CairoRenderer annotated(width, height);
            annotated.Render(list);
            int drawn = 0;
            int atTheEdge = 0;
            for (int y = 0; y < height; ++y)
            {
                for (int x = 0; x < width; ++x)
                {
                    const Pixel a = plain.PixelAt(x, y);
                    const Pixel b = annotated.PixelAt(x, y);
                    const bool changed = a.r != b.r || a.g != b.g || a.b != b.b;
                    drawn += changed ? 1 : 0;
                    atTheEdge += changed && (x == width - 1 || y == height - 1) ? 1 : 0;
                }
            }
            EXPECT_EQ(atTheEdge, 0) << "changed pixels in the last column or row";
            // Wherever the text fits at 5 px or more (at 160 px wide and 30 high both titles do).
            if (width >= 160 && height >= 30)
            {
                EXPECT_GT(drawn, width * height / 50) << "the overlay is drawn";
            }
        }
    }
}

TEST(Renderer, EncodesAPngOfItsSize)
{
    DrawList list;
    list.Begin(MakeCamera(37, 21, 5.0f, b2Vec2(0.0f, 0.0f)), DrawStyle{}.background);
    CairoRenderer renderer(37, 21);
    renderer.Render(list);
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
