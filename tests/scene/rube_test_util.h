// Helpers for the scene tests: the shared sample files and reading their JSON independently of the library.
#pragma once

#include "contactfx/scene/rube.h"
#include "rube_samples_dir.h"

#include <algorithm>
#include <bit>
#include <box2d/box2d.h>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace cfx::test
{

/// The project's own scenes (scenes/*.json, effects configs left out).
inline std::filesystem::path ProjectScene(const char* name)
{
    return std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes" / name;
}

/// Every RUBE scene the tests can read: the project's own scenes, then ../shared/rube-samples/*.json
/// when that folder exists (see rube_samples_dir.h; RubeSamples.SharedFolder says when it does not).
inline std::vector<std::filesystem::path> SampleFiles()
{
    std::vector<std::filesystem::path> files;
    auto addJsonFiles = [&files](const std::filesystem::path& folder)
    {
        std::vector<std::filesystem::path> found;
        for (const auto& entry : std::filesystem::directory_iterator(folder))
        {
            const std::string name = entry.path().filename().string();
            if (entry.path().extension() == ".json" && !name.ends_with(".effects.json"))
            {
                found.push_back(entry.path());
            }
        }
        std::sort(found.begin(), found.end());
        files.insert(files.end(), found.begin(), found.end());
    };
    addJsonFiles(std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes");
    if (HaveRubeSamples())
    {
        addJsonFiles(RubeSamplesDir());
    }
    return files;
}

/// GoogleTest name of a sample file parameter: its stem with non-alphanumerics replaced.
inline std::string SampleTestName(const ::testing::TestParamInfo<std::filesystem::path>& sample)
{
    std::string name = sample.param.stem().string();
    for (char& c : name)
    {
        if (!std::isalnum(static_cast<unsigned char>(c)))
        {
            c = '_';
        }
    }
    return name;
}

inline std::string ReadText(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

inline nlohmann::json ReadJson(const std::filesystem::path& path)
{
    return nlohmann::json::parse(ReadText(path));
}

/// A b2dJson number: plain, or 8 hex digits of IEEE float bits.
inline float JsonFloat(const nlohmann::json& value)
{
    if (value.is_string())
    {
        return std::bit_cast<float>(
            static_cast<std::uint32_t>(std::stoul(value.get<std::string>(), nullptr, 16)));
    }
    return static_cast<float>(value.get<double>());
}

inline float JsonFloat(const nlohmann::json& object, const char* key, float fallback)
{
    auto it = object.find(key);
    return it == object.end() ? fallback : JsonFloat(*it);
}

/// A b2dJson vector: {"x", "y"} or 0.
inline b2Vec2 JsonVec(const nlohmann::json& object, const char* key)
{
    auto it = object.find(key);
    if (it == object.end() || it->is_number())
    {
        return b2Vec2(0.0f, 0.0f);
    }
    return b2Vec2(JsonFloat((*it)["x"]), JsonFloat((*it)["y"]));
}

inline bool HasDiagnostic(const std::vector<Diagnostic>& diagnostics, const std::string& path,
                          const std::string& messagePart = "")
{
    for (const Diagnostic& diagnostic : diagnostics)
    {
        if (diagnostic.path == path && diagnostic.message.find(messagePart) != std::string::npos)
        {
            return true;
        }
    }
    return false;
}

inline std::string Dump(const std::vector<Diagnostic>& diagnostics)
{
    std::string text;
    for (const Diagnostic& diagnostic : diagnostics)
    {
        text += diagnostic.ToString() + "\n";
    }
    return text;
}

/// The diagnostics LoadRubeString throws for `json` (fails the test when it loads).
inline std::vector<Diagnostic> LoadErrors(const std::string& json)
{
    try
    {
        LoadRubeString(json, "test.json");
    }
    catch (const InputError& error)
    {
        return error.Diagnostics();
    }
    ADD_FAILURE() << "expected InputError for: " << json;
    return {};
}

/// A world with the given bodies and joints around them (JSON text of the arrays' contents).
inline std::string World(const std::string& bodies, const std::string& joints = "",
                         const std::string& extra = "")
{
    return R"({"gravity": {"x": 0, "y": -10}, "body": [)" + bodies + R"(], "joint": [)" + joints + "]" +
           (extra.empty() ? "" : ", " + extra) + "}";
}

/// A dynamic body with one unit box fixture at `x`.
inline std::string Box(float x, int type = 2, const std::string& more = "")
{
    return R"({"type": )" + std::to_string(type) + R"(, "position": {"x": )" + std::to_string(x) +
           R"(, "y": 0}, "awake": true, "fixture": [{"density": 1, "friction": 0.5,
              "polygon": {"vertices": {"x": [0.5, 0.5, -0.5, -0.5], "y": [-0.5, 0.5, 0.5, -0.5]}}}])" +
           (more.empty() ? "" : ", " + more) + "}";
}

} // namespace cfx::test
