// Output files of run, demo, render and preset, through the binary: every output is checked before the
// simulation starts (never an input, a device, a FIFO, a directory or a read-only file), all outputs of
// a command are written together or none, a failure leaves pre-existing files as they were, a video
// counts only when it is complete, and --events streams to disk as the run goes.
//
// A full disk is simulated with a file size limit (`ulimit -f`, in 512-byte blocks under /bin/sh):
// contactfx ignores SIGXFSZ, so writes past the limit fail with EFBIG, for ffmpeg too.
#include "cli/cli_support.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace cfx::test
{

namespace
{

namespace fs = std::filesystem;

std::string Binary()
{
    return std::string(CONTACTFX_BINARY_DIR) + "/bin/contactfx";
}

// `contactfx ARGS` with files limited to `blocks` of 512 bytes: a disk that fills up.
CliResult RunCliLimited(int blocks, const std::string& args)
{
    return RunCommand("ulimit -f " + std::to_string(blocks) + "; exec " + Binary() + " " + args);
}

std::string Join(const std::vector<std::string>& names)
{
    std::string text;
    for (const std::string& name : names)
    {
        text += name + " ";
    }
    return text;
}

unsigned Mode(const fs::path& path)
{
    struct stat info = {};
    return ::stat(path.c_str(), &info) == 0 ? static_cast<unsigned>(info.st_mode) : 0u;
}

// Exit 1 with an error line naming `words`, no crash.
void ExpectError(const CliResult& result, const std::vector<std::string>& words, const std::string& what)
{
    EXPECT_EQ(result.exitCode, 1) << what << "\n" << result.output;
    EXPECT_NE(result.output.find("contactfx: error:"), std::string::npos) << what << "\n" << result.output;
    for (const std::string& word : words)
    {
        EXPECT_NE(result.output.find(word), std::string::npos)
            << what << ": '" << word << "' missing in: " << result.output;
    }
    EXPECT_EQ(result.output.find("terminate"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("Sanitizer"), std::string::npos) << result.output;
}

const std::string kTiny = " --width 48 --height 32 ";

} // namespace

TEST(CliOutputs, AnOutputThatIsAnInputIsRefusedAndTheInputStaysAsItWas)
{
    const fs::path dir = ScratchDir("outputs_input");
    const fs::path scene = dir / "scene.json";
    const fs::path effects = dir / "fx.json";
    fs::copy_file(Scene("physics_driven_particles.json"), scene);
    fs::copy_file(Scene("default.effects.json"), effects);
    const std::string sceneText = FileText(scene);
    const std::string effectsText = FileText(effects);
    ASSERT_EQ(::link(scene.c_str(), (dir / "hardlink.json").c_str()), 0);
    fs::create_symlink(scene, dir / "symlink.json");

    const std::string run = "run " + scene.string() + " --seconds 0.5 ";
    for (const std::string flag : {"--stats", "--events"})
    {
        ExpectError(RunCli(run + flag + " " + scene.string()), {scene.string(), flag, "input"}, flag);
    }
    // Another spelling, a hard link and a symbolic link are the same file.
    const std::string other = (dir / "." / "scene.json").string();
    ExpectError(RunCli(run + "--stats " + other), {"input"}, other);
    ExpectError(RunCli(run + "--stats " + (dir / "hardlink.json").string()), {"hardlink.json", "input"},
                "hard link");
    ExpectError(RunCli(run + "--stats " + (dir / "symlink.json").string()), {"symlink.json", "input"},
                "symbolic link");
    ExpectError(RunCli(run + "--effects " + effects.string() + " --events " + effects.string()),
                {"fx.json", "--events", "input"}, "effects as output");
    ExpectError(RunCli("render " + scene.string() + " --time 0.1" + kTiny + "--out " +
                       (dir / "r.png").string() + " --stats " + scene.string()),
                {"--stats", "input"}, "render");
    EXPECT_EQ(FileText(scene), sceneText);
    EXPECT_EQ(FileText(effects), effectsText);
    EXPECT_EQ(FilesIn(dir),
              (std::vector<std::string>{"fx.json", "hardlink.json", "scene.json", "symlink.json"}));
}

TEST(CliOutputs, DevicesFifosAndDirectoriesAreRefusedAndStayWhatTheyAre)
{
    const fs::path dir = ScratchDir("outputs_devices");
    ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0644), 0);
    ASSERT_EQ(::mkfifo((dir / "fifo.png").c_str(), 0644), 0);
    fs::create_directory(dir / "folder.png");
    fs::create_directory(dir / "folder.json");
    const std::string demo = "demo --seconds 0.5 ";
    for (const std::string flag : {"--stats", "--events"})
    {
        ExpectError(RunCli(demo + flag + " /dev/full"), {"/dev/full", flag, "device"}, flag + " /dev/full");
        ExpectError(RunCli(demo + flag + " /dev/null"), {"/dev/null", flag, "device"}, flag + " /dev/null");
        ExpectError(RunCli(demo + flag + " " + (dir / "fifo.json").string()), {"fifo.json", flag, "FIFO"},
                    flag + " FIFO");
        ExpectError(RunCli(demo + flag + " " + (dir / "folder.json").string()),
                    {"folder.json", flag, "directory"}, flag + " directory");
    }
    ExpectError(RunCli(demo + "--plot " + (dir / "fifo.png").string()), {"fifo.png", "--plot", "FIFO"},
                "plot");
    ExpectError(RunCli(demo + "--plot " + (dir / "folder.png").string()), {"--plot", "directory"},
                "plot dir");
    ExpectError(RunCli("render --demo --time 0.1" + kTiny + "--out " + (dir / "fifo.png").string()),
                {"fifo.png", "--out", "FIFO"}, "render FIFO");
    ExpectError(RunCli("render --demo --time 0.1" + kTiny + "--out " + (dir / "folder.png").string()),
                {"--out", "directory"}, "render directory");
    ExpectError(RunCli("render --demo --time 0.1" + kTiny + "--out " + (dir / "f.png").string() +
                       " --stats /dev/full"),
                {"/dev/full", "--stats", "device"}, "render stats");
    ExpectError(RunCli("preset default --out /dev/full"), {"/dev/full", "--out", "device"}, "preset");
    EXPECT_TRUE(S_ISCHR(Mode("/dev/full")));
    EXPECT_TRUE(S_ISCHR(Mode("/dev/null")));
    EXPECT_TRUE(S_ISFIFO(Mode(dir / "fifo.json")));
    EXPECT_TRUE(fs::is_directory(dir / "folder.png"));
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"fifo.json", "fifo.png", "folder.json", "folder.png"}));
}

TEST(CliOutputs, ReadOnlyFilesAreRefusedEvenForRoot)
{
    const fs::path dir = ScratchDir("outputs_read_only");
    for (const char* name : {"s.json", "e.jsonl", "p.png", "r.png", "preset.json"})
    {
        WriteTestFile(dir / name, "keep");
        fs::permissions(dir / name, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    }
    const std::string demo = "demo --seconds 0.5 ";
    ExpectError(RunCli(demo + "--stats " + (dir / "s.json").string()), {"s.json", "--stats", "read-only"},
                "stats");
    ExpectError(RunCli(demo + "--events " + (dir / "e.jsonl").string()), {"e.jsonl", "read-only"}, "events");
    ExpectError(RunCli(demo + "--plot " + (dir / "p.png").string()), {"p.png", "read-only"}, "plot");
    ExpectError(RunCli("render --demo --time 0.1" + kTiny + "--out " + (dir / "r.png").string()),
                {"r.png", "read-only"}, "render");
    ExpectError(RunCli("preset tutorial --out " + (dir / "preset.json").string()),
                {"preset.json", "read-only"}, "preset");
    for (const char* name : {"s.json", "e.jsonl", "p.png", "r.png", "preset.json"})
    {
        EXPECT_EQ(FileText(dir / name), "keep") << name;
        EXPECT_EQ(Mode(dir / name) & 0777u, 0444u) << name;
    }
    EXPECT_EQ(FilesIn(dir).size(), 5u) << Join(FilesIn(dir));
}

TEST(CliOutputs, EveryProblemIsReportedBeforeTheSimulationStarts)
{
    const fs::path dir = ScratchDir("outputs_before");
    // A day of the grinder would take minutes: the refusal comes first, and with every problem.
    const CliResult both = RunCli("run --scene grinder --seconds 86400 --stats /dev/full --events " +
                                  (dir / "missing" / "e.jsonl").string());
    ExpectError(both, {"/dev/full: --stats: is a device", "--events: folder", "missing\" does not exist"},
                "two problems");
    ExpectError(RunCli("demo --seconds 86400 --stats " + (dir / "a.json").string() + " --events " +
                       (dir / "a.json").string()),
                {"a.json", "--events", "also the output of --stats"}, "one file twice");
    // The same file under two names (a hard link) is one file twice too.
    WriteTestFile(dir / "linked.json", "x\n");
    fs::create_hard_link(dir / "linked.json", dir / "link.json");
    ExpectError(RunCli("demo --seconds 86400 --stats " + (dir / "linked.json").string() + " --events " +
                       (dir / "link.json").string()),
                {"--events", "also the output of --stats"}, "one file under two names");
    EXPECT_EQ(FileText(dir / "link.json"), "x\n");
    fs::remove(dir / "linked.json");
    fs::remove(dir / "link.json");
    // Wrong extensions are among the problems, not reported one at a time before the others.
    const std::string wav = (dir / "x.wav").string();
    const std::string png = (dir / "ev.png").string();
    ExpectError(RunCli("run --scene grinder --seconds 3600 --stats /dev/full --plot " + wav + " --audio " +
                       png + " --events " + (dir / "missing" / "e.jsonl").string()),
                {"<command line>: --plot: expected a .png file, found \"" + wav + "\"",
                 "<command line>: --audio: expected a .wav file, found \"" + png + "\"",
                 "/dev/full: --stats: is a device", "--events: folder"},
                "four problems");
    EXPECT_TRUE(FilesIn(dir).empty()) << Join(FilesIn(dir));
}

TEST(CliOutputs, AFailedCommandLeavesNoOutputAndOldFilesAsTheyWere)
{
    const fs::path dir = ScratchDir("outputs_all_or_none");
    // Refused before the run: the stats that could be written are not.
    ExpectError(RunCli("demo --seconds 0.5 --stats " + (dir / "s.json").string() + " --events " +
                       (dir / "nodir" / "e.jsonl").string()),
                {"nodir"}, "missing folder");
    ExpectError(RunCli("render --demo --time 0.2" + kTiny + "--out " + (dir / "r.png").string() +
                       " --stats " + (dir / "nodir" / "s.json").string()),
                {"nodir"}, "render, missing folder");
    EXPECT_TRUE(FilesIn(dir).empty()) << Join(FilesIn(dir));

    // Failing during the run (the disk fills up with events): neither output changes.
    WriteTestFile(dir / "s.json", "old stats");
    WriteTestFile(dir / "e.jsonl", "old events");
    WriteTestFile(dir / "p.png", "old plot");
    ExpectError(RunCliLimited(16, "run --scene grinder --seconds 60 --stats " + (dir / "s.json").string() +
                                      " --events " + (dir / "e.jsonl").string() + " --plot " +
                                      (dir / "p.png").string()),
                {"e.jsonl", "--events", "File too large"}, "disk full");
    EXPECT_EQ(FileText(dir / "s.json"), "old stats");
    EXPECT_EQ(FileText(dir / "e.jsonl"), "old events");
    EXPECT_EQ(FileText(dir / "p.png"), "old plot");
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"e.jsonl", "p.png", "s.json"})) << "temporaries left";

    // A picture too big for the disk: the stats, which would fit, are not written either.
    ExpectError(RunCliLimited(8, "render --demo --time 0.5 --width 320 --height 240 --out " +
                                     (dir / "r.png").string() + " --stats " + (dir / "rs.json").string()),
                {"r.png", "--out", "File too large"}, "render disk full");
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"e.jsonl", "p.png", "s.json"}));
}

TEST(CliOutputs, ASequenceThatFailsMidwayKeepsTheFramesThatWereThere)
{
    const fs::path dir = ScratchDir("outputs_sequence");
    WriteTestFile(dir / "f_00.png", "old frame 0");
    WriteTestFile(dir / "f_07.png", "old frame 7");
    // Each 320x240 frame is larger than 4 KB: the first one already fails.
    ExpectError(RunCliLimited(8, "render --demo --seconds 1 --fps 10 --width 320 --height 240 --out " +
                                     (dir / "f_%02d.png").string()),
                {"f_00.png", "File too large"}, "sequence");
    EXPECT_EQ(FileText(dir / "f_00.png"), "old frame 0");
    EXPECT_EQ(FileText(dir / "f_07.png"), "old frame 7");
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"f_00.png", "f_07.png"}));
    // A frame that cannot be replaced is found before anything is drawn.
    fs::permissions(dir / "f_07.png", fs::perms::owner_read);
    ExpectError(
        RunCli("render --demo --seconds 1 --fps 10" + kTiny + "--out " + (dir / "f_%02d.png").string()),
        {"f_07.png", "read-only"}, "read-only frame");
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"f_00.png", "f_07.png"}));
}

TEST(CliOutputs, ReplacedFilesKeepTheirModeAndLinksKeepPointing)
{
    const fs::path dir = ScratchDir("outputs_mode");
    WriteTestFile(dir / "s.json", "old");
    fs::permissions(dir / "s.json", fs::perms::owner_read | fs::perms::owner_write);
    fs::create_directory(dir / "real");
    WriteTestFile(dir / "real" / "e.jsonl", "old");
    fs::create_symlink(dir / "real" / "e.jsonl", dir / "e.jsonl");
    const CliResult result = RunCli("demo --seconds 1 --stats " + (dir / "s.json").string() + " --events " +
                                    (dir / "e.jsonl").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(FileText(dir / "s.json"), "old");
    EXPECT_EQ(Mode(dir / "s.json") & 0777u, 0600u);
    EXPECT_TRUE(fs::is_symlink(dir / "e.jsonl"));
    EXPECT_NE(FileText(dir / "real" / "e.jsonl"), "old");
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"e.jsonl", "real", "s.json"}));
    EXPECT_EQ(FilesIn(dir / "real"), std::vector<std::string>{"e.jsonl"});
}

// An output given as a link to a file not written yet creates that file and keeps the link; two outputs
// that are one file through such a link are refused like any two outputs that are the same file.
TEST(CliOutputs, DanglingLinksAreFollowedToTheirTarget)
{
    const fs::path dir = ScratchDir("outputs_dangling");
    fs::create_directory(dir / "real");
    fs::create_symlink("real/s.json", dir / "s.json"); // relative: to the link's folder
    const CliResult result = RunCli("run --scene grinder --seconds 0.2 --stats " + (dir / "s.json").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(fs::is_symlink(dir / "s.json"));
    EXPECT_FALSE(FileText(dir / "real" / "s.json").empty());
    EXPECT_EQ(FilesIn(dir / "real"), std::vector<std::string>{"s.json"});

    fs::create_symlink("o1.json", dir / "o1link.json");
    ExpectError(RunCli("run --scene grinder --seconds 0.2 --stats " + (dir / "o1.json").string() +
                       " --events " + (dir / "o1link.json").string()),
                {"o1link.json: --events: is also the output of --stats"},
                "same file through a dangling link");
    fs::create_symlink("loop-b", dir / "loop-a");
    fs::create_symlink("loop-a", dir / "loop-b");
    ExpectError(RunCli("run --scene grinder --seconds 0.2 --stats " + (dir / "loop-a").string()),
                {"loop-a: --stats:", std::strerror(ELOOP)}, "a loop of links");
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"loop-a", "loop-b", "o1link.json", "real", "s.json"}));
}

// What a command prints is part of its result: when standard output cannot be written, the command fails
// and writes none of its files.
TEST(CliOutputs, AFailedWriteOfStandardOutputLeavesNoOutput)
{
    if (!fs::exists("/dev/full"))
    {
        GTEST_SKIP() << "no /dev/full";
    }
    const fs::path dir = ScratchDir("outputs_stdout");
    for (const std::string& args :
         {"render --scene grinder --seconds 0.2" + kTiny + "--out " + (dir / "v1.png").string(),
          "run --scene grinder --seconds 0.2 --stats " + (dir / "v1.json").string() + " --audio " +
              (dir / "v1.wav").string()})
    {
        // Standard output to /dev/full, standard error to the test.
        ExpectError(RunCommand("{ " + Binary() + " " + args + " > /dev/full; }"),
                    {"standard output: write failed"}, args);
        EXPECT_TRUE(FilesIn(dir).empty()) << args << ": " << Join(FilesIn(dir));
    }
}

TEST(CliOutputs, EventsStreamToDiskWhileTheRunGoes)
{
    const fs::path dir = ScratchDir("outputs_stream");
    // An hour of the grinder writes about 65 MB of events. With 8 KB of disk, a streamed run fails within
    // its first simulated seconds (one that kept every event in memory would run the whole hour first).
    const CliResult result =
        RunCliLimited(16, "run --scene grinder --seconds 3600 --events " + (dir / "e.jsonl").string());
    ExpectError(result, {"e.jsonl", "--events", "File too large", "s simulated)"}, "stream");
    const std::size_t after = result.output.find("(after ");
    ASSERT_NE(after, std::string::npos) << result.output;
    EXPECT_LT(std::stod(result.output.substr(after + 7)), 10.0) << result.output;
    EXPECT_TRUE(FilesIn(dir).empty()) << Join(FilesIn(dir));
}

TEST(CliOutputs, AVideoCutShortByAFullDiskIsAnErrorAndLeavesNoFile)
{
    const fs::path dir = ScratchDir("outputs_video_full");
    // ffmpeg says "File too large" yet exits 0, leaving an MP4 without its index or a GIF cut short.
    for (const char* name : {"clip.mp4", "clip.gif"})
    {
        const CliResult result = RunCliLimited(
            16, "render --demo --seconds 2 --fps 10 --width 320 --height 240 --out " + (dir / name).string());
        ExpectError(result, {name, "incomplete", "no file written"}, name);
        EXPECT_TRUE(FilesIn(dir).empty()) << name << ": " << Join(FilesIn(dir));
    }
    // The same render with room to spare is complete.
    const CliResult ok = RunCli("render --demo --seconds 2 --fps 10 --width 320 --height 240 --out " +
                                (dir / "clip.mp4").string());
    EXPECT_EQ(ok.exitCode, 0) << ok.output;
    EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"clip.mp4"});
}

TEST(CliOutputs, AnFfmpegThatExitsZeroWithABrokenVideoLeavesNoFile)
{
    // A stand-in ffmpeg that takes every frame, writes garbage where it was told and says all went well.
    const fs::path dir = ScratchDir("outputs_fake_ffmpeg");
    WriteTestFile(dir / "clip.mp4", "old video");
    const CliResult result = RunCliWithFakeFfmpeg(
        "render --demo --seconds 0.3 --fps 10" + kTiny + "--out " + (dir / "clip.mp4").string(), 0);
    ExpectError(result, {"clip.mp4", "incomplete"}, "fake ffmpeg");
    EXPECT_EQ(FileText(dir / "clip.mp4"), "old video");
    EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"clip.mp4"});
}

// A trial filled the disk while ffmpeg added the audio track: that ffmpeg exited 0, the file it wrote was
// cut short, and the message said only "ffmpeg wrote no audio stream". A stand-in ffmpeg that encodes the
// video as the real one does and then writes garbage where the audio track should be added.
TEST(CliOutputs, AVideoWhoseAudioTrackIsCutShortIsAnIncompleteVideo)
{
    const fs::path dir = ScratchDir("outputs_cut_audio");
    const CliResult real = RunCommand("command -v ffmpeg");
    ASSERT_EQ(real.exitCode, 0) << "ffmpeg is needed";
    const std::string ffmpeg = real.output.substr(0, real.output.find('\n'));
    fs::create_directories(dir / "bin");
    fs::create_directories(dir / "out");
    std::ofstream(dir / "bin" / "ffmpeg")
        << "#!/bin/sh\ncase \"$*\" in *\"-c:a aac\"*)\n"
           "  for a; do last=$a; done; echo partial > \"$last\"; exit 0;;\nesac\n"
           "exec '"
        << ffmpeg << "' \"$@\"\n";
    fs::permissions(dir / "bin" / "ffmpeg", fs::perms::owner_all);
    const CliResult result =
        RunCommand("PATH='" + (dir / "bin").string() + ":'\"$PATH\" " + std::string(CONTACTFX_BINARY_DIR) +
                   "/bin/contactfx render --scene grinder --seconds 0.5 --fps 10" + kTiny + "--out " +
                   (dir / "out" / "g.mp4").string());
    ExpectError(result, {"g.mp4", "incomplete", "a full disk?", "no file written"}, "audio cut short");
    EXPECT_TRUE(FilesIn(dir / "out").empty()) << Join(FilesIn(dir / "out"));
}

TEST(CliOutputs, AnInterruptedRunLeavesNoFile)
{
    const fs::path dir = ScratchDir("outputs_interrupted");
    const std::string events = (dir / "e.jsonl").string();
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0)
    {
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, STDOUT_FILENO);
        ::dup2(null, STDERR_FILENO);
        const std::string binary = Binary();
        ::execl(binary.c_str(), binary.c_str(), "run", "--scene", "grinder", "--seconds", "86400", "--events",
                events.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Wait until the outputs are prepared (their temporary file is there), then interrupt.
    bool started = false;
    for (int i = 0; i < 600 && !started; ++i)
    {
        started = !FilesIn(dir).empty();
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ::kill(child, SIGINT);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(started);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal instead of stopping";
    EXPECT_EQ(WEXITSTATUS(status), 1);
    EXPECT_TRUE(FilesIn(dir).empty()) << Join(FilesIn(dir));
}

namespace
{

// Starts `contactfx args...` with standard output into `stdoutFd` and standard error into `stderrFile`.
pid_t StartCli(const std::vector<std::string>& args, int stdoutFd, const fs::path& stderrFile)
{
    const pid_t child = ::fork();
    if (child == 0)
    {
        const int error = ::open(stderrFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(stdoutFd, STDOUT_FILENO);
        ::dup2(error, STDERR_FILENO);
        const std::string binary = Binary();
        std::vector<char*> argv{const_cast<char*>(binary.c_str())};
        for (const std::string& arg : args)
        {
            argv.push_back(const_cast<char*>(arg.c_str()));
        }
        argv.push_back(nullptr);
        ::execv(binary.c_str(), argv.data());
        ::_exit(127);
    }
    return child;
}

} // namespace

TEST(CliOutputs, APipeWhoseReaderIsGoneIsAFailedWriteAndLeavesNoOutput)
{
    // `contactfx run ... | head -0`: killed by SIGPIPE, it left its temporary files behind.
    const fs::path dir = ScratchDir("outputs_broken_pipe");
    const fs::path logs = ScratchDir("outputs_broken_pipe_log");
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    ::close(fds[0]); // the reader is gone before anything is written
    const pid_t child = StartCli({"run", "--scene", "grinder", "--seconds", "1", "--stats",
                                  (dir / "s.json").string(), "--events", (dir / "e.jsonl").string()},
                                 fds[1], logs / "stderr.txt");
    ::close(fds[1]);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    EXPECT_EQ(WEXITSTATUS(status), 1);
    EXPECT_NE(FileText(logs / "stderr.txt").find("standard output: write failed"), std::string::npos)
        << FileText(logs / "stderr.txt");
    EXPECT_TRUE(FilesIn(dir).empty()) << Join(FilesIn(dir));
}

TEST(CliOutputs, AnInterruptWhileBlockedStopsAtOnceAndLeavesNoOutput)
{
    // Blocked opening a FIFO nobody writes: the interrupt waited for the next write, that is for ever.
    const fs::path dir = ScratchDir("outputs_interrupt_blocked");
    const fs::path logs = ScratchDir("outputs_interrupt_blocked_log");
    ASSERT_EQ(::mkfifo((dir / "scene.json").c_str(), 0644), 0);
    const int null = ::open("/dev/null", O_WRONLY);
    const pid_t child = StartCli({"run", (dir / "scene.json").string(), "--stats", (dir / "s.json").string()},
                                 null, logs / "e.txt");
    ::close(null);
    bool prepared = false; // the stats file's temporary is there: the handlers are in place
    for (int i = 0; i < 600 && !prepared; ++i)
    {
        prepared = FilesIn(dir).size() > 1;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_TRUE(prepared);
    ::kill(child, SIGINT);
    int status = 0;
    pid_t done = 0;
    for (int i = 0; i < 250 && done == 0; ++i) // 5 s at most; it stops about a second after the signal
    {
        done = ::waitpid(child, &status, WNOHANG);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (done == 0)
    {
        ::kill(child, SIGKILL);
        ::waitpid(child, &status, 0);
        FAIL() << "still blocked 5 s after the interrupt";
    }
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 1);
    EXPECT_NE(FileText(logs / "e.txt").find("interrupted by Interrupt: no output written"), std::string::npos)
        << FileText(logs / "e.txt");
    EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"scene.json"});
}

// Reading an input, before any output exists (the effects config or a file to validate from a FIFO
// nobody writes): the interrupt stops contactfx at once with the same message, where it died silently.
TEST(CliOutputs, AnInterruptWhileReadingTheInputsStopsWithTheMessage)
{
    const fs::path dir = ScratchDir("outputs_interrupt_reading");
    const fs::path logs = ScratchDir("outputs_interrupt_reading_log");
    ASSERT_EQ(::mkfifo((dir / "fx.json").c_str(), 0644), 0);
    const std::vector<std::vector<std::string>> commands = {
        {"validate", (dir / "fx.json").string()},
        {"run", "--scene", "grinder", "--effects", (dir / "fx.json").string()}};
    for (const std::vector<std::string>& command : commands)
    {
        const int null = ::open("/dev/null", O_WRONLY);
        const pid_t child = StartCli(command, null, logs / "e.txt");
        ::close(null);
        // The handlers are in place when /proc says SIGINT is caught (SigCgt, bit SIGINT - 1).
        bool caught = false;
        for (int i = 0; i < 500 && !caught; ++i)
        {
            const std::string status = FileText("/proc/" + std::to_string(child) + "/status");
            const std::size_t at = status.find("SigCgt:");
            caught = at != std::string::npos &&
                     (std::stoull(status.substr(at + 7, 17), nullptr, 16) & (1ull << (SIGINT - 1))) != 0;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        ASSERT_TRUE(caught) << command[0];
        ::kill(child, SIGINT);
        int status = 0;
        pid_t done = 0;
        for (int i = 0; i < 250 && done == 0; ++i)
        {
            done = ::waitpid(child, &status, WNOHANG);
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        if (done == 0)
        {
            ::kill(child, SIGKILL);
            ::waitpid(child, &status, 0);
            FAIL() << command[0] << ": still running 5 s after the interrupt";
        }
        ASSERT_TRUE(WIFEXITED(status)) << command[0] << ": killed by the signal, no message";
        EXPECT_EQ(WEXITSTATUS(status), 1);
        EXPECT_EQ(FileText(logs / "e.txt"), "contactfx: error: interrupted by Interrupt: no output written\n")
            << command[0];
        EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"fx.json"});
    }
}

} // namespace cfx::test
