// contactfx-testbed --scene NAME --frames N --screenshot FILE on a virtual display (Xvfb, Mesa): the
// picture shows the scene and its particles in their colours.
//
// Each scene is shot twice at the same frame, with and without particles. The simulation is
// deterministic and particles do not move bodies under the default preset, so the two pictures differ
// only where particles are drawn. A changed pixel counts for a particle type when it lies on the blend
// from the particle-free pixel below it towards one of the colours the drawing layer gives the type over
// its life (its own colours for smoke; the lifted colour and the rim of a grain; the heat colours of a
// spark, added onto what is below): that is what drawing a translucent sprite of that colour does,
// whatever the shape or the background under it. Then the look: sparks glow beyond their streak (the
// pixels around a white-hot core are brighter than without particles), and dirt does not take the
// colours of the ground it lies on.
#include "contactfx/draw/debug_layers.h"
#include "contactfx/draw/draw_list.h"
#include "contactfx/draw/palette.h"
#include "contactfx/draw/style.h"
#include "harness/scenes.h"
#include "layout.h"
#include "testbed/testbed_support.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <map>

namespace cfx::test
{

namespace
{

using Rgb = std::array<float, 3>;

constexpr float kChanged = 4.0f / 255.0f; // a pixel differs when a channel moved more than this
constexpr float kOnBlend = 0.04f;         // largest distance from the blend line, per unit of colour
constexpr float kLeastCover = 0.2f;       // least sprite opacity that counts
constexpr int kColourSteps = 10;          // colours tried between colorEnd and colorStart
constexpr float kLeastLight = 0.1f; // least red added onto a pixel that counts (faint light is any colour)

float Distance(const Rgb& a, const Rgb& b)
{
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
}

// How well `shown` is `under` covered by `color` at some opacity in [kLeastCover, 1]: the distance from
// the blend line, or infinity when no opacity in range fits.
float BlendMiss(const Rgb& shown, const Rgb& under, const Rgb& color)
{
    const Rgb toward{color[0] - under[0], color[1] - under[1], color[2] - under[2]};
    const float length2 = toward[0] * toward[0] + toward[1] * toward[1] + toward[2] * toward[2];
    if (length2 < 1e-4f)
    {
        return INFINITY;
    }
    const float cover = ((shown[0] - under[0]) * toward[0] + (shown[1] - under[1]) * toward[1] +
                         (shown[2] - under[2]) * toward[2]) /
                        length2;
    if (cover < kLeastCover || cover > 1.05f)
    {
        return INFINITY;
    }
    const Rgb blend{under[0] + cover * toward[0], under[1] + cover * toward[1], under[2] + cover * toward[2]};
    return Distance(shown, blend);
}

// The colours the drawing layer gives sprites of one type: laid over what is below (smoke, grains and
// their rims) or added onto it (sparks' streaks and glows). Light added by several sprites is a sum of
// their colours, so its green and blue relative to its red stay within the range of theirs.
struct TypeColours
{
    std::vector<Rgb> laid;
    bool adds = false;
    float greenLow = INFINITY, greenHigh = -INFINITY; // green / red of the added colours
    float blueLow = INFINITY, blueHigh = -INFINITY;   // blue / red

    bool Explains(const Rgb& shown, const Rgb& under) const
    {
        if (std::any_of(laid.begin(), laid.end(),
                        [&](const Rgb& color) { return BlendMiss(shown, under, color) < kOnBlend; }))
        {
            return true;
        }
        const Rgb added{shown[0] - under[0], shown[1] - under[1], shown[2] - under[2]};
        if (!adds || added[0] < kLeastLight || added[1] < -kChanged || added[2] < -kChanged)
        {
            return false;
        }
        if (std::max({shown[0], shown[1], shown[2]}) >= 0.98f)
        {
            return true; // light added past white: its ratios are lost
        }
        constexpr float kSlack = 0.06f;
        const float green = added[1] / added[0];
        const float blue = added[2] / added[0];
        return green >= greenLow - kSlack && green <= greenHigh + kSlack && blue >= blueLow - kSlack &&
               blue <= blueHigh + kSlack;
    }
};

// What the drawing layer gives sprites of `type` over its life: probe sprites through AddParticles with
// the default style.
TypeColours DrawnColours(const ParticleTypeDef& type)
{
    TypeColours colours;
    DrawList list;
    list.Begin(MakeCamera(100, 100, 10.0f, b2Vec2(0.0f, 0.0f)), Color{});
    for (int step = 0; step <= kColourSteps; ++step)
    {
        const float life = static_cast<float>(step) / kColourSteps;
        const ParticleLook look = LookAt(type, life);
        ParticleSprite sprite;
        sprite.velocity = b2Vec2(1.0f, 0.0f);
        sprite.color = look.color;
        sprite.color.a = 1.0f; // any opacity: only the colour matters here
        sprite.size = look.size;
        sprite.streak = type.streak;
        sprite.look = LookOf(type);
        sprite.life = life;
        sprite.lifetime = 0.0f; // no rise: stay on the probe image
        AddParticles(list, std::span(&sprite, 1), DrawStyle{});
    }
    for (const SpriteCommand& command : list.sprites)
    {
        const Color& c = command.color;
        if (command.kind == SpriteKind::streak || command.kind == SpriteKind::glow)
        {
            colours.adds = true;
            colours.greenLow = std::min(colours.greenLow, c.g / c.r);
            colours.greenHigh = std::max(colours.greenHigh, c.g / c.r);
            colours.blueLow = std::min(colours.blueLow, c.b / c.r);
            colours.blueHigh = std::max(colours.blueHigh, c.b / c.r);
            continue;
        }
        colours.laid.push_back(Rgb{c.r, c.g, c.b});
        if (command.kind == SpriteKind::grain)
        {
            colours.laid.push_back(Rgb{command.rim.r, command.rim.g, command.rim.b});
        }
    }
    return colours;
}

struct Shot
{
    Image withParticles;
    Image withoutParticles;
    const EffectsConfig config;
};

Shot TakeShots(const std::string& scene, int frames)
{
    const std::filesystem::path dir = ScratchDir("testbed_shot_" + scene);
    const std::string common = "--scene " + scene + " --frames " + std::to_string(frames) + " --screenshot ";
    const CliResult shown = RunTestbedOnXvfb(common + (dir / "particles.png").string());
    EXPECT_EQ(shown.exitCode, 0) << shown.output;
    const CliResult hidden = RunTestbedOnXvfb(common + (dir / "plain.png").string() + " --hide-particles");
    EXPECT_EQ(hidden.exitCode, 0) << hidden.output;
    const SceneEntry& entry = *FindScene(scene);
    return Shot{LoadPng(dir / "particles.png"), LoadPng(dir / "plain.png"),
                SceneSimulationDef(entry, std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes").config};
}

// The type (index into the config's particle types) whose drawn colours alone explain each changed pixel
// of the world view, or -1 where none or several do or nothing changed; row by row like the image.
std::vector<int> ParticleTypeMap(const Shot& shot)
{
    const std::vector<ParticleTypeDef>& types = shot.config.particleTypes;
    std::vector<TypeColours> colours;
    for (const ParticleTypeDef& type : types)
    {
        colours.push_back(DrawnColours(type));
    }
    const Image& image = shot.withParticles;
    std::vector<int> map(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height), -1);
    const testbed::PixelRect view = testbed::WorldViewRect(image.width, image.height);
    for (int y = view.y; y < view.y + view.height; ++y)
    {
        for (int x = view.x; x < view.x + view.width; ++x)
        {
            const Rgb& shown = image.At(x, y);
            const Rgb& under = shot.withoutParticles.At(x, y);
            if (Distance(shown, under) * 0.58f < kChanged) // 0.58 ~ 1/sqrt(3): per channel
            {
                continue;
            }
            // Only a pixel that one type alone explains counts: a faint white glow added onto the dark
            // sky is also a faint grey puff laid over it.
            int explainedBy = -1;
            for (std::size_t t = 0; t < types.size(); ++t)
            {
                if (colours[t].Explains(shown, under))
                {
                    explainedBy = explainedBy == -1 ? static_cast<int>(t) : -2;
                }
            }
            map[static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                static_cast<std::size_t>(x)] = std::max(explainedBy, -1);
        }
    }
    return map;
}

// Pixels of the world view that particles changed, by the particle type whose colours explain them:
// all of them, and those changed clearly (a channel by kLeastLight or more). A faint change is a faint
// white glow as much as a faint grey puff, so only clear ones show that a type is there when it should
// not be.
struct ParticleCounts
{
    std::map<std::string, int> all;
    std::map<std::string, int> clear;
};

ParticleCounts ParticlePixels(const Shot& shot)
{
    ParticleCounts counts;
    for (const ParticleTypeDef& type : shot.config.particleTypes)
    {
        counts.all[type.name] = 0;
        counts.clear[type.name] = 0;
    }
    const std::vector<int> map = ParticleTypeMap(shot);
    for (std::size_t i = 0; i < map.size(); ++i)
    {
        if (map[i] < 0)
        {
            continue;
        }
        const std::string& name = shot.config.particleTypes[static_cast<std::size_t>(map[i])].name;
        ++counts.all[name];
        const Rgb& shown = shot.withParticles.pixels[i];
        const Rgb& under = shot.withoutParticles.pixels[i];
        const float change = std::max(
            {std::abs(shown[0] - under[0]), std::abs(shown[1] - under[1]), std::abs(shown[2] - under[2])});
        counts.clear[name] += change >= kLeastLight ? 1 : 0;
    }
    return counts;
}

float Brightness(const Rgb& pixel)
{
    return pixel[0] + pixel[1] + pixel[2];
}

// Around white-hot spark cores (changed pixels brighter than 2.4 of 3), the pixels 3 px away in the eight
// directions that are not cores themselves: the share of them brighter than without particles. A streak
// is at most a few pixels thick and covers two of the eight directions at most (more where sparks crowd),
// so a share well above that is the glow. Returns -1 when there is no core.
float GlowShare(const Shot& shot)
{
    const Image& image = shot.withParticles;
    const testbed::PixelRect view = testbed::WorldViewRect(image.width, image.height);
    constexpr int kAway = 3;
    auto core = [&](int x, int y)
    {
        return Brightness(image.At(x, y)) > 2.4f &&
               Brightness(image.At(x, y)) > Brightness(shot.withoutParticles.At(x, y)) + 0.3f;
    };
    int around = 0;
    int brighter = 0;
    for (int y = view.y + kAway; y < view.y + view.height - kAway; ++y)
    {
        for (int x = view.x + kAway; x < view.x + view.width - kAway; ++x)
        {
            if (!core(x, y))
            {
                continue;
            }
            for (int dy = -kAway; dy <= kAway; dy += kAway)
            {
                for (int dx = -kAway; dx <= kAway; dx += kAway)
                {
                    if ((dx == 0 && dy == 0) || core(x + dx, y + dy))
                    {
                        continue;
                    }
                    ++around;
                    brighter += Brightness(image.At(x + dx, y + dy)) >
                                        Brightness(shot.withoutParticles.At(x + dx, y + dy)) + 3.0f / 255.0f
                                    ? 1
                                    : 0;
                }
            }
        }
    }
    return around == 0 ? -1.0f : static_cast<float>(brighter) / static_cast<float>(around);
}

constexpr int kShown = 50; // pixels: a type is shown when a few sprites' worth of pixels carry its colours
constexpr int kAbsent = 5; // pixels: a type is absent below this (a little room for stray blends)

void ExpectShown(const ParticleCounts& counts, const std::vector<std::string>& shown,
                 const std::vector<std::string>& absent)
{
    for (const std::string& type : shown)
    {
        EXPECT_GE(counts.all.at(type), kShown) << type;
    }
    for (const std::string& type : absent)
    {
        EXPECT_LT(counts.clear.at(type), kAbsent) << type;
    }
}

// Share of the world view's pixels within two 8-bit steps of `color` filled as shapes are.
float ShareOfFill(const Image& image, const b2Color& color)
{
    const DrawStyle style;
    const Rgb fill{color.r * style.fillShade, color.g * style.fillShade, color.b * style.fillShade};
    const testbed::PixelRect view = testbed::WorldViewRect(image.width, image.height);
    int count = 0;
    for (int y = view.y; y < view.y + view.height; ++y)
    {
        for (int x = view.x; x < view.x + view.width; ++x)
        {
            const Rgb& pixel = image.At(x, y);
            count += std::abs(pixel[0] - fill[0]) <= 2.5f / 255.0f &&
                             std::abs(pixel[1] - fill[1]) <= 2.5f / 255.0f &&
                             std::abs(pixel[2] - fill[2]) <= 2.5f / 255.0f
                         ? 1
                         : 0;
        }
    }
    return static_cast<float>(count) / static_cast<float>(view.width * view.height);
}

b2Color MaterialColor(const std::string& material)
{
    for (const ShapePalette::Entry& entry : TutorialPalette().materials)
    {
        if (entry.material == material)
        {
            return entry.color;
        }
    }
    ADD_FAILURE() << "no colour for " << material;
    return b2Color(0.0f, 0.0f, 0.0f, 1.0f); // b2Color() leaves its members uninitialised
}

// Pixels of the world view on a `material` ground's outline (within 0.1 of its colour without particles)
// that particles made less than half as bright: the dark rims of grains lying on it. Dirt drawn in its own
// colour (what the ground's outline is drawn in) is never that dark, so without rims there are none.
int DarkRimsOn(const Shot& shot, const std::string& material)
{
    const b2Color outline = MaterialColor(material);
    const Rgb ground{outline.r, outline.g, outline.b};
    const Image& image = shot.withParticles;
    const testbed::PixelRect view = testbed::WorldViewRect(image.width, image.height);
    int count = 0;
    for (int y = view.y; y < view.y + view.height; ++y)
    {
        for (int x = view.x; x < view.x + view.width; ++x)
        {
            const Rgb& under = shot.withoutParticles.At(x, y);
            count += Distance(under, ground) < 0.1f && Brightness(image.At(x, y)) < 0.5f * Brightness(under)
                         ? 1
                         : 0;
        }
    }
    return count;
}

// Sparks glow: most pixels around their white-hot cores are brighter than without particles.
void ExpectSparksGlow(const Shot& shot)
{
    const float share = GlowShare(shot);
    ASSERT_GE(share, 0.0f) << "no white-hot spark core in the picture";
    // Without glows, crowded sparks' own streaks brighten 0.42 (tutorial) and 0.53 (grinder) of these
    // pixels; with them 0.78 and 0.89.
    EXPECT_GT(share, 0.65f);
}

} // namespace

// The tutorial's demo drive at 10.3 s: the car has tipped onto its body and grinds on the concrete
// (sparks) after its skid (smoke); the concrete and dirt grounds and the car are in view.
TEST(TestbedScreenshot, TutorialShowsTheGroundsTheCarSparksAndSmoke)
{
    const Shot shot = TakeShots("tutorial", 620);
    ASSERT_EQ(shot.withParticles.width, testbed::kDefaultWidth);
    ASSERT_EQ(shot.withParticles.height, testbed::kDefaultHeight);
    ASSERT_EQ(shot.withoutParticles.width, testbed::kDefaultWidth);
    constexpr float kGround = 0.05f; // the grounds fill well over a twentieth of the view each
    EXPECT_GT(ShareOfFill(shot.withoutParticles, MaterialColor("concrete")), kGround);
    EXPECT_GT(ShareOfFill(shot.withoutParticles, MaterialColor("dirt")), kGround);
    EXPECT_GT(ShareOfFill(shot.withoutParticles, MaterialColor("steel")), 0.0f);
    ExpectShown(ParticlePixels(shot), {"sparks", "smoke"}, {});
    ExpectSparksGlow(shot);
}

TEST(TestbedScreenshot, GrinderShowsGlowingSparksAndNoSmoke)
{
    const Shot shot = TakeShots("grinder", 150);
    ExpectShown(ParticlePixels(shot), {"sparks"}, {"smoke"});
    ExpectSparksGlow(shot);
}

TEST(TestbedScreenshot, SkidpadShowsSmokeOnly)
{
    ExpectShown(ParticlePixels(TakeShots("skidpad", 120)), {"smoke"}, {"sparks", "dirt"});
}

// Boulders on the dirt slope at 8 s: dirt lies on the slope, whose outline is drawn in dirt's own
// colour, yet its grains stand out from it by their dark rims.
TEST(TestbedScreenshot, RockslideShowsDirtUnlikeTheSlopeAndNoSmoke)
{
    const Shot shot = TakeShots("rockslide", 480);
    ExpectShown(ParticlePixels(shot), {"dirt"}, {"smoke"});
    constexpr int kOneRim = 10; // pixels: the rim of one grain of the smallest size (4 px across)
    EXPECT_GE(DarkRimsOn(shot, "dirt"), kOneRim);
}

// The OpenGL backend draws the debug layers over the particles: the grinder's contact with its normal
// (cyan) and normal impulse (magenta) in view with --debug, and neither colour without.
TEST(TestbedScreenshot, DebugDrawingShowsTheContactsNormalAndImpulse)
{
    const std::filesystem::path dir = ScratchDir("testbed_shot_debug");
    const std::string common = "--scene grinder --frames 90 --hide-particles --screenshot ";
    const CliResult plain = RunTestbedOnXvfb(common + (dir / "plain.png").string());
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    const CliResult debug = RunTestbedOnXvfb(common + (dir / "debug.png").string() + " --debug");
    ASSERT_EQ(debug.exitCode, 0) << debug.output;
    auto count = [](const Image& image, const Color& color)
    {
        const testbed::PixelRect view = testbed::WorldViewRect(image.width, image.height);
        int found = 0;
        for (int y = view.y; y < view.y + view.height; ++y)
        {
            for (int x = view.x; x < view.x + view.width; ++x)
            {
                found += Distance(image.At(x, y), Rgb{color.r, color.g, color.b}) < 0.1f ? 1 : 0;
            }
        }
        return found;
    };
    const Image without = LoadPng(dir / "plain.png");
    const Image with = LoadPng(dir / "debug.png");
    EXPECT_EQ(count(without, kDebugNormalColor), 0);
    EXPECT_EQ(count(without, kDebugImpulseColor), 0);
    EXPECT_GT(count(with, kDebugNormalColor), 0);
    EXPECT_GT(count(with, kDebugImpulseColor), 0);
}

} // namespace cfx::test
