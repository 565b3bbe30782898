// contactfx-testbed --scene NAME --frames N --screenshot FILE on a virtual display (Xvfb, Mesa): the
// picture shows the scene and its particles in their colours.
//
// Each scene is shot twice at the same frame, with and without particles. The simulation is
// deterministic and particles do not move bodies under the default preset, so the two pictures differ
// only where particles are drawn. A changed pixel counts for a particle type when it lies on the blend
// from the particle-free pixel below it towards one of the type's colours over life (colorEnd ..
// colorStart of the default preset): that is what drawing a translucent sprite of that colour does,
// whatever the shape or the background under it.
#include "contactfx/render/cairo_renderer.h"
#include "contactfx/render/palette.h"
#include "harness/scenes.h"
#include "layout.h"
#include "testbed/testbed_support.h"

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

float Distance(const Rgb& a, const Rgb& b)
{
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
}

// How well `shown` is `under` covered by `color` at some opacity in [kLeastCover, 1]: the distance
// from the blend line, or infinity when no opacity in range fits.
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

// Pixels of the world view that particles changed, by the particle type whose colours explain them.
std::map<std::string, int> ParticlePixels(const Shot& shot)
{
    std::map<std::string, int> counts;
    for (const ParticleTypeDef& type : shot.config.particleTypes)
    {
        counts[type.name] = 0;
    }
    const testbed::PixelRect view =
        testbed::WorldViewRect(shot.withParticles.width, shot.withParticles.height);
    for (int y = view.y; y < view.y + view.height; ++y)
    {
        for (int x = view.x; x < view.x + view.width; ++x)
        {
            const Rgb& shown = shot.withParticles.At(x, y);
            const Rgb& under = shot.withoutParticles.At(x, y);
            if (Distance(shown, under) * 0.58f < kChanged) // 0.58 ~ 1/sqrt(3): per channel
            {
                continue;
            }
            const std::string* best = nullptr;
            float bestMiss = kOnBlend;
            for (const ParticleTypeDef& type : shot.config.particleTypes)
            {
                for (int step = 0; step <= kColourSteps; ++step)
                {
                    const float t = static_cast<float>(step) / kColourSteps;
                    const Rgb color{type.colorEnd.r + t * (type.colorStart.r - type.colorEnd.r),
                                    type.colorEnd.g + t * (type.colorStart.g - type.colorEnd.g),
                                    type.colorEnd.b + t * (type.colorStart.b - type.colorEnd.b)};
                    const float miss = BlendMiss(shown, under, color);
                    if (miss < bestMiss)
                    {
                        bestMiss = miss;
                        best = &type.name;
                    }
                }
            }
            if (best != nullptr)
            {
                ++counts[*best];
            }
        }
    }
    return counts;
}

constexpr int kShown = 50; // pixels: a type is shown when a few sprites' worth of pixels carry its colours
constexpr int kAbsent = 5; // pixels: a type is absent below this (a little room for stray blends)

void ExpectShown(const std::map<std::string, int>& counts, const std::vector<std::string>& shown,
                 const std::vector<std::string>& absent)
{
    for (const std::string& type : shown)
    {
        EXPECT_GE(counts.at(type), kShown) << type;
    }
    for (const std::string& type : absent)
    {
        EXPECT_LT(counts.at(type), kAbsent) << type;
    }
}

// Share of the world view's pixels within two 8-bit steps of `color` filled as shapes are.
float ShareOfFill(const Image& image, const b2Color& color)
{
    const render::RenderStyle style;
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
    for (const render::ShapePalette::Entry& entry : render::TutorialPalette().materials)
    {
        if (entry.material == material)
        {
            return entry.color;
        }
    }
    ADD_FAILURE() << "no colour for " << material;
    return b2Color();
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
}

TEST(TestbedScreenshot, GrinderShowsSparksAndNoSmoke)
{
    ExpectShown(ParticlePixels(TakeShots("grinder", 150)), {"sparks"}, {"smoke"});
}

TEST(TestbedScreenshot, SkidpadShowsSmokeOnly)
{
    ExpectShown(ParticlePixels(TakeShots("skidpad", 120)), {"smoke"}, {"sparks", "dirt"});
}

TEST(TestbedScreenshot, RockslideShowsDirtAndNoSmoke)
{
    ExpectShown(ParticlePixels(TakeShots("rockslide", 480)), {"dirt"}, {"smoke"});
}

} // namespace cfx::test
