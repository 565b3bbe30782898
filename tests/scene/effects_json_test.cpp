#include "contactfx/presets.h"
#include "contactfx/scene/effects_json.h"
#include "contactfx/scene/text_file.h"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>

namespace cfx
{

namespace
{

std::vector<std::string> PathsOf(const std::string& json)
{
    try
    {
        LoadEffectsString(json, "fx.json");
    }
    catch (const InputError& error)
    {
        std::vector<std::string> paths;
        for (const Diagnostic& problem : error.Diagnostics())
        {
            EXPECT_EQ(problem.file, "fx.json");
            paths.push_back(problem.path);
        }
        return paths;
    }
    return {};
}

} // namespace

TEST(EffectsJson, ShippedPresetFilesEqualTheBuiltInPresets)
{
    const std::filesystem::path scenes = std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes";
    EXPECT_EQ(LoadEffectsFile(scenes / "default.effects.json"), DefaultPreset());
    EXPECT_EQ(LoadEffectsFile(scenes / "tutorial.effects.json"), TutorialPreset());
    EXPECT_EQ(ReadTextFile(scenes / "default.effects.json"), SaveEffectsString(DefaultPreset()));
    EXPECT_EQ(ReadTextFile(scenes / "tutorial.effects.json"), SaveEffectsString(TutorialPreset()));
}

TEST(EffectsJson, RoundTripIsExact)
{
    EffectsConfig config = DefaultPreset();
    config.particleTypes[1].colorStart = Color{0.1f, 0.2f, 0.3f, 0.4f};
    config.particleTypes[2].backend = ParticleBackend::body;
    config.rules[0].intensity =
        IntensityModel{SpeedMode::full, FrictionMix::mean, ManifoldPoints::first, 0.125f};
    config.rules[1].emission = EmissionMode::perStep;
    config.rules[2].placement = SpawnPlacement::tutorialDrop;
    config.rules[3].threshold = 1.0f / 3.0f;
    EXPECT_EQ(LoadEffectsString(SaveEffectsString(config), "x"), config);
}

TEST(EffectsJson, MissingFieldsTakeTheDefaults)
{
    EffectsConfig config = LoadEffectsString(R"({"materials": ["a", "b"], "particleTypes": [{"name": "p"}],
        "rules": [{"materialA": "a", "materialB": "b", "particleType": "p"}]})",
                                             "x");
    EXPECT_EQ(config.particleTypes[0], ParticleTypeDef{.name = "p"});
    RuleDef expected;
    expected.materialA = "a";
    expected.materialB = "b";
    expected.particleType = "p";
    EXPECT_EQ(config.rules[0], expected);
    EXPECT_EQ(config.budget, ParticleBudget{});
}

TEST(EffectsJson, EveryProblemIsReportedWithItsPath)
{
    EXPECT_EQ(PathsOf(R"({"materials": ["a", 3], "particleTypes": [{"name": "p", "drag": "NaN", "radius": "x",
        "colour": [1, 0, 0], "backend": "gpu", "colorEnd": [1, 2]}], "budget": {"capacity": -4}})"),
              (std::vector<std::string>{"materials[1]", "particleTypes[0].colour", "particleTypes[0].drag",
                                        "particleTypes[0].radius", "particleTypes[0].colorEnd",
                                        "particleTypes[0].backend", "budget.capacity"}));
}

TEST(EffectsJson, SemanticProblemsUseJsonPaths)
{
    EXPECT_EQ(PathsOf(R"({"materials": ["a", "b", "a"], "particleTypes": [{"name": "p", "radius": -1}],
        "rules": [{"materialA": "a", "materialB": "c", "particleType": "q", "threshold": -2,
                   "intensity": {"impulseWeight": -1}},
                  {"materialA": "b", "materialB": "a", "particleType": "p"},
                  {"materialA": "a", "materialB": "b", "particleType": "p"}]})"),
              (std::vector<std::string>{"materials[2]", "particleTypes[0].radius", "rules[0].materialB",
                                        "rules[0].particleType", "rules[0].intensity.impulseWeight",
                                        "rules[0].threshold", "rules[2]"}));
}

TEST(EffectsJson, MalformedJsonHasLineAndColumn)
{
    try
    {
        LoadEffectsString("{\n  \"materials\": [\"a\",\n}", "fx.json");
        FAIL();
    }
    catch (const InputError& error)
    {
        EXPECT_EQ(error.Diagnostics()[0].line, 3);
        EXPECT_GT(error.Diagnostics()[0].column, 0);
    }
}

TEST(EffectsJson, SaveNeverLeavesAHalfWrittenFile)
{
    const std::filesystem::path missing =
        std::filesystem::temp_directory_path() / "contactfx_no_such_dir" / "fx.json";
    EXPECT_THROW(SaveEffectsFile(DefaultPreset(), missing), InputError);
    EXPECT_FALSE(std::filesystem::exists(missing.parent_path()));
}

namespace
{

// A config with materials a and b, then the given assignments array text.
std::string WithAssignments(const std::string& assignments)
{
    return R"({"materials": ["a", "b"], "assignments": [)" + assignments + "]}";
}

} // namespace

TEST(AssignmentJson, RoundTripIsExactAndUnsetBoundsStayUnset)
{
    EffectsConfig config = DefaultPreset();
    MaterialAssignment named;
    named.material = "dirt";
    named.bodyName = "ground_?";
    named.fixtureName = "*mud*";
    named.bodyType = BodyTypeFilter::kinematicBody;
    named.frictionBelow = 1.0f / 3.0f;
    named.massAbove = -2.5f;
    named.massBelow = 1e-7f;
    config.assignments.insert(config.assignments.begin(), named);
    const EffectsConfig back = LoadEffectsString(SaveEffectsString(config), "x");
    EXPECT_EQ(back, config);
    EXPECT_FALSE(back.assignments[0].frictionAbove.has_value());
}

TEST(AssignmentJson, MissingFieldsTakeTheDefaults)
{
    const EffectsConfig config = LoadEffectsString(WithAssignments(R"({"material": "b"})"), "x");
    ASSERT_EQ(config.assignments.size(), 1u);
    MaterialAssignment expected;
    expected.material = "b";
    EXPECT_EQ(config.assignments[0], expected);
    EXPECT_EQ(LoadEffectsString(WithAssignments(R"({"material": "a", "bodyType": "static"})"), "x")
                  .assignments[0]
                  .bodyType,
              BodyTypeFilter::staticBody);
}

TEST(AssignmentJson, ReadingProblemsNameTheirPaths)
{
    EXPECT_EQ(
        PathsOf(WithAssignments(R"({"material": 3, "bodyType": "heavy", "massAbove": "x",
        "frictionAbove": 1e39, "frictionBelow": "7FC00000", "fixture": "wheel"}, 5)")),
        (std::vector<std::string>{"assignments[0].fixture", "assignments[0].material",
                                  "assignments[0].frictionAbove", "assignments[0].frictionBelow",
                                  "assignments[0].massAbove", "assignments[0].bodyType", "assignments[1]"}));
    EXPECT_EQ(PathsOf(R"({"materials": ["a"], "assignments": {"material": "a"}})"),
              (std::vector<std::string>{"assignments"}));
}

TEST(AssignmentJson, SemanticProblemsNameTheirPaths)
{
    EXPECT_EQ(PathsOf(WithAssignments(R"({"material": "glass"}, {"material": "a", "bodyName": "",
        "fixtureName": ""}, {"material": "b", "frictionAbove": 0.5, "frictionBelow": 0.5},
        {"material": "b", "massAbove": 3, "massBelow": 1})")),
              (std::vector<std::string>{"assignments[0].material", "assignments[1].bodyName",
                                        "assignments[1].fixtureName", "assignments[2].frictionBelow",
                                        "assignments[3].massBelow"}));
}

TEST(AssignmentValidate, ApiValuesAreCheckedToo)
{
    EffectsConfig config = TutorialPreset();
    config.assignments[1].frictionAbove = std::nanf("");
    config.assignments[2].bodyType = static_cast<BodyTypeFilter>(9);
    config.assignments[3].material = "";
    std::vector<std::string> paths;
    for (const Diagnostic& problem : Validate(config))
    {
        EXPECT_EQ(problem.file, "<api>");
        paths.push_back(problem.path);
    }
    EXPECT_EQ(paths, (std::vector<std::string>{"assignments[1].frictionAbove", "assignments[2].bodyType",
                                               "assignments[3].material"}));
}

} // namespace cfx
