// contactfx render and --plot, through the binary: what files they write, and that bad flags write none.
#include "cli/cli_support.h"
#include "png_header.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

namespace cfx::test
{

namespace
{

std::string Bytes(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

// Tiny, short renders keep these tests fast.
const std::string kTiny = " --width 48 --height 32 ";

// A refused render: exit 1, the flag named on one line, nothing written into `dir`.
void ExpectRefused(const std::string& args, const std::filesystem::path& dir, const std::string& flag)
{
    const CliResult result = RunCli("render " + args);
    EXPECT_EQ(result.exitCode, 1) << args << "\n" << result.output;
    EXPECT_NE(result.output.find("contactfx: error:"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(flag), std::string::npos)
        << "'" << flag << "' missing in: " << result.output;
    EXPECT_EQ(result.output.find("terminate"), std::string::npos) << result.output;
    EXPECT_TRUE(FilesIn(dir).empty()) << "files written by a refused render: " << args;
}

} // namespace

TEST(CliRender, OneFrameAtATimeIsAPngOfTheAskedSize)
{
    const std::filesystem::path dir = ScratchDir("render_png");
    const std::filesystem::path out = dir / "frame.png";
    const CliResult result = RunCli("render --demo --time 0.5" + kTiny + "--out " + out.string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const auto size = PngSize(Bytes(out));
    ASSERT_TRUE(size.has_value());
    EXPECT_EQ(size->first, 48u);
    EXPECT_EQ(size->second, 32u);
    EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"frame.png"}); // no temporary file left

    // Sizes are decimal: CLI11 alone read "010" as octal 8 and "0x100" as 256.
    ASSERT_EQ(RunCli("render --demo --time 0.5 --width 010 --height +012 --out " + out.string()).exitCode, 0);
    const auto decimal = PngSize(Bytes(out));
    ASSERT_TRUE(decimal.has_value());
    EXPECT_EQ(decimal->first, 10u);
    EXPECT_EQ(decimal->second, 12u);
    const CliResult hex = RunCli("render --demo --time 0.5 --width 0x100 --height 32 --out " + out.string());
    EXPECT_EQ(hex.exitCode, 1);
    EXPECT_NE(hex.output.find("--width: expected a whole number from 2 to 8192, found \"0x100\""),
              std::string::npos)
        << hex.output;
}

TEST(CliRender, ARegisteredSceneRendersLikeAFile)
{
    const std::filesystem::path dir = ScratchDir("render_scene");
    const std::filesystem::path out = dir / "x.png";
    const CliResult result = RunCli("render --scene grinder --time 2" + kTiny + "--out " + out.string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const auto size = PngSize(Bytes(out));
    ASSERT_TRUE(size.has_value());
    EXPECT_EQ(size->first, 48u);
    EXPECT_EQ(size->second, 32u);
}

// A trial's `--follow blok` (for "block") rendered the whole world without a word. A name given on the
// command line that the scene lacks is warned of (the picture is still made, as the docs say); the default
// "car" in a scene without a car is not.
TEST(CliRender, AFollowedNameTheSceneLacksIsWarnedOf)
{
    const std::filesystem::path dir = ScratchDir("render_follow");
    const std::filesystem::path out = dir / "x.png";
    const CliResult typo =
        RunCli("render --scene grinder --time 0.1 --follow blok" + kTiny + "--out " + out.string());
    ASSERT_EQ(typo.exitCode, 0) << typo.output;
    EXPECT_NE(typo.output.find("warning: --follow: the scene has no body named \"blok\""), std::string::npos)
        << typo.output;
    EXPECT_TRUE(PngSize(Bytes(out)).has_value());
    const CliResult plain = RunCli("render --scene grinder --time 0.1" + kTiny + "--out " + out.string());
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_EQ(plain.output.find("warning"), std::string::npos) << plain.output;
}

TEST(CliRender, SameFlagsGiveTheSameBytesAndTheOneFrameIsTheSequencesFrame)
{
    const std::filesystem::path dir = ScratchDir("render_same");
    const std::string scene = Scene("physics_driven_particles.json");
    ASSERT_EQ(
        RunCli("render " + scene + " --time 0.4" + kTiny + "--out " + (dir / "a.png").string()).exitCode, 0);
    ASSERT_EQ(
        RunCli("render " + scene + " --time 0.4" + kTiny + "--out " + (dir / "b.png").string()).exitCode, 0);
    EXPECT_EQ(Bytes(dir / "a.png"), Bytes(dir / "b.png"));
    // Frame 2 of a 5 fps sequence shows t = 0.4 s.
    ASSERT_EQ(
        RunCli("render " + scene + " --seconds 0.6 --fps 5" + kTiny + "--out " + (dir / "s_%d.png").string())
            .exitCode,
        0);
    EXPECT_EQ(Bytes(dir / "a.png"), Bytes(dir / "s_2.png"));
    EXPECT_NE(Bytes(dir / "s_0.png"), Bytes(dir / "s_2.png"));
}

TEST(CliRender, ASequenceWritesSecondsTimesFpsNumberedFiles)
{
    const std::filesystem::path dir = ScratchDir("render_sequence");
    const CliResult result =
        RunCli("render --demo --seconds 0.5 --fps 8" + kTiny + "--out " + (dir / "frame_%04d.png").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::vector<std::string> expected = {"frame_0000.png", "frame_0001.png", "frame_0002.png",
                                               "frame_0003.png"}; // round(0.5 * 8) = 4 frames
    EXPECT_EQ(FilesIn(dir), expected);
    for (const std::string& name : expected)
    {
        EXPECT_TRUE(PngSize(Bytes(dir / name)).has_value()) << name;
    }
    EXPECT_NE(result.output.find("4/4 frames"), std::string::npos) << "no progress shown: " << result.output;

    // round(0.2 * 0.1) = 0: still one frame, the first.
    const std::filesystem::path one = ScratchDir("render_sequence_one");
    ASSERT_EQ(
        RunCli("render --demo --seconds 0.2 --fps 0.1" + kTiny + "--out " + (one / "f_%02d.png").string())
            .exitCode,
        0);
    EXPECT_EQ(FilesIn(one), std::vector<std::string>{"f_00.png"});
}

TEST(CliRender, VideosGoThroughFfmpeg)
{
    const std::filesystem::path dir = ScratchDir("render_video");
    const std::string flags = " --demo --seconds 0.3 --fps 10" + kTiny;
    CliResult result = RunCli("render" + flags + "--out " + (dir / "clip.mp4").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    result = RunCli("render" + flags + "--out " + (dir / "clip.gif").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"clip.gif", "clip.mp4"})); // no temporary files
    const std::string mp4 = Bytes(dir / "clip.mp4");
    ASSERT_GT(mp4.size(), 12u);
    EXPECT_EQ(mp4.substr(4, 4), "ftyp");
    EXPECT_EQ(Bytes(dir / "clip.gif").substr(0, 6), "GIF89a");
}

TEST(CliRender, WithoutFfmpegAVideoIsAClearErrorAndNoFile)
{
    const std::filesystem::path dir = ScratchDir("render_no_ffmpeg");
    const std::filesystem::path emptyPath = ScratchDir("render_empty_path");
    // The shell that runs contactfx is /bin/sh by its full path, so it starts with an empty $PATH.
    const char* saved = std::getenv("PATH");
    const std::string path = saved != nullptr ? saved : "";
    ::setenv("PATH", emptyPath.c_str(), 1);
    const CliResult result =
        RunCli("render --demo --seconds 0.2" + kTiny + "--out " + (dir / "clip.mp4").string());
    ::setenv("PATH", path.c_str(), 1);
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("contactfx: error: ffmpeg not found: install ffmpeg to write .mp4/.gif"),
              std::string::npos)
        << result.output;
    EXPECT_TRUE(FilesIn(dir).empty());
}

TEST(CliRender, AFailingFfmpegLeavesNoFile)
{
    // A stand-in ffmpeg that takes every frame, writes half a file where it was told, and fails.
    const std::filesystem::path dir = ScratchDir("render_fake_ffmpeg");
    const CliResult result = RunCliWithFakeFfmpeg(
        "render --demo --seconds 0.2" + kTiny + "--out " + (dir / "clip.mp4").string(), 3);
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("ffmpeg failed (exit status 3)"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("clip.mp4"), std::string::npos) << result.output;
    EXPECT_TRUE(FilesIn(dir).empty()) << "left behind: " << (FilesIn(dir).empty() ? "" : FilesIn(dir)[0]);
}

TEST(CliRender, BadFlagsAreRefusedNamingTheFlagAndWriteNothing)
{
    const std::filesystem::path dir = ScratchDir("render_bad");
    const std::string png = " --out " + (dir / "f.png").string();
    const std::string mp4 = " --out " + (dir / "f.mp4").string();
    ExpectRefused("--demo --width -5" + png, dir, "--width");
    ExpectRefused("--demo --height 0" + png, dir, "--height");
    ExpectRefused("--demo --time nan" + png, dir, "--time");
    ExpectRefused("--demo --time -1" + png, dir, "--time");
    ExpectRefused("--demo --fps 0 --seconds 1" + mp4, dir, "--fps");
    ExpectRefused("--demo --seconds inf" + mp4, dir, "--seconds");
    ExpectRefused("--demo --view 0" + png, dir, "--view");
    ExpectRefused("--demo --out " + (dir / "f.avi").string(), dir, "--out");
    ExpectRefused("--demo --out " + (dir / "f_%d_%d.png").string(), dir, "--out");
    ExpectRefused("--demo --out " + (dir / "missing" / "f.png").string(), dir, "--out");
    ExpectRefused("--demo --time 1" + mp4, dir, "--time");
    ExpectRefused("--demo --width 47 --height 32" + mp4, dir, "--width");
    ExpectRefused("--time 1" + png, dir, "scene");
    ExpectRefused(Scene("physics_driven_particles.json") + " --demo" + png, dir, "scene");
    ExpectRefused((dir / "missing.json").string() + png, dir, "missing.json");
}

std::size_t LineCount(const std::string& text)
{
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// A sequence whose folder is missing, or a file on the way to it, is one error before anything is
// rendered, not one per frame.
TEST(CliRender, ASequenceIntoNoFolderIsOneErrorAndNoFile)
{
    const std::filesystem::path dir = ScratchDir("render_sequence_folder");
    const std::string missing = (dir / "frames" / "f_%04d.png").string();
    CliResult result = RunCli("render --demo --seconds 1" + kTiny + "--out " + missing);
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_EQ(result.output, "contactfx: error: " + missing + ": --out: folder \"" +
                                 (dir / "frames").string() + "\" does not exist\n");
    EXPECT_TRUE(FilesIn(dir).empty());

    WriteTestFile(dir / "afile", "x\n");
    for (const std::filesystem::path& through :
         {dir / "afile" / "f_%d.png", dir / "afile" / "sub" / "f_%d.png"})
    {
        result = RunCli("render --demo --seconds 1" + kTiny + "--out " + through.string());
        EXPECT_EQ(result.exitCode, 1) << result.output;
        EXPECT_EQ(LineCount(result.output), 1u) << result.output;
        EXPECT_NE(result.output.find(through.string() + ": --out: \"" + (dir / "afile").string() +
                                     "\" is not a folder"),
                  std::string::npos)
            << result.output;
        EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"afile"});
    }
}

// What the target is comes before what its name says: a device is refused as a device.
TEST(CliRender, ADeviceIsRefusedAsADevice)
{
    if (!std::filesystem::exists("/dev/full"))
    {
        GTEST_SKIP() << "no /dev/full";
    }
    const CliResult result = RunCli("render --demo --seconds 0.1" + kTiny + "--out /dev/full");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("contactfx: error: /dev/full: --out: is a device, not a regular file"),
              std::string::npos)
        << result.output;
}

// A target --out cannot be written to, or whose name is no kind of picture, is one of the problems of the
// outputs, all reported at once.
TEST(CliRender, ABadOutIsReportedWithTheOtherOutputsProblems)
{
    const std::filesystem::path dir = ScratchDir("render_bad_out");
    for (const std::string& out : {(dir / "nodir" / "a.png").string(), (dir / "nodir" / "f_%d.png").string(),
                                   (dir / "o.avi").string(), (dir / "o").string()})
    {
        const std::string stats = (dir / "nodir2" / "s.json").string();
        const CliResult result =
            RunCli("render --demo --seconds 0.1" + kTiny + "--out " + out + " --stats " + stats);
        EXPECT_EQ(result.exitCode, 1) << result.output;
        EXPECT_EQ(LineCount(result.output), 2u) << result.output;
        const bool misnamed = out.find("nodir") == std::string::npos; // else its folder is missing
        EXPECT_NE(result.output.find(misnamed ? "<command line>: --out: unknown extension"
                                              : out + ": --out: folder"),
                  std::string::npos)
            << result.output;
        EXPECT_NE(result.output.find(stats + ": --stats: folder"), std::string::npos) << result.output;
    }
    EXPECT_TRUE(FilesIn(dir).empty());
}

// A GIF's frame delays are whole hundredths of a second, 2 at least as players show them: at most 50 fps.
TEST(CliRender, AGifFasterThanFiftyFramesASecondIsRefused)
{
    const std::filesystem::path dir = ScratchDir("render_gif_fps");
    const CliResult result =
        RunCli("render --demo --seconds 0.5 --fps 60" + kTiny + "--out " + (dir / "v.gif").string());
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("contactfx: error: <command line>: --fps: a .gif plays at most 50 frames a "
                                 "second"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("found 60\n"), std::string::npos) << result.output;
    EXPECT_TRUE(FilesIn(dir).empty());
}

// A rejected number is shown as given (shortest round trip), never rounded into its range, and
// nothing follows it on its line.
TEST(CliRender, RangeErrorsShowTheValueAsGiven)
{
    const std::filesystem::path dir = ScratchDir("render_range_text");
    const std::string png = " --out " + (dir / "f.png").string();
    const std::string sequence = " --out " + (dir / "f_%d.png").string();
    const std::pair<std::string, std::string> cases[] = {
        {"--fps 240.0000001" + sequence, "--fps: expected a number in (0, 240], found 240.0000001\n"},
        {"--view -5" + png, "--view: expected metres in (0, 1e6], found -5\n"},
        {"--width 99999999999" + png,
         "--width: expected a whole number from 2 to 8192, found \"99999999999\"\n"},
        {"--height 10.5" + png, "--height: expected a whole number from 2 to 8192, found \"10.5\"\n"},
        {"--time nan" + png, "--time: expected a number in [0, 86400], found nan\n"},
        {"--seconds 86400.0000001" + png,
         "--seconds: expected a number in (0, 86400], found 86400.0000001\n"},
    };
    for (const auto& [args, expected] : cases)
    {
        const CliResult result = RunCli("render --demo" + kTiny + args);
        EXPECT_EQ(result.exitCode, 1) << args << "\n" << result.output;
        EXPECT_NE(result.output.find(expected), std::string::npos) << args << "\n" << result.output;
    }
    EXPECT_TRUE(FilesIn(dir).empty());
}

TEST(CliPlot, RunAndDemoWriteATuningPlot)
{
    const std::filesystem::path dir = ScratchDir("plot");
    CliResult result = RunCli("demo --seconds 1 --plot " + (dir / "demo.png").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    result = RunCli("run " + Scene("physics_driven_particles.json") + " --seconds 1 --plot " +
                    (dir / "run.png").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    for (const char* name : {"demo.png", "run.png"})
    {
        const auto size = PngSize(Bytes(dir / name));
        ASSERT_TRUE(size.has_value()) << name;
        EXPECT_GT(size->first, 0u);
    }
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"demo.png", "run.png"}));
}

TEST(CliPlot, APlotThatIsNotAPngIsRefused)
{
    const std::filesystem::path dir = ScratchDir("plot_bad");
    const CliResult result = RunCli("demo --seconds 1 --plot " + (dir / "plot.svg").string());
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("--plot"), std::string::npos) << result.output;
    EXPECT_TRUE(FilesIn(dir).empty());
}

} // namespace cfx::test

namespace cfx::test
{

TEST(CliRender, TheSummaryAndTheStatsEndAtTheLastFrameForEveryOutput)
{
    // 10 frames at 10 fps: the last shows 0.9 s. The video's sound goes on for that frame's length, which
    // made the summary say 1.00 s while its stats said 0.9.
    const std::filesystem::path dir = ScratchDir("render_summary_time");
    for (const std::string out : {"clip.mp4", "frame_%02d.png"})
    {
        const std::filesystem::path stats = dir / (out.substr(0, 4) + ".json");
        const CliResult result = RunCli("render --scene grinder --seconds 1 --fps 10" + kTiny + "--out " +
                                        (dir / out).string() + " --stats " + stats.string());
        ASSERT_EQ(result.exitCode, 0) << result.output;
        EXPECT_NE(result.output.find("10 frames, 48x32, 0.90 s simulated"), std::string::npos)
            << result.output;
        const nlohmann::json json = nlohmann::json::parse(FileText(stats));
        EXPECT_DOUBLE_EQ(json["seconds"].get<double>(), 0.9) << out;
        EXPECT_EQ(json["steps"].get<int>(), 54) << out;
    }
}

} // namespace cfx::test
