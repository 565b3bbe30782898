// OutputFiles::Commit against interrupts, in-process (the CLI tests cannot time a signal into it). A trial
// sent Ctrl-C while a 24,000-frame sequence was being renamed into place: the command said "no output
// written" with every frame replaced and 20,000 backups left, because the signal's one-second grace ran
// out in the middle of the renames. And a temporary file that replaced a 0640 file was readable by all
// while the command ran.
#include "cli/cli_support.h"
#include "outputs.h"

#include <algorithm>
#include <atomic>
#include <csignal>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <thread>

namespace cfx::cli
{
namespace
{

namespace fs = std::filesystem;
using test::FilesIn;
using test::FileText;
using test::ScratchDir;
using test::WriteTestFile;

constexpr int kOutputs = 5;

// Writes "new i" into every output of `dir` through an OutputFiles and commits, calling `beforeRename`
// before each rename.
void WriteAll(const fs::path& dir, const std::function<void(std::size_t)>& beforeRename)
{
    OutputFiles outputs;
    std::vector<OutputFiles::Handle> handles;
    for (int i = 0; i < kOutputs; ++i)
    {
        handles.push_back(outputs.Add("--out", dir / ("f" + std::to_string(i) + ".txt")));
    }
    outputs.Prepare();
    for (int i = 0; i < kOutputs; ++i)
    {
        outputs.Write(handles[i], "new " + std::to_string(i));
    }
    outputs.OnEachFile(
        [&](OutputFiles::FileStep step, std::size_t index)
        {
            if (step == OutputFiles::FileStep::renaming)
            {
                beforeRename(index);
            }
        });
    outputs.Commit();
}

void WriteOld(const fs::path& dir)
{
    for (int i = 0; i < kOutputs; ++i)
    {
        WriteTestFile(dir / ("f" + std::to_string(i) + ".txt"), "old " + std::to_string(i));
    }
}

const std::vector<std::string> kTargets{"f0.txt", "f1.txt", "f2.txt", "f3.txt", "f4.txt"};

// The signal lands on this thread, or on another one (the CLI's particle threads, ffmpeg's feeder): a
// re-check found the first fix, which blocked signals on the committing thread only, did nothing when the
// signal went to another.
TEST(OutputsCommit, AnInterruptDuringTheRenamesWaitsForThemAllAndSaysTheOutputsWereWritten)
{
    for (const bool otherThread : {false, true})
    {
        SCOPED_TRACE(otherThread ? "signal on another thread" : "signal on the committing thread");
        const fs::path dir =
            ScratchDir(otherThread ? "outputs_commit_interrupt_other" : "outputs_commit_interrupt");
        WriteOld(dir);
        // Started before the commit, as the CLI's threads are, and told to raise the signal during it.
        std::atomic<int> stage{0}; // 1: raise it; 2: raised
        std::thread other(
            [&]
            {
                while (stage.load() == 0)
                {
                    std::this_thread::yield();
                }
                if (stage.load() == 1)
                {
                    ::raise(SIGINT); // to this thread
                    stage.store(2);
                }
            });
        std::string message;
        try
        {
            WriteAll(dir,
                     [&](std::size_t index)
                     {
                         if (index != 1)
                         {
                             return;
                         }
                         if (!otherThread)
                         {
                             ::raise(SIGINT); // after the first rename
                             return;
                         }
                         stage.store(1);
                         while (stage.load() != 2)
                         {
                             std::this_thread::yield();
                         }
                     });
        }
        catch (const std::runtime_error& error)
        {
            message = error.what();
        }
        stage.store(3); // lets the other thread end if it was not asked
        other.join();
        EXPECT_EQ(message, "interrupted by Interrupt after its outputs were written");
        EXPECT_EQ(FilesIn(dir), kTargets) << "no temporary or backup file left";
        for (int i = 0; i < kOutputs; ++i)
        {
            EXPECT_EQ(FileText(dir / kTargets[i]), "new " + std::to_string(i)) << "every output written";
        }
    }
}

// The handler reads the list of temporary files, which Prepare grows: a signal landing on another thread
// then could read it while it moved (a second signal makes the handler remove the files it lists and exit at
// once). While Prepare makes the files a signal is only noted, even a second one, and Prepare then unwinds,
// leaving no file.
TEST(OutputsCommit, AnInterruptWhilePreparingOnAnotherThreadLeavesNoFile)
{
    const fs::path dir = ScratchDir("outputs_prepare_interrupt");
    WriteOld(dir);
    std::atomic<int> stage{0}; // 1: raise it; 2: raised; 3: done
    std::thread other(
        [&]
        {
            while (stage.load() == 0)
            {
                std::this_thread::yield();
            }
            if (stage.load() == 1)
            {
                ::raise(SIGINT);
                ::raise(SIGINT);
                stage.store(2);
            }
        });
    std::string message;
    {
        OutputFiles outputs;
        for (int i = 0; i < kOutputs; ++i)
        {
            outputs.Add("--out", dir / ("f" + std::to_string(i) + ".txt"));
        }
        outputs.OnEachFile(
            [&](OutputFiles::FileStep step, std::size_t index)
            {
                if (step == OutputFiles::FileStep::prepared && index == 1)
                {
                    stage.store(1);
                    while (stage.load() != 2)
                    {
                        std::this_thread::yield();
                    }
                }
            });
        try
        {
            outputs.Prepare();
        }
        catch (const std::runtime_error& error)
        {
            message = error.what();
        }
    }
    stage.store(3);
    other.join();
    EXPECT_EQ(message, "interrupted by Interrupt: no output written");
    EXPECT_EQ(FilesIn(dir), kTargets) << "no temporary file left";
    for (int i = 0; i < kOutputs; ++i)
    {
        EXPECT_EQ(FileText(dir / kTargets[i]), "old " + std::to_string(i));
    }
}

TEST(OutputsCommit, AnInterruptBeforeTheRenamesLeavesEveryOldFile)
{
    const fs::path dir = ScratchDir("outputs_commit_before");
    WriteOld(dir);
    OutputFiles outputs;
    const OutputFiles::Handle handle = outputs.Add("--out", dir / "f0.txt");
    outputs.Prepare();
    outputs.Write(handle, "new 0");
    ::raise(SIGINT); // caught: the handler notes it, and Commit unwinds before renaming anything
    EXPECT_THROW(outputs.Commit(), std::runtime_error);
    EXPECT_EQ(FileText(dir / "f0.txt"), "old 0");
}

TEST(OutputsCommit, ATemporaryFileHasTheModeOfTheFileItReplacesFromTheStart)
{
    const fs::path dir = ScratchDir("outputs_commit_mode");
    WriteTestFile(dir / "f0.txt", "old 0");
    ASSERT_EQ(::chmod((dir / "f0.txt").c_str(), 0640), 0);
    OutputFiles outputs;
    const OutputFiles::Handle handle = outputs.Add("--out", dir / "f0.txt");
    const OutputFiles::Handle fresh = outputs.Add("--out", dir / "f1.txt");
    outputs.Prepare();
    struct stat info = {};
    ASSERT_EQ(::stat(outputs.Temporary(handle).c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777u, 0640u);
    ASSERT_EQ(::stat(outputs.Temporary(fresh).c_str(), &info), 0);
    const mode_t mask = ::umask(0);
    ::umask(mask);
    EXPECT_EQ(info.st_mode & 0777u, 0666u & ~mask) << "a new file as any other";
    outputs.Write(handle, "new 0");
    outputs.Write(fresh, "new 1");
    outputs.Commit();
    ASSERT_EQ(::stat((dir / "f0.txt").c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777u, 0640u);
}

} // namespace
} // namespace cfx::cli
