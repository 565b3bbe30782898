// WriteTextFileAtomically: the whole file or the old one, never over a device, a read-only file or a
// folder, and no temporary file left behind either way.
#include "contactfx/error.h"
#include "contactfx/files/text_file.h"

#include <algorithm>
#include <filesystem>
#include <gtest/gtest.h>
#include <sys/stat.h>

namespace cfx::test
{

namespace
{

namespace fs = std::filesystem;

fs::path FreshDir(const char* name)
{
    const fs::path dir = fs::temp_directory_path() / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::vector<fs::path> FilesIn(const fs::path& dir)
{
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir))
    {
        files.push_back(entry.path().filename());
    }
    std::sort(files.begin(), files.end());
    return files;
}

// The message of the InputError that writing `text` to `path` throws, or "" when none is thrown.
std::string WriteError(const fs::path& path, std::string_view text)
{
    try
    {
        WriteTextFileAtomically(path, text);
    }
    catch (const InputError& error)
    {
        return error.what();
    }
    return "";
}

} // namespace

// Every test's scratch folder is under its own build (tests/CMakeLists.txt sets TMPDIR), so the suites of
// two builds run at once on one machine never write into each other's folders.
TEST(TestScratch, FoldersAreUnderThisBuild)
{
    const fs::path scratch = fs::weakly_canonical(fs::temp_directory_path());
    const fs::path build = fs::weakly_canonical(CONTACTFX_BINARY_DIR);
    const auto [buildEnd, scratchAt] =
        std::mismatch(build.begin(), build.end(), scratch.begin(), scratch.end());
    EXPECT_EQ(buildEnd, build.end()) << scratch << " is not under " << build;
    EXPECT_TRUE(fs::is_directory(scratch)) << scratch;
}

TEST(TextFile, WritesAndReplacesAWholeFileLeavingNoTemporary)
{
    const fs::path dir = FreshDir("contactfx_test_text_file_write");
    WriteTextFileAtomically(dir / "out.json", "first");
    WriteTextFileAtomically(dir / "out.json", "second, longer");
    EXPECT_EQ(ReadTextFile(dir / "out.json"), "second, longer");
    EXPECT_EQ(FilesIn(dir), std::vector<fs::path>{"out.json"});
}

// The message of the InputError that reading `path` throws, or "" when none is thrown.
std::string ReadError(const fs::path& path)
{
    try
    {
        ReadTextFile(path);
    }
    catch (const InputError& error)
    {
        return error.what();
    }
    return "";
}

// An input longer than kMaxTextFileBytes is refused, naming the file: a regular one by its size, before
// reading (a huge sparse file costs nothing), an endless device once that much has come.
TEST(TextFile, AnInputLongerThanTheLimitIsRefused)
{
    const fs::path dir = FreshDir("contactfx_test_text_file_long");
    const fs::path huge = dir / "huge.json";
    WriteTextFileAtomically(huge, "{}");
    fs::resize_file(huge, kMaxTextFileBytes + 1); // sparse
    const std::string tooLong = ReadError(huge);
    EXPECT_EQ(tooLong, huge.string() + ": longer than 256 MiB: not read (no scene or effects config is)");
    fs::resize_file(huge, kMaxTextFileBytes);
    EXPECT_EQ(ReadError(huge), "") << "exactly the limit is read";
    fs::remove(huge);

    ASSERT_TRUE(fs::is_character_file("/dev/zero"));
    EXPECT_EQ(ReadError("/dev/zero"),
              "/dev/zero: longer than 256 MiB: not read (no scene or effects config is)");
}

TEST(TextFile, RefusesADeviceNamingIt)
{
    if (!fs::is_character_file("/dev/full"))
    {
        GTEST_SKIP() << "no /dev/full";
    }
    const std::string message = WriteError("/dev/full", "bytes");
    EXPECT_NE(message.find("/dev/full"), std::string::npos) << message;
    EXPECT_NE(message.find("device"), std::string::npos) << message;
    EXPECT_TRUE(fs::is_character_file("/dev/full")) << "still the device, not a file renamed over it";
}

TEST(TextFile, RefusesAReadOnlyFileAndLeavesItAsItWas)
{
    const fs::path dir = FreshDir("contactfx_test_text_file_read_only");
    const fs::path file = dir / "kept.json";
    WriteTextFileAtomically(file, "original");
    fs::permissions(file, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    const std::string message = WriteError(file, "replacement");
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("read-only"), std::string::npos) << message;
    EXPECT_EQ(ReadTextFile(file), "original");
    EXPECT_EQ(FilesIn(dir), std::vector<fs::path>{"kept.json"});
    fs::permissions(file, fs::perms::owner_write, fs::perm_options::add);
}

TEST(TextFile, RefusesAFolderAndLeavesItAsItWas)
{
    const fs::path dir = FreshDir("contactfx_test_text_file_folder");
    fs::create_directories(dir / "frames");
    WriteTextFileAtomically(dir / "frames" / "inside.txt", "x");
    const std::string message = WriteError(dir / "frames", "bytes");
    EXPECT_NE(message.find((dir / "frames").string()), std::string::npos) << message;
    EXPECT_NE(message.find("directory"), std::string::npos) << message;
    EXPECT_TRUE(fs::is_directory(dir / "frames"));
    EXPECT_EQ(FilesIn(dir / "frames"), std::vector<fs::path>{"inside.txt"});
    EXPECT_EQ(FilesIn(dir), std::vector<fs::path>{"frames"});
}

TEST(TextFile, AMissingFolderIsNamedAsGiven)
{
    EXPECT_EQ(OutputFileProblem("no_such_folder_cfx/out.png"),
              "folder \"no_such_folder_cfx\" does not exist");
    const std::string message = WriteError("no_such_folder_cfx/out.png", "bytes");
    EXPECT_NE(message.find("no_such_folder_cfx/out.png"), std::string::npos) << message;
    EXPECT_FALSE(fs::exists("no_such_folder_cfx"));
}

TEST(TextFile, AFileOnTheWayToTheFolderIsNamed)
{
    const fs::path dir = FreshDir("contactfx_test_text_file_on_the_way");
    WriteTextFileAtomically(dir / "afile", "x");
    const std::string named = "\"" + (dir / "afile").string() + "\" is not a folder";
    EXPECT_EQ(OutputFileProblem(dir / "afile" / "out.png"), named);
    EXPECT_EQ(OutputFileProblem(dir / "afile" / "deeper" / "out.png"), named);
    const std::string message = WriteError(dir / "afile" / "out.png", "bytes");
    EXPECT_NE(message.find(named), std::string::npos) << message;
    EXPECT_EQ(FilesIn(dir), std::vector<fs::path>{"afile"});
}

TEST(TextFile, AWriteThroughASymbolicLinkReplacesItsTargetAndKeepsTheLink)
{
    const fs::path dir = FreshDir("contactfx_test_text_file_link");
    fs::create_directories(dir / "real");
    WriteTextFileAtomically(dir / "real" / "old.png", "old");
    fs::create_symlink("real/old.png", dir / "to_old.png");
    fs::create_symlink("real/new.png", dir / "to_new.png"); // dangling: its target is not written yet
    fs::create_symlink("to_new.png", dir / "to_to_new.png");
    EXPECT_EQ(WrittenPath(dir / "to_to_new.png"), fs::canonical(dir) / "real" / "new.png");

    WriteTextFileAtomically(dir / "to_old.png", "replaced");
    WriteTextFileAtomically(dir / "to_to_new.png", "created");
    EXPECT_TRUE(fs::is_symlink(dir / "to_old.png"));
    EXPECT_TRUE(fs::is_symlink(dir / "to_new.png"));
    EXPECT_TRUE(fs::is_symlink(dir / "to_to_new.png"));
    EXPECT_EQ(ReadTextFile(dir / "real" / "old.png"), "replaced");
    EXPECT_EQ(ReadTextFile(dir / "real" / "new.png"), "created");
    EXPECT_EQ(FilesIn(dir / "real"), (std::vector<fs::path>{"new.png", "old.png"}));

    // A link into a missing folder names the folder it leads to; a loop is refused, and stays a loop.
    fs::create_symlink("gone/x.png", dir / "to_gone.png");
    EXPECT_EQ(OutputFileProblem(dir / "to_gone.png"),
              "folder \"" + (fs::canonical(dir) / "gone").string() + "\" does not exist");
    fs::create_symlink("loop_b.png", dir / "loop_a.png");
    fs::create_symlink("loop_a.png", dir / "loop_b.png");
    EXPECT_NE(WriteError(dir / "loop_a.png", "x"), "");
    EXPECT_TRUE(fs::is_symlink(dir / "loop_a.png"));
    EXPECT_EQ(FilesIn(dir), (std::vector<fs::path>{"loop_a.png", "loop_b.png", "real", "to_gone.png",
                                                   "to_new.png", "to_old.png", "to_to_new.png"}));
}

TEST(TextFile, AReplacedFileKeepsItsMode)
{
    const fs::path dir = FreshDir("contactfx_test_text_file_mode");
    const fs::path file = dir / "shared.json";
    WriteTextFileAtomically(file, "first");
    fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    WriteTextFileAtomically(file, "second");
    EXPECT_EQ(ReadTextFile(file), "second");
    EXPECT_EQ(fs::status(file).permissions(),
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST(TextFile, ReadingAFolderOrAMissingFileNamesIt)
{
    const fs::path dir = FreshDir("contactfx_test_text_file_read");
    EXPECT_THROW(ReadTextFile(dir), InputError);
    try
    {
        ReadTextFile(dir / "missing.json");
        ADD_FAILURE() << "read a missing file";
    }
    catch (const InputError& error)
    {
        EXPECT_NE(std::string(error.what()).find("missing.json"), std::string::npos) << error.what();
    }
}

} // namespace cfx::test
