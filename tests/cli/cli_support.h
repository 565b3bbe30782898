// Running the contactfx binary from tests.
#pragma once

#include "rube_samples_dir.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace cfx::test
{

struct CliResult
{
    int exitCode = -1;
    std::string output; ///< stdout and stderr together
};

/// Runs a shell command line and captures its output (stdout and stderr together).
inline CliResult RunCommand(const std::string& commandLine)
{
    const std::string command = commandLine + " 2>&1";
    CliResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr)
    {
        return result;
    }
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr)
    {
        result.output += buffer.data();
    }
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

/// Runs `contactfx ARGS` (ARGS as shell words) and captures its output.
inline CliResult RunCli(const std::string& args)
{
    return RunCommand(std::string(CONTACTFX_BINARY_DIR) + "/bin/contactfx " + args);
}

/// Runs `contactfx ARGS` with a stand-in `ffmpeg` first on PATH: one that reads every frame, writes
/// "partial" to the file it was told to write (its last argument) and exits with `exitStatus`.
inline CliResult RunCliWithFakeFfmpeg(const std::string& args, int exitStatus)
{
    const std::filesystem::path bin =
        std::filesystem::temp_directory_path() / ("contactfx_test_fake_ffmpeg_" + std::to_string(exitStatus));
    std::filesystem::create_directories(bin);
    std::ofstream(bin / "ffmpeg") << "#!/bin/sh\ncat > /dev/null\nfor a; do last=$a; done\n"
                                     "echo partial > \"$last\"\nexit "
                                  << exitStatus << "\n";
    std::filesystem::permissions(bin / "ffmpeg", std::filesystem::perms::owner_all);
    const char* saved = std::getenv("PATH");
    const std::string path = saved != nullptr ? saved : "";
    return RunCommand("PATH='" + bin.string() + ":" + path + "' " + std::string(CONTACTFX_BINARY_DIR) +
                      "/bin/contactfx " + args);
}

/// A fresh scratch folder for one test.
inline std::filesystem::path ScratchDir(const std::string& name)
{
    std::filesystem::path dir = std::filesystem::temp_directory_path() / ("contactfx_test_" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string Scene(const char* name)
{
    return std::string(CONTACTFX_SOURCE_DIR) + "/scenes/" + name;
}

/// A real RUBE scene of ../shared/rube-samples; tests that use one start with
/// CONTACTFX_REQUIRE_RUBE_SAMPLES().
inline std::string Sample(const char* name)
{
    return (RubeSamplesDir() / name).string();
}

/// A file's bytes ("" when it cannot be read).
inline std::string FileText(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// The particles of `type` a run spawned, from its --stats file.
inline std::uint64_t Spawned(const std::filesystem::path& stats, const char* type)
{
    return nlohmann::json::parse(FileText(stats))["spawned"][type].get<std::uint64_t>();
}

/// Every name in `dir`, hidden temporary files included, sorted.
inline std::vector<std::string> FilesIn(const std::filesystem::path& dir)
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
    {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

/// Writes a test input (not atomically: tests only).
inline void WriteTestFile(const std::filesystem::path& path, const std::string& text)
{
    std::ofstream(path, std::ios::binary) << text;
}

} // namespace cfx::test
