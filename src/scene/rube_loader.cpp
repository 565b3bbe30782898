// LoadRubeFile, LoadRubeString, ValidateRubeFile: text -> JSON -> checked document -> Scene.
#include "contactfx/files/text_file.h"
#include "contactfx/scene/rube.h"
#include "scene/json_text.h"
#include "scene/rube_reader.h"
#include "scene/scene_builder.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <system_error>

namespace cfx
{

namespace
{

struct LoadOutcome
{
    std::optional<Scene> scene;
    SceneCounts counts;
    std::vector<Diagnostic> diagnostics;
    std::vector<Diagnostic> warnings;
};

LoadOutcome Load(std::string_view text, const std::string& fileName)
{
    LoadOutcome outcome;
    scene_detail::DiagnosticList diagnostics(fileName);
    std::optional<scene_detail::Json> root = scene_detail::ParseJsonText(text, diagnostics);
    if (root)
    {
        scene_detail::RubeDocument document = scene_detail::ReadRubeDocument(*root, diagnostics);
        root.reset();
        outcome.counts = document.counts;
        if (diagnostics.Empty())
        {
            Scene scene = scene_detail::BuildScene(document, diagnostics);
            if (diagnostics.Empty())
            {
                outcome.scene = std::move(scene);
                outcome.scene->warnings = diagnostics.Warnings();
            }
        }
    }
    outcome.diagnostics = diagnostics.Take();
    outcome.warnings = diagnostics.TakeWarnings();
    return outcome;
}

/// The whole file, or nothing after adding why it cannot be read.
std::optional<std::string> ReadFile(const std::filesystem::path& path, std::vector<Diagnostic>& diagnostics)
{
    try
    {
        return ReadTextFile(path);
    }
    catch (const InputError& error)
    {
        diagnostics.insert(diagnostics.end(), error.Diagnostics().begin(), error.Diagnostics().end());
        return std::nullopt;
    }
}

} // namespace

Scene LoadRubeString(std::string_view json, std::string_view fileName)
{
    LoadOutcome outcome = Load(json, std::string(fileName));
    if (!outcome.scene)
    {
        throw InputError(std::move(outcome.diagnostics));
    }
    return std::move(*outcome.scene);
}

Scene LoadRubeFile(const std::filesystem::path& path)
{
    std::vector<Diagnostic> diagnostics;
    std::optional<std::string> text = ReadFile(path, diagnostics);
    if (!text)
    {
        throw InputError(std::move(diagnostics));
    }
    return LoadRubeString(*text, path.string());
}

std::vector<Diagnostic> ValidateRubeString(std::string_view json, std::string_view fileName,
                                           SceneCounts* counts, std::vector<Diagnostic>* warnings)
{
    LoadOutcome outcome = Load(json, std::string(fileName));
    if (counts != nullptr)
    {
        *counts = outcome.counts;
    }
    if (warnings != nullptr)
    {
        *warnings = std::move(outcome.warnings);
    }
    return std::move(outcome.diagnostics);
}

std::vector<Diagnostic> ValidateRubeFile(const std::filesystem::path& path, SceneCounts* counts,
                                         std::vector<Diagnostic>* warnings)
{
    if (warnings != nullptr)
    {
        warnings->clear();
    }
    std::vector<Diagnostic> diagnostics;
    std::optional<std::string> text = ReadFile(path, diagnostics);
    if (!text)
    {
        if (counts != nullptr)
        {
            *counts = SceneCounts{};
        }
        return diagnostics;
    }
    return ValidateRubeString(*text, path.string(), counts, warnings);
}

} // namespace cfx
