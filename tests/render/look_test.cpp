// The look the drawing layer decides for every backend: sparks that glow and cool, smoke that billows,
// grains with a rim, the background gradient, the overlay's on-image counts and the scale bar.
#include "contactfx/draw/frame_builder.h"
#include "contactfx/effects.h"
#include "dirt_slide.h"
#include "test_world.h"

#include <cmath>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

float Luminance(const Color& c)
{
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

const Camera kCamera = MakeCamera(200, 100, 20.0f, b2Vec2(0.0f, 0.0f)); // 10 px per metre

ParticleSprite Sprite(SpriteLook look, float life)
{
    ParticleSprite sprite;
    sprite.position = b2Vec2(1.0f, 1.0f);
    sprite.velocity = b2Vec2(20.0f, 0.0f);
    sprite.color = Color{1.0f, 0.6f, 0.4f, 0.9f};
    sprite.size = 0.5f;
    sprite.look = look;
    sprite.life = life;
    sprite.lifetime = 2.0f;
    if (look == SpriteLook::spark)
    {
        sprite.streak = 0.03f;
    }
    return sprite;
}

} // namespace

TEST(Look, HeatColorCoolsFromWhiteThroughYellowToRed)
{
    const Color white = HeatColor(1.0f);
    EXPECT_GT(std::min({white.r, white.g, white.b}), 0.85f);
    const Color yellow = HeatColor(0.6f);
    EXPECT_GT(yellow.r, 0.9f);
    EXPECT_GT(yellow.g, 0.7f);
    EXPECT_LT(yellow.b, 0.5f * yellow.g);
    const Color red = HeatColor(0.15f);
    EXPECT_GT(red.r, 0.5f);
    EXPECT_LT(red.g, 0.3f * red.r);
    // Cooling never brightens a channel back.
    Color last = HeatColor(1.0f);
    for (int i = 19; i >= 0; --i)
    {
        const Color now = HeatColor(0.05f * static_cast<float>(i));
        EXPECT_LE(now.r, last.r + 1e-6f) << i;
        EXPECT_LE(now.g, last.g + 1e-6f) << i;
        EXPECT_LE(now.b, last.b + 1e-6f) << i;
        EXPECT_EQ(now.a, 1.0f);
        last = now;
    }
    EXPECT_EQ(HeatColor(std::nanf("")), HeatColor(0.0f));
}

TEST(Look, ASparkIsAGlowThenAStreakInItsHeatColourWithItsOpacity)
{
    DrawList list;
    list.Begin(kCamera, Color{});
    const DrawStyle style;
    const ParticleSprite spark = Sprite(SpriteLook::spark, 0.6f);
    AddParticles(list, std::span(&spark, 1), style);
    ASSERT_EQ(list.sprites.size(), 2u);
    const SpriteCommand& glow = list.sprites[0];
    const SpriteCommand& streak = list.sprites[1];
    EXPECT_EQ(glow.kind, SpriteKind::glow);
    EXPECT_FALSE(glow.type.IsValid()) << "a glow is no particle of its own";
    EXPECT_EQ(streak.kind, SpriteKind::streak);
    EXPECT_FLOAT_EQ(glow.size, style.glowSize * streak.size);
    const Color hot = HeatColor(spark.life);
    EXPECT_EQ(streak.color, (Color{hot.r, hot.g, hot.b, spark.color.a}));
    EXPECT_FLOAT_EQ(glow.color.a, spark.color.a * style.glowOpacity);
    EXPECT_EQ(glow.head.x, streak.head.x);

    DrawStyle noGlow;
    noGlow.glowSize = 0.0f;
    list.Begin(kCamera, Color{});
    AddParticles(list, std::span(&spark, 1), noGlow);
    ASSERT_EQ(list.sprites.size(), 1u);
    EXPECT_EQ(list.sprites[0].kind, SpriteKind::streak);
}

TEST(Look, APuffGrowsAndRisesAsItAges)
{
    DrawList list;
    list.Begin(kCamera, Color{});
    const DrawStyle style;
    const ParticleSprite young = Sprite(SpriteLook::puff, 1.0f);
    const ParticleSprite old = Sprite(SpriteLook::puff, 0.25f);
    const ParticleSprite both[] = {young, old};
    AddParticles(list, both, style);
    ASSERT_EQ(list.sprites.size(), 2u);
    const SpriteCommand& a = list.sprites[0];
    const SpriteCommand& b = list.sprites[1];
    EXPECT_EQ(a.kind, SpriteKind::soft);
    EXPECT_EQ(a.head.y, kCamera.ToPixels(young.position).y) << "just made: where it is";
    EXPECT_FLOAT_EQ(b.size, a.size * (1.0f + style.puffGrowth * (1.0f - old.life)));
    const float rise = style.puffRise * (1.0f - old.life) * old.lifetime; // m
    EXPECT_NEAR(a.head.y - b.head.y, rise * kCamera.pixelsPerMetre, 1e-3f) << "pixels run down";
    EXPECT_EQ(a.head.x, b.head.x);
}

TEST(Look, AGrainIsLighterInsideADarkRimAndNeverTiny)
{
    DrawList list;
    list.Begin(kCamera, Color{});
    const DrawStyle style;
    ParticleSprite grain = Sprite(SpriteLook::grain, 1.0f);
    grain.size = 0.01f; // 0.1 px
    AddParticles(list, std::span(&grain, 1), style);
    ASSERT_EQ(list.sprites.size(), 1u);
    const SpriteCommand& drawn = list.sprites[0];
    EXPECT_EQ(drawn.kind, SpriteKind::grain);
    EXPECT_EQ(drawn.size, style.minGrainSize);
    EXPECT_EQ(drawn.rimWidth, style.grainRim);
    EXPECT_GT(Luminance(drawn.color), Luminance(grain.color));
    EXPECT_LT(Luminance(drawn.rim), 0.5f * Luminance(grain.color));
    EXPECT_EQ(drawn.color.a, grain.color.a);
}

TEST(Look, LookOfFollowsTheTypesData)
{
    ParticleTypeDef type;
    type.streak = 0.02f;
    EXPECT_EQ(LookOf(type), SpriteLook::spark);
    type.streak = 0.0f;
    type.sizeStart = 0.1f;
    type.sizeEnd = 0.5f;
    EXPECT_EQ(LookOf(type), SpriteLook::puff);
    type.sizeEnd = 0.1f;
    type.gravityScale = 0.0f;
    EXPECT_EQ(LookOf(type), SpriteLook::puff);
    type.gravityScale = 1.0f;
    EXPECT_EQ(LookOf(type), SpriteLook::grain);
}

TEST(Look, TheFrameHasTheStylesBackgroundGradient)
{
    TestWorld world;
    world.CreateGround();
    world.Attach();
    FrameScratch scratch;
    FrameOptions options;
    options.style.background = Color{0.1f, 0.0f, 0.0f, 1.0f};
    options.style.backgroundBottom = Color{0.0f, 0.0f, 0.3f, 1.0f};
    const DrawList& list = BuildFrame(*world.effects, 0.0f, kCamera, options, scratch);
    EXPECT_EQ(list.background, options.style.background);
    EXPECT_EQ(list.backgroundBottom, options.style.backgroundBottom);
}

TEST(Look, TheOverlayCountsOnlyParticlesOnTheImage)
{
    TestWorld world;
    b2Body* ground = world.CreateGround();
    b2Body* crate = world.CreateBox(b2Vec2(-3.0f, 2.0f), 0.5f, 0.5f, 0.5f);
    world.Attach();
    SlideRubberOverDirt(world, ground, crate);
    const std::uint32_t live = world.effects->Particles().count;
    ASSERT_GT(live, 0u);
    FrameScratch scratch;
    auto counted = [&](const Camera& camera)
    {
        const DrawList& list = BuildFrame(*world.effects, 0.0f, camera, FrameOptions{}, scratch);
        std::uint64_t total = 0;
        for (const LegendEntry& entry : list.overlay.legend)
        {
            total += entry.count;
        }
        return total;
    };
    EXPECT_EQ(counted(MakeCamera(200, 100, 40.0f, b2Vec2(0.0f, 0.0f))), live) << "all in view";
    EXPECT_EQ(counted(MakeCamera(200, 100, 40.0f, b2Vec2(0.0f, 500.0f))), 0u) << "the sky far above";
}

TEST(Look, TheScaleBarIsARoundLengthOfAtMostAFifthOfTheImage)
{
    for (const float ppm : {3.0f, 50.0f, 137.0f, 1000.0f, 40000.0f})
    {
        Camera camera = kCamera;
        camera.pixelsPerMetre = ppm;
        const ScaleBar bar = MakeScaleBar(camera);
        ASSERT_TRUE(bar.shown) << ppm;
        const float widest = 0.2f * static_cast<float>(camera.width) / ppm;
        EXPECT_LE(bar.metres, widest * 1.0001f) << ppm;
        // The next round length (x2 or x2.5) would not fit.
        EXPECT_GT(2.5f * bar.metres, widest) << ppm;
        const float mantissa = bar.metres / std::pow(10.0f, std::floor(std::log10(bar.metres) + 1e-4f));
        EXPECT_TRUE(std::abs(mantissa - 1.0f) < 1e-3f || std::abs(mantissa - 2.0f) < 1e-3f ||
                    std::abs(mantissa - 5.0f) < 1e-3f)
            << ppm << ": " << bar.metres;
        EXPECT_FLOAT_EQ(bar.pixels, bar.metres * ppm);
        EXPECT_LT(bar.from.y, static_cast<float>(camera.height));
        EXPECT_GT(bar.from.x, 0.0f);
    }
    Camera camera = kCamera;
    camera.pixelsPerMetre = 50.0f; // a fifth of 200 px is 0.8 m: 50 cm
    EXPECT_EQ(MakeScaleBar(camera).label, "50 cm");
    camera.pixelsPerMetre = 2.0f; // 20 m
    EXPECT_EQ(MakeScaleBar(camera).label, "20 m");
    camera.pixelsPerMetre = 6000.0f; // a fifth is 6.7 mm: 5 mm
    EXPECT_EQ(MakeScaleBar(camera).label, "5 mm");
    // Below a millimetre (a trial's --view 1e-6 read "0 mm"): in metres.
    camera.pixelsPerMetre = 200.0f / 1.0e-6f; // a fifth is 2e-7 m
    EXPECT_EQ(MakeScaleBar(camera).label, "2e-07 m");
    camera.pixelsPerMetre = 6.0e5f; // a fifth is 6.7e-5 m: 5e-5 m
    EXPECT_EQ(MakeScaleBar(camera).label, "5e-05 m");
}

TEST(Look, TheScaleBarShowsOnlyWhenAsked)
{
    TestWorld world;
    world.CreateGround();
    world.Attach();
    FrameScratch scratch;
    FrameOptions options;
    EXPECT_FALSE(BuildFrame(*world.effects, 0.0f, kCamera, options, scratch).overlay.scaleBar.shown);
    options.scaleBar = true;
    EXPECT_TRUE(BuildFrame(*world.effects, 0.0f, kCamera, options, scratch).overlay.scaleBar.shown);
}

} // namespace cfx::test
