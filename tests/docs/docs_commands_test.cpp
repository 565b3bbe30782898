// Every command in README.md and docs/*.md runs as written from the repository root.
//
// The convention the docs follow, and this test enforces:
// - Commands to type go in fenced blocks marked ```sh (or ```bash, ```shell; in ```console blocks only
//   the lines starting with "$ "). Synopses, output and commands that cannot run unattended in a few
//   seconds (an interactive window, a full-length render, a long benchmark) go in ```text blocks or in
//   prose, which are not run.
// - The programs are spelled build/bin/contactfx and build/bin/contactfx-testbed, the paths the README's
//   build produces. Any other spelling of them in a command block (bare `contactfx`, ./contactfx, an
//   installed path) is an error: the test could not run it, and it is not on a fresh checkout's PATH.
// - A command writes into out/ (never into the source tree).
//
// For each file, every command line of its command blocks that runs one of the two programs (also
// behind `xvfb-run ...` or after `&&`) runs, in the file's order, with bash, from a scratch folder
// that mirrors the repository root: every top-level entry of the source tree linked, `build` linked
// to this build's folder, and an empty `out/`. Each must exit 0 within kCommandTimeoutSeconds, and
// each file it names after --stats, --out, --events, --plot or --screenshot must then exist and not
// be empty. Other lines (cmake, scripts) are not run.
#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace cfx::test
{

namespace
{

namespace fs = std::filesystem;

constexpr int kCommandTimeoutSeconds = 60;

const std::array<std::string, 2> kPrograms = {"build/bin/contactfx", "build/bin/contactfx-testbed"};

/// One command of a command block: a logical line (continuations joined) of a Markdown file.
struct DocCommand
{
    int line = 0;         ///< 1-based line where it starts
    std::string text;     ///< as written, continuation backslashes and line breaks replaced by spaces
    bool runsContactfx{}; ///< one of its simple commands is build/bin/contactfx[-testbed]
    std::vector<std::string> outputs; ///< files it names after an output option
};

struct DocScan
{
    int commandBlocks = 0;
    std::vector<DocCommand> commands; ///< every command of the command blocks
    std::vector<std::string> problems;
};

std::string Trim(const std::string& text)
{
    const auto begin = text.find_first_not_of(" \t\r");
    if (begin == std::string::npos)
    {
        return "";
    }
    return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

/// Shell words of a command line, split into simple commands at unquoted ;, &, | (so also && and ||);
/// quotes removed, an unquoted # starting a word ends the line.
std::vector<std::vector<std::string>> SimpleCommands(const std::string& line)
{
    std::vector<std::vector<std::string>> commands(1);
    std::string word;
    bool inWord = false;
    const auto endWord = [&]
    {
        if (inWord)
        {
            commands.back().push_back(word);
        }
        word.clear();
        inWord = false;
    };
    for (std::size_t i = 0; i < line.size(); ++i)
    {
        const char c = line[i];
        if (c == '\'' || c == '"')
        {
            inWord = true;
            const std::size_t close = line.find(c, i + 1);
            word += line.substr(i + 1, (close == std::string::npos ? line.size() : close) - i - 1);
            i = close == std::string::npos ? line.size() : close;
        }
        else if (c == '\\' && i + 1 < line.size())
        {
            inWord = true;
            word += line[++i];
        }
        else if (c == ' ' || c == '\t')
        {
            endWord();
        }
        else if (c == ';' || c == '&' || c == '|')
        {
            endWord();
            if (!commands.back().empty())
            {
                commands.emplace_back();
            }
        }
        else if (c == '#' && !inWord)
        {
            break;
        }
        else
        {
            inWord = true;
            word += c;
        }
    }
    endWord();
    return commands;
}

/// The program a simple command runs: the first word after VAR=value assignments, looking through
/// `xvfb-run [options]`.
std::string ProgramOf(const std::vector<std::string>& words)
{
    std::size_t i = 0;
    while (i < words.size() && words[i].find('=') != std::string::npos && words[i][0] != '-')
    {
        ++i;
    }
    if (i < words.size() && words[i] == "xvfb-run")
    {
        for (++i; i < words.size() && words[i][0] == '-'; ++i)
        {
            const std::string& option = words[i];
            if (option.size() == 2 && std::string("efnpsw").find(option[1]) != std::string::npos)
            {
                ++i; // the option's argument
            }
        }
    }
    return i < words.size() ? words[i] : "";
}

bool IsProgram(const std::string& word)
{
    return std::find(kPrograms.begin(), kPrograms.end(), word) != kPrograms.end();
}

/// contactfx or contactfx-testbed spelled some other way (bare, ./, an installed path).
bool IsOtherSpelling(const std::string& word)
{
    const std::string name = fs::path(word).filename().string();
    return (name == "contactfx" || name == "contactfx-testbed") && !IsProgram(word);
}

/// Classifies one command: which programs it runs, which files it writes.
void Classify(const std::string& fileName, DocCommand& command, std::vector<std::string>& problems)
{
    static const std::array<std::string, 5> kOutputOptions = {"--stats", "--out", "--events", "--plot",
                                                              "--screenshot"};
    for (const std::vector<std::string>& words : SimpleCommands(command.text))
    {
        const std::string program = ProgramOf(words);
        if (IsOtherSpelling(program))
        {
            problems.push_back(
                fileName + ":" + std::to_string(command.line) + ": '" + program +
                "' in a command block: write build/bin/" + fs::path(program).filename().string() +
                " (run from the repository root), or show it in a ```text block\n  " + command.text);
            continue;
        }
        if (!IsProgram(program))
        {
            if (std::any_of(words.begin(), words.end(), IsProgram))
            {
                problems.push_back(fileName + ":" + std::to_string(command.line) +
                                   ": runs contactfx behind '" + program +
                                   "', which the test does not run: start the command with the program "
                                   "(after VAR=value or xvfb-run)\n  " +
                                   command.text);
            }
            continue;
        }
        command.runsContactfx = true;
        for (std::size_t i = 0; i < words.size(); ++i)
        {
            for (const std::string& option : kOutputOptions)
            {
                if (words[i] == option && i + 1 < words.size())
                {
                    command.outputs.push_back(words[i + 1]);
                }
                else if (words[i].rfind(option + "=", 0) == 0)
                {
                    command.outputs.push_back(words[i].substr(option.size() + 1));
                }
            }
        }
    }
}

/// Reads the fenced command blocks of a Markdown text.
DocScan ScanMarkdown(const std::string& fileName, const std::string& markdown)
{
    DocScan scan;
    std::istringstream in(markdown);
    std::string raw;
    int lineNumber = 0;
    bool inFence = false;
    int fenceLine = 0;
    std::string language;
    DocCommand pending; // a command continued with a trailing backslash
    bool continued = false;
    while (std::getline(in, raw))
    {
        ++lineNumber;
        const std::string line = Trim(raw);
        if (line.rfind("```", 0) == 0)
        {
            if (!inFence)
            {
                inFence = true;
                fenceLine = lineNumber;
                std::istringstream info(line.substr(3));
                info >> language;
                scan.commandBlocks +=
                    language == "sh" || language == "bash" || language == "shell" || language == "console";
            }
            else if (line == "```")
            {
                if (continued)
                {
                    scan.problems.push_back(fileName + ":" + std::to_string(pending.line) +
                                            ": the command block ends inside a continued line");
                }
                inFence = false;
                continued = false;
                language.clear();
            }
            continue;
        }
        if (!inFence ||
            (language != "sh" && language != "bash" && language != "shell" && language != "console"))
        {
            continue;
        }
        std::string text = line;
        if (!continued)
        {
            if (language == "console")
            {
                if (text.rfind("$ ", 0) != 0)
                {
                    continue; // output
                }
                text = Trim(text.substr(2));
            }
            if (text.empty() || text[0] == '#')
            {
                continue;
            }
            pending = DocCommand{};
            pending.line = lineNumber;
        }
        const bool continues = !text.empty() && text.back() == '\\';
        if (continues)
        {
            text = Trim(text.substr(0, text.size() - 1));
        }
        pending.text += (continued ? " " : "") + text;
        continued = continues;
        if (!continued)
        {
            Classify(fileName, pending, scan.problems);
            scan.commands.push_back(pending);
        }
    }
    if (inFence)
    {
        scan.problems.push_back(fileName + ":" + std::to_string(fenceLine) + ": unterminated code block");
    }
    return scan;
}

std::string FileText(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The first file a name writes: a printf-style frame pattern (%d, %0Nd, %%) with frame 0.
std::string FirstFile(const std::string& name)
{
    static const std::regex kFrame("%0?[0-9]*d");
    std::string file = name;
    std::smatch match;
    if (std::regex_search(file, match, kFrame))
    {
        const std::string spec = match.str();
        const int width = spec.size() > 2 ? std::stoi(spec.substr(1, spec.size() - 2)) : 1;
        file =
            match.prefix().str() + std::string(static_cast<std::size_t>(width), '0') + match.suffix().str();
    }
    for (std::size_t at = file.find("%%"); at != std::string::npos; at = file.find("%%", at + 1))
    {
        file.erase(at, 1);
    }
    return file;
}

bool IsWithin(const fs::path& path, const fs::path& folder)
{
    const fs::path relative = path.lexically_relative(folder);
    return !relative.empty() && *relative.begin() != "..";
}

/// A scratch folder that looks like the repository root after the README's build.
fs::path MirrorRoot(const std::string& name)
{
    const fs::path source = fs::canonical(CONTACTFX_SOURCE_DIR);
    const fs::path scratch = fs::path(CONTACTFX_BINARY_DIR) / "tests" / "docs" / "scratch" / name;
    fs::remove_all(scratch);
    fs::create_directories(scratch / "root" / "out");
    for (const fs::directory_entry& entry : fs::directory_iterator(source))
    {
        const std::string entryName = entry.path().filename().string();
        if (entryName.rfind("build", 0) == 0 || entryName == "out" || entryName.rfind(".git", 0) == 0)
        {
            continue;
        }
        fs::create_symlink(entry.path(), scratch / "root" / entryName);
    }
    fs::create_directory_symlink(fs::canonical(CONTACTFX_BINARY_DIR), scratch / "root" / "build");
    return scratch;
}

struct RunReport
{
    int ran = 0;
    double seconds = 0.0;
    std::vector<std::string> problems;
};

/// Runs a scanned file's contactfx commands in a fresh mirror of the repository root.
RunReport RunCommands(const std::string& fileName, const DocScan& scan, const std::string& scratchName)
{
    RunReport report;
    const fs::path scratch = MirrorRoot(scratchName);
    const fs::path root = scratch / "root";
    const fs::path source = fs::canonical(CONTACTFX_SOURCE_DIR);
    const fs::path binary = fs::canonical(CONTACTFX_BINARY_DIR);
    for (const DocCommand& command : scan.commands)
    {
        if (!command.runsContactfx)
        {
            continue;
        }
        const std::string where = fileName + ":" + std::to_string(command.line) + ": " + command.text;
        bool intoSource = false;
        for (const std::string& output : command.outputs)
        {
            const fs::path resolved = fs::weakly_canonical(root / FirstFile(output));
            if (IsWithin(resolved, source) && !IsWithin(resolved, binary))
            {
                report.problems.push_back(where + "\n  writes " + output +
                                          " into the source tree; write into out/");
                intoSource = true;
            }
        }
        if (intoSource)
        {
            continue;
        }
        // No display: a window that waits for input fails at once instead of hanging (xvfb-run sets its own).
        // The testbed's OpenGL driver (Mesa) is unloaded at exit and leaves a few allocations LeakSanitizer
        // can neither attribute nor suppress: in sanitized builds its runs are checked for all but leaks,
        // as tests/testbed does (testbed_support.h).
        const bool openGl = command.text.find("contactfx-testbed") != std::string::npos;
        std::ofstream(scratch / "command.sh")
            << "unset DISPLAY WAYLAND_DISPLAY\n"
            << (openGl ? "export ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\"\n" : "")
            << command.text << "\n";
        const std::string shell = "cd '" + root.string() + "' && timeout " +
                                  std::to_string(kCommandTimeoutSeconds) +
                                  " bash ../command.sh </dev/null 2>&1";
        const auto start = std::chrono::steady_clock::now();
        std::string output;
        FILE* pipe = popen(shell.c_str(), "r");
        if (pipe == nullptr)
        {
            report.problems.push_back(where + "\n  could not start bash");
            continue;
        }
        std::array<char, 4096> buffer{};
        while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr)
        {
            output += buffer.data();
        }
        const int status = pclose(pipe);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++report.ran;
        report.seconds += seconds;
        std::printf("  %5.2f s  %s:%d: %s\n", seconds, fileName.c_str(), command.line, command.text.c_str());
        const int exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        if (exitCode != 0)
        {
            constexpr std::size_t kTail = 3000;
            report.problems.push_back(
                where + "\n  exit code " + std::to_string(exitCode) +
                (exitCode == 124 ? " (timed out after " + std::to_string(kCommandTimeoutSeconds) +
                                       " s: make the example shorter, or show it in a ```text block)"
                                 : "") +
                ", output:\n" +
                (output.size() > kTail ? "..." + output.substr(output.size() - kTail) : output));
            continue;
        }
        for (const std::string& name : command.outputs)
        {
            const fs::path file = root / FirstFile(name);
            std::error_code error;
            if (!fs::is_regular_file(file) || fs::file_size(file, error) == 0)
            {
                report.problems.push_back(where + "\n  exited 0 but did not write " + file.string() +
                                          " (or wrote it empty)");
            }
        }
    }
    return report;
}

std::string Joined(const std::vector<std::string>& problems)
{
    std::string text;
    for (const std::string& problem : problems)
    {
        text += problem + "\n";
    }
    return text;
}

/// README.md and docs/*.md, relative to the source folder.
std::vector<std::string> DocFiles()
{
    std::vector<std::string> files = {"README.md"};
    std::vector<std::string> docs;
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(CONTACTFX_SOURCE_DIR) / "docs"))
    {
        if (entry.path().extension() == ".md")
        {
            docs.push_back("docs/" + entry.path().filename().string());
        }
    }
    std::sort(docs.begin(), docs.end());
    files.insert(files.end(), docs.begin(), docs.end());
    return files;
}

std::string TestName(const std::string& file)
{
    std::string name = file;
    for (char& c : name)
    {
        if (std::isalnum(static_cast<unsigned char>(c)) == 0)
        {
            c = '_';
        }
    }
    return name;
}

/// Does the text talk about running the programs (in prose, tables or blocks)?
bool MentionsCommands(const std::string& text)
{
    static const std::regex kMention(
        "contactfx(-testbed\\b| (demo|run|render|validate|preset|bench|help)\\b)");
    return std::regex_search(text, kMention);
}

class DocsCommands : public testing::TestWithParam<std::string>
{
};

TEST_P(DocsCommands, RunAsWritten)
{
    const std::string file = GetParam();
    const std::string text = FileText(fs::path(CONTACTFX_SOURCE_DIR) / file);
    ASSERT_FALSE(text.empty()) << file << " is missing or empty";
    const DocScan scan = ScanMarkdown(file, text);
    EXPECT_TRUE(scan.problems.empty()) << Joined(scan.problems);

    const RunReport report = RunCommands(file, scan, TestName(file));
    std::printf("%s: %d command blocks, %zu commands, ran %d contactfx commands in %.1f s\n", file.c_str(),
                scan.commandBlocks, scan.commands.size(), report.ran, report.seconds);
    RecordProperty("commands_run", report.ran);
    EXPECT_TRUE(report.problems.empty()) << Joined(report.problems);
    if (scan.commandBlocks > 0 && MentionsCommands(text))
    {
        EXPECT_GT(report.ran, 0) << file
                                 << " has command blocks and talks about contactfx commands, but none of its "
                                    "blocks runs build/bin/contactfx: show at least one that runs as written";
    }
}

INSTANTIATE_TEST_SUITE_P(Docs, DocsCommands, testing::ValuesIn(DocFiles()),
                         [](const testing::TestParamInfo<std::string>& param)
                         { return TestName(param.param); });

// The checker itself, on Markdown written here.

TEST(DocsCommandsChecker, ReadsShBashAndConsoleBlocksOnly)
{
    const DocScan scan = ScanMarkdown("t.md", "Prose: `build/bin/contactfx run --scene nope`.\n"
                                              "```sh\n"
                                              "# a comment\n"
                                              "build/bin/contactfx --version\n"
                                              "cmake --build build\n"
                                              "```\n"
                                              "```text\n"
                                              "build/bin/contactfx run --scene nope\n"
                                              "```\n"
                                              "```console\n"
                                              "$ build/bin/contactfx help run\n"
                                              "build/bin/contactfx is output here\n"
                                              "```\n"
                                              "```bash\n"
                                              "build/bin/contactfx preset default\n"
                                              "```\n");
    EXPECT_TRUE(scan.problems.empty()) << Joined(scan.problems);
    EXPECT_EQ(scan.commandBlocks, 3);
    ASSERT_EQ(scan.commands.size(), 4u);
    EXPECT_EQ(scan.commands[0].text, "build/bin/contactfx --version");
    EXPECT_EQ(scan.commands[0].line, 4);
    EXPECT_TRUE(scan.commands[0].runsContactfx);
    EXPECT_FALSE(scan.commands[1].runsContactfx) << "cmake is not run";
    EXPECT_EQ(scan.commands[2].text, "build/bin/contactfx help run");
    EXPECT_EQ(scan.commands[3].text, "build/bin/contactfx preset default");
}

TEST(DocsCommandsChecker, JoinsContinuationsAndFindsOutputs)
{
    const DocScan scan =
        ScanMarkdown("t.md", "```sh\n"
                             "build/bin/contactfx run --scene grinder \\\n"
                             "    --seconds 1 --stats out/s.json --events=out/e.jsonl   # why\n"
                             "mkdir -p out/f && build/bin/contactfx render --demo --out "
                             "out/f/f_%04d.png\n"
                             "xvfb-run -a -s \"-screen 0 64x64x24\" build/bin/contactfx-testbed "
                             "--frames 2 --screenshot out/t.png\n"
                             "```\n");
    EXPECT_TRUE(scan.problems.empty()) << Joined(scan.problems);
    ASSERT_EQ(scan.commands.size(), 3u);
    EXPECT_EQ(scan.commands[0].text, "build/bin/contactfx run --scene grinder --seconds 1 --stats out/s.json "
                                     "--events=out/e.jsonl   # why");
    EXPECT_EQ(scan.commands[0].outputs, (std::vector<std::string>{"out/s.json", "out/e.jsonl"}));
    EXPECT_TRUE(scan.commands[1].runsContactfx);
    EXPECT_EQ(scan.commands[1].outputs, (std::vector<std::string>{"out/f/f_%04d.png"}));
    EXPECT_EQ(FirstFile(scan.commands[1].outputs[0]), "out/f/f_0000.png");
    EXPECT_EQ(FirstFile("a_%d_100%%.png"), "a_0_100%.png");
    EXPECT_TRUE(scan.commands[2].runsContactfx);
    EXPECT_EQ(scan.commands[2].outputs, (std::vector<std::string>{"out/t.png"}));
}

TEST(DocsCommandsChecker, ReportsContactfxNotSpelledBuildBin)
{
    for (const char* line : {"contactfx run --scene grinder", "./contactfx --version",
                             "/usr/local/bin/contactfx --version", "contactfx-testbed --scene grinder",
                             "cd build && bin/contactfx demo", "time build/bin/contactfx demo"})
    {
        const DocScan scan = ScanMarkdown("t.md", std::string("```sh\n") + line + "\n```\n");
        ASSERT_EQ(scan.problems.size(), 1u) << line;
        EXPECT_NE(scan.problems[0].find("t.md:2: "), std::string::npos) << scan.problems[0];
        EXPECT_NE(scan.problems[0].find("build/bin/contactfx"), std::string::npos) << scan.problems[0];
    }
    EXPECT_TRUE(ScanMarkdown("t.md", "```text\ncontactfx run --scene grinder\n```\n").problems.empty());
    EXPECT_EQ(ScanMarkdown("t.md", "```sh\nbuild/bin/contactfx run \\\n```\n").problems.size(), 1u);
    EXPECT_EQ(ScanMarkdown("t.md", "```sh\nbuild/bin/contactfx run\n").problems.size(), 1u);
}

TEST(DocsCommandsChecker, ReportsFailuresMissingOutputsAndWritesIntoTheSource)
{
    const DocScan scan = ScanMarkdown("t.md", "```sh\n"
                                              "build/bin/contactfx --version\n"
                                              "build/bin/contactfx run --scene nope --seconds 1\n"
                                              "build/bin/contactfx --version # --stats out/none.json\n"
                                              "build/bin/contactfx --version && true --stats out/none.json\n"
                                              "build/bin/contactfx preset default --out scenes/x.json\n"
                                              "```\n");
    ASSERT_TRUE(scan.problems.empty()) << Joined(scan.problems);
    ASSERT_EQ(scan.commands.size(), 5u);
    EXPECT_TRUE(scan.commands[2].outputs.empty()) << "a comment names no output";
    EXPECT_TRUE(scan.commands[3].outputs.empty()) << "only contactfx's own options name outputs";

    DocScan missing = scan;
    missing.commands[3].outputs = {"out/none.json"}; // as if contactfx had been asked to write it
    const RunReport report = RunCommands("t.md", missing, "checker");
    EXPECT_EQ(report.ran, 4) << "the write into scenes/ is refused before it runs";
    ASSERT_EQ(report.problems.size(), 3u) << Joined(report.problems);
    EXPECT_NE(report.problems[0].find("t.md:3: build/bin/contactfx run --scene nope"), std::string::npos);
    EXPECT_NE(report.problems[0].find("exit code 1"), std::string::npos) << report.problems[0];
    EXPECT_NE(report.problems[1].find("did not write"), std::string::npos) << report.problems[1];
    EXPECT_NE(report.problems[2].find("into the source tree"), std::string::npos) << report.problems[2];
    EXPECT_FALSE(fs::exists(fs::path(CONTACTFX_SOURCE_DIR) / "scenes" / "x.json"));
}

} // namespace

} // namespace cfx::test
