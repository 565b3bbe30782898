// contactfx-testbed's command line: every bad flag is one line on stderr and exit code 1, before any
// window opens, and no screenshot is left behind. None of these needs a display (one runs on Xvfb all
// the same, to show that a run which could draw leaves its effects file alone).
#include "contactfx/version.h"
#include "harness/command_line.h"
#include "options.h"
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

// However few frames are asked for, the picture is the third drawn frame (ImGui sizes a table's columns
// from the frame before: after one drawn frame the statistics tables were collapsed), and the run steps
// exactly as many times as frames were asked for.
TEST(TestbedFrames, ARunDrawsItsLastThreeFramesAndStepsOncePerFrameAskedFor)
{
    for (const int frames : {1, 2, 3, 4, 620})
    {
        const int count = testbed::HeadlessFrameCount(frames);
        int drawn = 0;
        int steps = 0;
        for (int frame = 1; frame <= count; ++frame)
        {
            const testbed::HeadlessFrame plan = testbed::HeadlessFramePlan(frame, frames);
            drawn += plan.draw ? 1 : 0;
            steps += plan.step ? 1 : 0;
            EXPECT_TRUE(plan.draw || plan.step) << frames << " frames, frame " << frame;
        }
        EXPECT_EQ(count, std::max(frames, 3)) << frames;
        EXPECT_EQ(drawn, 3) << frames;
        EXPECT_EQ(steps, frames) << frames;
        EXPECT_TRUE(testbed::HeadlessFramePlan(count, frames).draw) << frames;
        EXPECT_TRUE(testbed::HeadlessFramePlan(count, frames).step) << frames;
    }
}

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
    // Beyond an int: the range is named, not only "a whole number".
    ExpectRefused(RunTestbed("--scene grinder --frames 2147483648 --screenshot " + shot.string()),
                  {"--frames: expected a whole number from 1 to 2147483647, found \"2147483648\""});
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

TEST(TestbedFlags, ScreenshotDoesNotOverwriteTheEffectsFile)
{
    // The user trial's command, on a display: without the check the PNG replaced the config.
    const std::filesystem::path dir = ScratchDir("testbed_screenshot_input");
    const std::filesystem::path effects = dir / "fx3.png";
    std::filesystem::copy_file(Scene("default.effects.json"), effects);
    const std::string config = FileText(effects);
    ExpectRefused(
        RunTestbedOnXvfb("--effects " + effects.string() + " --frames 3 --screenshot " + effects.string()),
        {kCommandLine + std::string(": --screenshot: ") + effects.string() + ": is the input file \"" +
         effects.string() + "\" of this command: not overwritten"});
    // The same file under another name: a symbolic link, a hard link, another spelling.
    std::filesystem::create_symlink(effects, dir / "symbolic.png");
    std::filesystem::create_hard_link(effects, dir / "hard.png");
    for (const std::filesystem::path& screenshot :
         {dir / "symbolic.png", dir / "hard.png", dir / "." / "fx3.png"})
    {
        ExpectRefused(
            RunTestbed("--effects " + effects.string() + " --frames 3 --screenshot " + screenshot.string()),
            {"--screenshot", screenshot.string(), "is the input file", "not overwritten"});
    }
    EXPECT_TRUE(FileText(effects) == config) << effects << " was replaced"; // not a dump of a PNG
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "symbolic.png"));
}

TEST(TestbedFlags, AScreenshotThroughASymbolicLinkIsWrittenToItsTarget)
{
    // As the command line's outputs: the link stays and its target (here not there yet) gets the PNG.
    const std::filesystem::path dir = ScratchDir("testbed_screenshot_link");
    std::filesystem::create_directories(dir / "shots");
    std::filesystem::create_symlink("shots/latest.png", dir / "latest.png");
    const CliResult result =
        RunTestbedOnXvfb("--scene grinder --frames 2 --screenshot " + (dir / "latest.png").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "latest.png"));
    EXPECT_EQ(FileText(dir / "shots" / "latest.png").substr(1, 3), "PNG");
}

TEST(TestbedFlags, AnExplicitlyEmptyFileIsRefused)
{
    // Not taken as "not given": `--effects ''` ran the scene's own effects, `--screenshot ''` saved nothing.
    ExpectRefused(RunTestbed("--scene grinder --frames 1 --effects ''"),
                  {kCommandLine + std::string(": --effects: names no file")});
    ExpectRefused(RunTestbed("--scene grinder --frames 3 --screenshot ''"),
                  {kCommandLine + std::string(": --screenshot: names no file")});
}

TEST(TestbedFlags, ParseErrorsNameTheCommandLineAndTheFlag)
{
    // As CheckOptions' own errors: "contactfx-testbed: error: <command line>: --frames: ...".
    const std::string frames = "contactfx-testbed: error: " + std::string(kCommandLine) + ": --frames: ";
    ExpectRefused(RunTestbed("--frames 1e3"), {frames, "whole number", "1e3"});
    ExpectRefused(RunTestbed("--frames"), {frames + "needs a whole number"});
    ExpectRefused(RunTestbed("--frames 1 --frames 2"), {frames + "given more than once"});
    ExpectRefused(RunTestbed("--frames 1 --no-such-flag"),
                  {std::string(kCommandLine) + ": --no-such-flag: unknown flag"});
    ExpectRefused(RunTestbed("--frames 1 scene.json stray"),
                  {std::string(kCommandLine) + ": stray: unexpected argument"});
}

// A RUBE file of the user's own is opened as it is (session_test.cpp has what it opens); it takes the
// place of --scene, and one that cannot be read is refused before any window opens.
TEST(TestbedFlags, ASceneFileOpensInsteadOfARegisteredScene)
{
    const std::filesystem::path dir = ScratchDir("testbed_scene_file_flag");
    const std::filesystem::path shot = dir / "shot.png";
    const std::string file = Scene("grinder.json");
    ExpectRefused(
        RunTestbed(file + " --scene grinder --frames 1 --screenshot " + shot.string()),
        {std::string(kCommandLine) + ": scene: give either a scene file or --scene NAME, not both"});
    const std::filesystem::path missing = dir / "missing.json";
    ExpectRefused(RunTestbed(missing.string() + " --frames 1 --screenshot " + shot.string()),
                  {missing.string()});
    EXPECT_FALSE(std::filesystem::exists(shot));

    const CliResult result = RunTestbedOnXvfb(file + " --frames 30 --screenshot " + shot.string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(FileText(shot).substr(1, 3), "PNG");

    // The screenshot never replaces the scene file: named .png, or through a link (a trial lost its level).
    const std::filesystem::path level = dir / "level.png";
    std::filesystem::copy_file(file, level);
    std::filesystem::create_symlink(level, dir / "link.png");
    for (const std::filesystem::path& screenshot : {level, dir / "link.png"})
    {
        ExpectRefused(RunTestbed(level.string() + " --frames 3 --screenshot " + screenshot.string()),
                      {"--screenshot", "is the input file", "not overwritten"});
    }
    EXPECT_TRUE(FileText(level) == FileText(file)) << "the level was replaced";
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
