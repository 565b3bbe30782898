// Output paths: which kind a path asks for, how sequence files are numbered, finding ffmpeg.
#include "contactfx/render/cairo_renderer.h"
#include "contactfx/render/frame_output.h"

#include <cstdio>
#include <cstdlib>
#include <gtest/gtest.h>
#include <unistd.h>

namespace cfx::test
{

using render::ClassifyOutput;
using render::OutputKind;
using render::SequenceFile;

TEST(Output, KindFollowsTheExtensionInAnyCase)
{
    EXPECT_EQ(ClassifyOutput("out/frame.png"), OutputKind::png);
    EXPECT_EQ(ClassifyOutput("frame.PNG"), OutputKind::png);
    EXPECT_EQ(ClassifyOutput("out/demo.mp4"), OutputKind::mp4);
    EXPECT_EQ(ClassifyOutput("demo.Gif"), OutputKind::gif);
    EXPECT_EQ(ClassifyOutput("frames/frame_%04d.png"), OutputKind::pngSequence);
    EXPECT_EQ(ClassifyOutput("frames/f%d.png"), OutputKind::pngSequence);
    EXPECT_EQ(ClassifyOutput("100%%.png"), OutputKind::png);
}

TEST(Output, RefusesUnknownExtensionsAndBadPatterns)
{
    for (const char* bad : {"demo.avi", "demo", "frames/", "a_%d_%d.png", "a_%s.png", "a_%4d.png", "a_%.png",
                            "frames_%d/f.png", "clip_%03d.mp4"})
    {
        EXPECT_THROW(ClassifyOutput(bad), std::invalid_argument) << bad;
    }
    try
    {
        ClassifyOutput("demo.avi");
    }
    catch (const std::invalid_argument& error)
    {
        EXPECT_NE(std::string(error.what()).find(".avi"), std::string::npos) << error.what();
    }
}

TEST(Output, SequenceFilesAreZeroPaddedToThePatternsWidth)
{
    EXPECT_EQ(SequenceFile("frames/frame_%04d.png", 7), std::filesystem::path("frames/frame_0007.png"));
    EXPECT_EQ(SequenceFile("f%d.png", 12), std::filesystem::path("f12.png"));
    EXPECT_EQ(SequenceFile("f%02d.png", 123), std::filesystem::path("f123.png"));
    EXPECT_EQ(SequenceFile("100%%_%03d.png", 5), std::filesystem::path("100%_005.png"));
    EXPECT_EQ(SequenceFile("still.png", 5), std::filesystem::path("still.png"));
}

TEST(Output, FindsProgramsOnThePathOnly)
{
    const char* saved = std::getenv("PATH");
    const std::string path = saved != nullptr ? saved : "";
    EXPECT_FALSE(render::FindProgram("sh").empty()); // any Debian system has /bin/sh
    const std::filesystem::path empty = std::filesystem::temp_directory_path() / "contactfx_empty_path";
    std::filesystem::create_directories(empty);
    ::setenv("PATH", empty.c_str(), 1);
    EXPECT_TRUE(render::FindProgram("sh").empty());
    ::setenv("PATH", path.c_str(), 1);
}

TEST(Output, ProgramsReadNothingOfOurStandardInput)
{
    // ffmpeg reads keys from its standard input: given ours, it took the bytes a script fed the commands
    // after ours (`while read line; do $line; done`).
    int feed[2];
    ASSERT_EQ(::pipe(feed), 0);
    const int savedInput = ::dup(STDIN_FILENO);
    ASSERT_GE(savedInput, 0);
    ASSERT_EQ(::dup2(feed[0], STDIN_FILENO), STDIN_FILENO);
    ::close(feed[0]);
    const std::string ours = "the next command\n";
    ASSERT_EQ(::write(feed[1], ours.data(), ours.size()), static_cast<ssize_t>(ours.size()));
    ::close(feed[1]);

    const render::ProgramResult cat = render::RunProgram(render::FindProgram("cat"), {});
    std::string left(64, '\0');
    const ssize_t n = ::read(STDIN_FILENO, left.data(), left.size());
    ::dup2(savedInput, STDIN_FILENO);
    ::close(savedInput);

    EXPECT_EQ(cat.status, 0);
    EXPECT_EQ(cat.output, "");
    ASSERT_GE(n, 0);
    EXPECT_EQ(left.substr(0, static_cast<std::size_t>(n)), ours);
}

namespace
{

// An 8 x 6 picture of the background only.
DrawList BlankList()
{
    DrawList list;
    list.Begin(MakeCamera(8, 6, 1.0f, b2Vec2(0.0f, 0.0f)), DrawStyle{}.background);
    return list;
}

} // namespace

TEST(Output, ASequenceLeftUnfinishedRemovesTheFramesItWrote)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "contactfx_test_sequence_sink";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    render::CairoRenderer frame(8, 6);
    frame.Render(BlankList());
    {
        render::PngSequenceSink sink(dir / "f_%02d.png");
        sink.Write(frame);
        sink.Write(frame);
        EXPECT_TRUE(std::filesystem::exists(dir / "f_00.png"));
        EXPECT_TRUE(std::filesystem::exists(dir / "f_01.png"));
        // No Finish: a render that failed midway.
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir));
    {
        render::PngSequenceSink sink(dir / "f_%02d.png");
        sink.Write(frame);
        sink.Finish();
    }
    EXPECT_TRUE(std::filesystem::exists(dir / "f_00.png"));
}

namespace
{

std::filesystem::path FreshDir(const char* name)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace

TEST(Output, AVideoIsCheckedWithFfprobeAndLeftInTheCallersTemporaryFile)
{
    if (render::FindProgram("ffmpeg").empty() || render::FindProgram("ffprobe").empty())
    {
        GTEST_SKIP() << "ffmpeg and ffprobe are not installed";
    }
    const std::filesystem::path dir = FreshDir("contactfx_test_video_temporary");
    const std::filesystem::path temporary = dir / ".clip.mp4.mine";
    render::CairoRenderer frame(8, 6);
    frame.Render(BlankList());
    {
        render::VideoSink sink(dir / "clip.mp4", render::OutputKind::mp4, 8, 6, 10.0, temporary);
        for (int i = 0; i < 3; ++i)
        {
            sink.Write(frame);
        }
        sink.Finish();
    }
    // Not renamed: the caller commits it with its other outputs.
    EXPECT_FALSE(std::filesystem::exists(dir / "clip.mp4"));
    const render::VideoProbe probe = render::ProbeVideo(temporary);
    ASSERT_TRUE(probe.ok) << probe.message;
    EXPECT_EQ(probe.frames, 3);
    EXPECT_NEAR(probe.seconds, 0.3, 0.05);
    {
        // Unfinished: what ffmpeg wrote is removed.
        render::VideoSink sink(dir / "clip.gif", render::OutputKind::gif, 8, 6, 10.0, dir / ".clip.gif.mine");
        sink.Write(frame);
    }
    EXPECT_FALSE(std::filesystem::exists(dir / ".clip.gif.mine"));
}

TEST(Output, FfprobeFindsNoVideoInACutOffFile)
{
    if (render::FindProgram("ffprobe").empty())
    {
        GTEST_SKIP() << "ffprobe is not installed";
    }
    const std::filesystem::path dir = FreshDir("contactfx_test_video_probe");
    std::FILE* file = std::fopen((dir / "broken.mp4").c_str(), "wb");
    ASSERT_NE(file, nullptr);
    const std::string bytes("\0\0\0\x20"
                            "ftypisom partial",
                            20); // an MP4's start, nothing after
    std::fwrite(bytes.data(), 1, bytes.size(), file);
    std::fclose(file);
    const render::VideoProbe probe = render::ProbeVideo(dir / "broken.mp4");
    EXPECT_FALSE(probe.ok);
    EXPECT_FALSE(probe.message.empty());
    EXPECT_FALSE(render::ProbeVideo(dir / "missing.mp4").ok);
}

} // namespace cfx::test
