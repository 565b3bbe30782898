// contactfx-testbed's command line: every bad flag is one line on stderr and exit code 1, before any
// window opens, and no screenshot is left behind. None of these needs a display.
#include "contactfx/version.h"
#include "testbed/testbed_support.h"

#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

void ExpectRefused(const CliResult& result, const std::vector<std::string>& expected)
{
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_EQ(CountLines(result.output), 1) << result.output;
    EXPECT_NE(result.output.find("contactfx-testbed: error: "), std::string::npos) << result.output;
    for (const std::string& word : expected)
    {
        EXPECT_NE(result.output.find(word), std::string::npos)
            << "'" << word << "' missing in: " << result.output;
    }
}

} // namespace

TEST(TestbedFlags, VersionPrintsTheVersionOfTheHeaders)
{
    const CliResult result = RunTestbed("--version");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(result.output, std::string("contactfx-testbed ") + CONTACTFX_VERSION_STRING + "\n");
}

TEST(TestbedFlags, UnknownSceneNamesTheRegisteredOnes)
{
    const std::filesystem::path shot = ScratchDir("testbed_unknown_scene") / "shot.png";
    ExpectRefused(RunTestbed("--scene no-such-scene --frames 1 --screenshot " + shot.string()),
                  {"--scene", "no-such-scene", "tutorial", "grinder"});
    EXPECT_FALSE(std::filesystem::exists(shot));
}

TEST(TestbedFlags, FramesMustBeAtLeastOne)
{
    const std::filesystem::path shot = ScratchDir("testbed_frames") / "shot.png";
    for (const char* frames : {"0", "-5"})
    {
        ExpectRefused(
            RunTestbed(std::string("--scene grinder --frames ") + frames + " --screenshot " + shot.string()),
            {"--frames", frames});
    }
    ExpectRefused(RunTestbed("--scene grinder --frames many"), {"--frames"});
    EXPECT_FALSE(std::filesystem::exists(shot));
}

TEST(TestbedFlags, ScreenshotNeedsFramesAndAWritableFile)
{
    const std::filesystem::path dir = ScratchDir("testbed_unwritable");
    ExpectRefused(RunTestbed("--scene grinder --screenshot " + (dir / "shot.png").string()),
                  {"--screenshot", "--frames"});
    const std::filesystem::path missing = dir / "missing" / "shot.png";
    ExpectRefused(RunTestbed("--scene grinder --frames 1 --screenshot " + missing.string()),
                  {"--screenshot", missing.string(), "does not exist"});
    const std::filesystem::path file = dir / "file";
    std::FILE* handle = std::fopen(file.c_str(), "w");
    ASSERT_NE(handle, nullptr);
    std::fclose(handle);
    ExpectRefused(RunTestbed("--scene grinder --frames 1 --screenshot " + (file / "shot.png").string()),
                  {"--screenshot", "\"" + file.string() + "\" is not a folder"});
    ExpectRefused(RunTestbed("--scene grinder --frames 1 --screenshot " + dir.string()),
                  {"--screenshot", "directory"});
    ExpectRefused(RunTestbed("--scene grinder --frames 1 --screenshot /dev/full"),
                  {"--screenshot", "device"});
    EXPECT_FALSE(std::filesystem::exists(dir / "shot.png"));
    EXPECT_FALSE(std::filesystem::exists(missing));
}

TEST(TestbedFlags, UnknownFlagAndBadEffectsFileAreRefused)
{
    ExpectRefused(RunTestbed("--scene grinder --frames 1 --no-such-flag"), {"--no-such-flag"});
    const std::filesystem::path missing = ScratchDir("testbed_effects") / "missing.effects.json";
    ExpectRefused(RunTestbed("--scene grinder --frames 1 --effects " + missing.string()), {missing.string()});
}

TEST(TestbedFlags, NoDisplayIsAClearError)
{
    const std::filesystem::path shot = ScratchDir("testbed_no_display") / "shot.png";
    const CliResult result = RunCommand("env -u DISPLAY -u WAYLAND_DISPLAY " + TestbedBinary() +
                                        " --scene grinder --frames 1 --screenshot " + shot.string());
    ExpectRefused(result, {"cannot open a window", "DISPLAY"});
    EXPECT_FALSE(std::filesystem::exists(shot));
}

} // namespace cfx::test
