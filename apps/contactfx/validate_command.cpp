// contactfx validate FILE...: every problem of every file, in one pass.
//
// A user fixing a scene exported from RUBE or a hand-tuned effects config wants the whole list at once:
// each problem names the file, the JSON path, what was expected and what was found (line and column for
// malformed JSON). A scene is also checked against the effects config that `run` would use with the same
// --preset/--effects, so that a scene that validates also runs: its `material` properties must name
// materials of that config. Files are only read, never written.
//
// Warnings (a scene's unknown keys, polygon vertices Box2D drops) are listed but do not fail a file;
// --strict counts them as errors.
//
// Which reader a file gets: --as, else a name ending in `.effects.json` means an effects config, else the
// content decides (a top-level object with effects keys and none of RUBE's is an effects config).
#include "validate_command.h"

#include "cli_common.h"
#include "contactfx/files/text_file.h"
#include "contactfx/scene/effects_json.h"
#include "contactfx/scene/rube.h"
#include "contactfx/scene/scene_materials.h"

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace cfx::cli
{

namespace
{

enum class FileKind
{
    scene,
    effects,
};

struct Options
{
    std::vector<std::string> files;
    bool json = false;
    bool strict = false;
    std::string as = "auto";
    RunOptions effects; ///< only --preset and --effects are used
};

/// What one file turned out to be.
struct Report
{
    Report(std::string name, FileKind what) : file(std::move(name)), kind(what) {}

    std::string file;
    FileKind kind;
    SceneCounts counts;
    int fixturesWithMaterial = 0;
    std::optional<EffectsConfig> config; ///< effects configs that loaded
    std::vector<Diagnostic> errors;
    std::vector<Diagnostic> warnings;
};

bool EndsWith(const std::string& text, const std::string& suffix)
{
    return text.size() >= suffix.size() &&
           text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

FileKind Classify(const std::string& file, const std::string& text, const std::string& as)
{
    if (as != "auto")
    {
        return as == "effects" ? FileKind::effects : FileKind::scene;
    }
    if (EndsWith(file, ".effects.json"))
    {
        return FileKind::effects;
    }
    const nlohmann::json root = nlohmann::json::parse(text, nullptr, false);
    if (!root.is_object())
    {
        return FileKind::scene; // malformed or not an object: either reader reports it the same way
    }
    bool effectsKey = false;
    bool sceneKey = false;
    for (const char* key : {"materials", "particleTypes", "rules", "assignments", "budget"})
    {
        effectsKey = effectsKey || root.contains(key);
    }
    for (const char* key : {"body", "joint", "image", "gravity", "stepsPerSecond"})
    {
        sceneKey = sceneKey || root.contains(key);
    }
    return effectsKey && !sceneKey ? FileKind::effects : FileKind::scene;
}

Report CheckEffects(const std::string& file, const std::string& text)
{
    Report report(file, FileKind::effects);
    try
    {
        report.config = LoadEffectsString(text, file);
    }
    catch (const InputError& error)
    {
        report.errors = error.Diagnostics();
    }
    return report;
}

// `config`: what the scene's materials are checked against; nullptr when --effects failed to load, which
// leaves the scene not fully checked: an error of its own, not "ok".
Report CheckScene(const std::string& file, const std::string& text, const EffectsConfig* config,
                  const std::string& effectsFile)
{
    Report report(file, FileKind::scene);
    report.errors = ValidateRubeString(text, file, &report.counts, &report.warnings);
    if (!report.errors.empty())
    {
        return report;
    }
    if (config == nullptr)
    {
        report.errors.push_back(Diagnostic{file, "",
                                           "materials not checked: the effects config \"" + effectsFile +
                                               "\" (--effects) has problems"});
        return report;
    }
    try
    {
        const Scene scene = LoadRubeString(text, file);
        for (MaterialId material : ResolveSceneMaterials(scene, *config, file))
        {
            report.fixturesWithMaterial += material.IsValid() ? 1 : 0;
        }
    }
    catch (const InputError& error)
    {
        report.errors = error.Diagnostics();
    }
    return report;
}

Report Check(const std::string& file, const Options& options, const EffectsConfig* config)
{
    std::string text;
    try
    {
        text = ReadTextFile(file);
    }
    catch (const InputError& error)
    {
        Report report(file, Classify(file, "", options.as)); // by --as or by name
        report.errors = error.Diagnostics();
        return report;
    }
    Report report = Classify(file, text, options.as) == FileKind::effects
                        ? CheckEffects(file, text)
                        : CheckScene(file, text, config, options.effects.effects);
    if (options.strict)
    {
        for (Diagnostic& warning : report.warnings)
        {
            warning.warning = false;
            report.errors.push_back(std::move(warning));
        }
        report.warnings.clear();
    }
    return report;
}

void PrintJson(const Report& report)
{
    using OrderedJson = nlohmann::ordered_json;
    OrderedJson line;
    line["file"] = report.file;
    line["kind"] = report.kind == FileKind::effects ? "effects" : "scene";
    line["ok"] = report.errors.empty();
    line["bodies"] = report.counts.bodies;
    line["fixtures"] = report.counts.fixtures;
    line["joints"] = report.counts.joints;
    line["images"] = report.counts.images;
    line["fixtures_with_material"] = report.fixturesWithMaterial;
    auto list = [](const std::vector<Diagnostic>& problems)
    {
        OrderedJson items = OrderedJson::array();
        for (const Diagnostic& problem : problems)
        {
            items.push_back(OrderedJson{{"path", problem.path},
                                        {"message", problem.message},
                                        {"line", problem.line},
                                        {"column", problem.column}});
        }
        return items;
    };
    line["errors"] = list(report.errors);
    line["warnings"] = list(report.warnings);
    std::cout << line.dump(-1, ' ', false, OrderedJson::error_handler_t::replace) << '\n';
}

std::string Count(std::size_t n, const char* one, const char* many)
{
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

void PrintText(const Report& report)
{
    for (const Diagnostic& warning : report.warnings)
    {
        std::cout << warning.ToString() << '\n';
    }
    const std::string warnings =
        report.warnings.empty() ? ""
                                : " (" + Count(CountProblems(report.warnings), "warning", "warnings") + ")";
    if (!report.errors.empty())
    {
        for (const Diagnostic& problem : report.errors)
        {
            std::cout << problem.ToString() << '\n';
        }
        std::cout << report.file << ": " << Count(CountProblems(report.errors), "problem", "problems")
                  << warnings << '\n';
    }
    else if (report.kind == FileKind::effects)
    {
        const EffectsConfig& config = *report.config;
        // JSON's escapes, as messages quote names (Validate refuses control characters in it).
        const std::string name =
            nlohmann::json(config.name).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        std::cout << report.file << ": ok: effects config " << name << ", "
                  << Count(config.materials.size(), "material", "materials") << ", "
                  << Count(config.particleTypes.size(), "particle type", "particle types") << ", "
                  << Count(config.rules.size(), "rule", "rules") << ", "
                  << Count(config.assignments.size(), "assignment", "assignments") << "\n";
    }
    else
    {
        std::cout << report.file << ": ok: scene, " << Count(report.counts.bodies, "body", "bodies") << ", "
                  << Count(report.counts.fixtures, "fixture", "fixtures") << " ("
                  << report.fixturesWithMaterial << " with a material), "
                  << Count(report.counts.joints, "joint", "joints") << ", "
                  << Count(report.counts.images, "image", "images") << warnings << "\n";
    }
}

int Validate(const Options& options)
{
    // The config scenes are checked against; a broken --effects file is itself a failed file.
    std::optional<EffectsConfig> config;
    bool ok = true;
    try
    {
        config = SelectConfig(options.effects);
    }
    catch (const InputError& error)
    {
        Report report(options.effects.effects, FileKind::effects);
        report.errors = error.Diagnostics();
        options.json ? PrintJson(report) : PrintText(report);
        ok = false;
    }
    for (const std::string& file : options.files)
    {
        const Report report = Check(file, options, config ? &*config : nullptr);
        options.json ? PrintJson(report) : PrintText(report);
        ok = ok && report.errors.empty();
    }
    return ok ? kExitOk : kExitError;
}

} // namespace

void RegisterValidateCommand(CLI::App& app, int& result)
{
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "validate", "Check RUBE scenes and effects configs; report every problem (exit 1 on any)");
    command->add_option("files", options->files, "Scene or effects config JSON files")
        ->required()
        ->check(NamesAFile());
    command->add_flag("--json", options->json,
                      "One JSON object per file and line: {file, kind, ok, bodies, fixtures, joints, images, "
                      "fixtures_with_material, errors: [{path, message, line, column}], warnings: [same]}");
    command->add_flag("--strict", options->strict,
                      "Count warnings (unknown keys in scenes, polygon vertices Box2D drops) as errors");
    command->add_option("--as", options->as, "How to read the files: auto, scene or effects")
        ->check(CLI::IsMember({"auto", "scene", "effects"}))
        ->capture_default_str();
    AddEffectsOptions(*command, options->effects,
                      "Effects config whose materials the scenes' `material` properties must name "
                      "(overrides --preset)");
    command->callback([command, options, &result]
                      { result = Guarded(*command, [&] { return Validate(*options); }); });
}

} // namespace cfx::cli
