// The conventions every contactfx command follows: --version, help and help COMMAND, and command lines
// that are not understood (a mistyped command or option, no command at all) answered with what was
// not understood, the nearest valid name, a pointer at --help and exit code 1.
#include "cli/cli_support.h"
#include "contactfx/version.h"

#include <cerrno>
#include <cstring>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cfx::test
{

namespace
{

// Exit code 1, every one of `expected` in the output, and nothing run.
void ExpectRefused(const std::string& args, const std::vector<std::string>& expected)
{
    const CliResult result = RunCli(args);
    EXPECT_EQ(result.exitCode, 1) << args << "\n" << result.output;
    for (const std::string& text : expected)
    {
        EXPECT_NE(result.output.find(text), std::string::npos)
            << "'" << text << "' missing for '" << args << "' in:\n"
            << result.output;
    }
    EXPECT_EQ(result.output.find("spawned:"), std::string::npos) << "simulated anyway: " << result.output;
}

} // namespace

TEST(CliConventions, VersionPrintsTheVersionOfTheHeaders)
{
    const CliResult result = RunCli("--version");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(result.output, std::string("contactfx ") + CONTACTFX_VERSION_STRING + "\n");
}

TEST(CliConventions, HelpListsTheCommandsLikeDashDashHelp)
{
    const CliResult help = RunCli("help");
    ASSERT_EQ(help.exitCode, 0) << help.output;
    EXPECT_EQ(help.output, RunCli("--help").output);
    for (const char* command : {"demo", "run", "render", "validate", "preset", "bench", "help"})
    {
        EXPECT_NE(help.output.find(std::string("\n  ") + command + " "), std::string::npos)
            << command << " not listed in:\n"
            << help.output;
    }
}

TEST(CliConventions, HelpFooterShowsExamplesAndHelpCommand)
{
    const CliResult help = RunCli("--help");
    ASSERT_EQ(help.exitCode, 0) << help.output;
    for (const char* text :
         {"contactfx demo --seconds 20 --stats out/demo-stats.json",
          "contactfx run --scene grinder --events out/grinder.jsonl",
          "contactfx render --scene rockslide --out out/rockslide.mp4", "contactfx help COMMAND"})
    {
        EXPECT_NE(help.output.find(text), std::string::npos) << "'" << text << "' missing in:\n"
                                                             << help.output;
    }
}

TEST(CliConventions, HelpCommandShowsThatCommandsHelp)
{
    const CliResult run = RunCli("help run");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output, RunCli("run --help").output);
    EXPECT_NE(run.output.find("Usage: contactfx run"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("--seconds"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("Examples:"), std::string::npos) << "the program's footer in: " << run.output;

    const CliResult particles = RunCli("help bench particles");
    ASSERT_EQ(particles.exitCode, 0) << particles.output;
    EXPECT_EQ(particles.output, RunCli("bench particles --help").output);
    EXPECT_NE(particles.output.find("--count"), std::string::npos) << particles.output;
}

TEST(CliConventions, HelpForAnUnknownCommandIsAnError)
{
    ExpectRefused("help nosuch", {"contactfx: error: unknown command 'nosuch'", "demo, run, render",
                                  "See 'contactfx --help'"});
    ExpectRefused("help rnu", {"unknown command 'rnu'", "did you mean 'run'?"});
    ExpectRefused("help bench partcles",
                  {"unknown command 'partcles' for 'contactfx bench'", "did you mean 'particles'?"});
    ExpectRefused("help run extra",
                  {"contactfx: error: unknown command 'extra' for 'contactfx run'; it has no commands\n"});
}

TEST(CliConventions, MistypedCommandIsNamedWithTheNearestOne)
{
    ExpectRefused(
        "rnu", {"contactfx: error: unknown command 'rnu'", "did you mean 'run'?", "See 'contactfx --help'"});
    ExpectRefused("rendr --out x.png", {"unknown command 'rendr'", "did you mean 'render'?"});
    ExpectRefused("bench partcles --count 10", {"unknown command 'partcles' for 'contactfx bench'",
                                                "did you mean 'particles'?", "See 'contactfx bench --help'"});
    const CliResult far = RunCli("nosuch");
    EXPECT_EQ(far.exitCode, 1);
    EXPECT_EQ(far.output.find("did you mean"), std::string::npos) << "nothing is near: " << far.output;
}

TEST(CliConventions, MistypedOptionIsNamedWithTheNearestOne)
{
    ExpectRefused("run --secnds 2", {"contactfx: error: unknown option '--secnds' for 'contactfx run'",
                                     "did you mean '--seconds'?", "See 'contactfx run --help'"});
    ExpectRefused("run --scene grinder --secnds=2",
                  {"unknown option '--secnds'", "did you mean '--seconds'?"});
    ExpectRefused("demo --seconds 1 --stat out.json", {"unknown option '--stat'", "did you mean '--stats'?"});
    ExpectRefused("--verison", {"unknown option '--verison'", "did you mean '--version'?"});
}

TEST(CliConventions, NoCommandShowsTheShortUsage)
{
    const CliResult result = RunCli("");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("contactfx: error: missing command"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("Usage: contactfx [OPTIONS] COMMAND"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("demo, run, render"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("'contactfx --help'"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("A subcommand is required"), std::string::npos) << result.output;
}

// A file option or argument given an empty value names no file: refused while parsing (nothing is read,
// simulated or written), never taken as "not given".
TEST(CliConventions, AnEmptyFileNameIsRefused)
{
    const std::string run = "run --scene grinder --seconds 0.2 ";
    // Where a command that took an empty name as "not given" would write its other output.
    const std::string png = (ScratchDir("empty_file_name") / "x.png").string();
    const struct
    {
        std::string args;
        std::string name;
        std::string command;
    } cases[] = {
        {run + "--effects ''", "--effects", "run"},
        {run + "--stats ''", "--stats", "run"},
        {run + "--events ''", "--events", "run"},
        {run + "--plot ''", "--plot", "run"},
        {run + "--audio ''", "--audio", "run"},
        {run + "--voices ''", "--voices", "run"},
        {"run '' --seconds 0.2", "scene", "run"},
        {"demo --seconds 0.2 --events ''", "--events", "demo"},
        {"preset default --out ''", "--out", "preset"},
        {"render --demo --out ''", "--out", "render"},
        {"render --demo --seconds 0.2 --out " + png + " --audio ''", "--audio", "render"},
        {"validate ''", "files", "validate"},
        {"validate --effects '' x.json", "--effects", "validate"},
    };
    for (const auto& refused : cases)
    {
        const CliResult result = RunCli(refused.args);
        EXPECT_EQ(result.exitCode, 1) << refused.args << "\n" << result.output;
        EXPECT_EQ(result.output, "contactfx: error: <command line>: " + refused.name +
                                     ": names no file\nSee 'contactfx " + refused.command + " --help'.\n")
            << refused.args;
    }
}

// A trial found the help pointer after `--threads 0` (CLI11's check) but not after `--hz 0` (the command's
// own range check): every error about the command line alone now ends with it, whoever found it.
TEST(CliConventions, EveryCommandLineErrorPointsAtTheHelp)
{
    const struct
    {
        std::string args;
        std::string line;
        std::string command;
    } cases[] = {
        {"run --scene grinder --hz 0", "--hz: expected a number in [1, 10000], found 0", "run"},
        {"run --scene grinder --seconds -1", "--seconds: expected a number in (0, 86400], found -1", "run"},
        {"render --demo --time nan --out x.png", "--time: expected a number in [0, 86400], found nan",
         "render"},
        {"run --scene grinder --threads 0", "--threads: expected a whole number from 1 to 8, found \"0\"",
         "run"},
    };
    for (const auto& refused : cases)
    {
        const CliResult result = RunCli(refused.args);
        EXPECT_EQ(result.exitCode, 1) << refused.args << "\n" << result.output;
        EXPECT_EQ(result.output, "contactfx: error: <command line>: " + refused.line + "\nSee 'contactfx " +
                                     refused.command + " --help'.\n")
            << refused.args;
    }
    const CliResult file = RunCli("run nonexistent.json");
    EXPECT_EQ(file.output.find("--help"), std::string::npos) << "a file's error is not the command line's";
}

// What CLI11 itself finds wrong is said in the project's format, naming the option or argument.
TEST(CliConventions, ParseErrorsNameTheCommandLineAndTheOption)
{
    const CliResult noFiles = RunCli("validate");
    EXPECT_EQ(noFiles.exitCode, 1) << noFiles.output;
    EXPECT_EQ(noFiles.output, "contactfx: error: <command line>: files: required, but not given\n"
                              "See 'contactfx validate --help'.\n");
    ExpectRefused("render --demo", {"contactfx: error: <command line>: --out: required, but not given"});
    ExpectRefused("run --scene grinder --seconds abc",
                  {"contactfx: error: <command line>: --seconds: expected a number, found \"abc\""});
    ExpectRefused("run --scene grinder --preset nosuch",
                  {"contactfx: error: <command line>: --preset: nosuch not in {default,tutorial}"});
}

// A whole-number option outside its range, beyond what its type holds or not a whole number at all says
// the range it takes and the value as given.
TEST(CliConventions, WholeNumbersOutOfRangeNameTheRange)
{
    ExpectRefused("bench debris --boxes 10001",
                  {"<command line>: --boxes: expected a whole number from 1 to 10000, found \"10001\"\n"});
    ExpectRefused("bench debris --boxes 4294967296", {"--boxes: expected a whole number from 1 to 10000, "
                                                      "found \"4294967296\""});
    ExpectRefused("bench debris --boxes -3",
                  {"--boxes: expected a whole number from 1 to 10000, found \"-3\""});
    ExpectRefused("bench particles --count 1e3", {"--count: expected a whole number from 1 to 4000000"});
    ExpectRefused("bench particles --count 5 --threads 9",
                  {"--threads: expected a whole number from 0 to 8"});
    ExpectRefused("run --scene grinder --threads 0", {"--threads: expected a whole number from 1 to 8"});
    ExpectRefused("bench particles --count 08x", {"--count: expected a whole number from 1 to 4000000"});
    // Decimal whatever the zeros and sign: CLI11 alone reads "010" as octal 8.
    const CliResult decimal =
        RunCli("bench particles --count +010 --steps 010 --warmup 0 --threads 1 --json");
    ASSERT_EQ(decimal.exitCode, 0) << decimal.output;
    const nlohmann::json result = nlohmann::json::parse(decimal.output);
    EXPECT_EQ(result["count"], 10);
    EXPECT_EQ(result["steps"], 10);
    EXPECT_NE(RunCli("bench debris --help").output.find("[1 - 10000]"), std::string::npos);
}

// What a command prints on standard output is its result: a failed write of it (a full disk) is an error
// on stderr and exit code 1, not a silent success.
TEST(CliConventions, AFailedWriteOfStandardOutputIsAnError)
{
    if (!std::filesystem::exists("/dev/full"))
    {
        GTEST_SKIP() << "no /dev/full";
    }
    for (const std::string& args :
         {std::string("preset default"), "validate --json " + Scene("grinder.json"), std::string("help"),
          std::string("--help"), std::string("--version"), std::string("demo --seconds 0.1")})
    {
        // Standard output to /dev/full, standard error to the test.
        const CliResult result = RunCommand("{ " + std::string(CONTACTFX_BINARY_DIR) + "/bin/contactfx " +
                                            args + " > /dev/full; }");
        EXPECT_EQ(result.exitCode, 1) << args << "\n" << result.output;
        EXPECT_NE(result.output.find("contactfx: error: standard output: write failed"), std::string::npos)
            << args << "\n"
            << result.output;
    }
    const CliResult full =
        RunCommand("{ " + std::string(CONTACTFX_BINARY_DIR) + "/bin/contactfx preset default > /dev/full; }");
    EXPECT_EQ(full.output, "contactfx: error: standard output: write failed: " +
                               std::string(std::strerror(ENOSPC)) + "\n");
}

} // namespace cfx::test
