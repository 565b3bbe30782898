// contactfx render --debug / --debug-layers / --scale-bar: the layers reach the picture.
#include "cli/cli_support.h"
#include "contactfx/draw/debug_layers.h"
#include "testbed/testbed_support.h"

#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

// Pixels within 0.12 per channel of `color`.
int PixelsOf(const Image& image, const Color& color)
{
    int count = 0;
    for (const auto& pixel : image.pixels)
    {
        count += std::abs(pixel[0] - color.r) < 0.12f && std::abs(pixel[1] - color.g) < 0.12f &&
                         std::abs(pixel[2] - color.b) < 0.12f
                     ? 1
                     : 0;
    }
    return count;
}

// The grinder at 2 s: the wheel grinds the steel bar, one contact in the middle of the picture.
Image Grinder(const std::string& name, const std::string& flags)
{
    const std::filesystem::path out = ScratchDir("render_debug_" + name) / "frame.png";
    const CliResult result = RunCli("render --scene grinder --time 2 --width 320 --height 180 " + flags +
                                    " --out " + out.string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    return LoadPng(out);
}

} // namespace

TEST(CliRenderDebug, NormalsAndImpulsesShowOnlyWhenAsked)
{
    const Image plain = Grinder("plain", "");
    const Image layers = Grinder("layers", "--debug-layers normals,impulses");
    const Image all = Grinder("all", "--debug");
    ASSERT_GT(plain.width, 0);
    EXPECT_EQ(PixelsOf(plain, kDebugNormalColor), 0);
    EXPECT_EQ(PixelsOf(plain, kDebugImpulseColor), 0);
    EXPECT_GT(PixelsOf(layers, kDebugNormalColor), 0);
    EXPECT_GT(PixelsOf(layers, kDebugImpulseColor), 0);
    EXPECT_GT(PixelsOf(all, kDebugNormalColor), 0);
    EXPECT_GT(PixelsOf(all, kDebugVelocityColor), PixelsOf(layers, kDebugVelocityColor))
        << "--debug adds the particles' velocities";
}

TEST(CliRenderDebug, AnUnknownLayerIsRefusedNamingTheFlag)
{
    const std::filesystem::path dir = ScratchDir("render_debug_bad");
    const CliResult result = RunCli("render --scene grinder --time 1 --debug-layers normals,nope --out " +
                                    (dir / "frame.png").string());
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("--debug-layers"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "frame.png"));
}

} // namespace cfx::test
