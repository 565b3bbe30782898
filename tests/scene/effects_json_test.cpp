#include "contactfx/config_fields.h"
#include "contactfx/files/text_file.h"
#include "contactfx/presets.h"
#include "contactfx/scene/effects_json.h"
#include "scene/rube_test_util.h"

#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <limits>
#include <nlohmann/json.hpp>

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

// Every problem as "path: message".
std::vector<std::string> ProblemsOf(const std::string& json)
{
    std::vector<std::string> lines;
    try
    {
        LoadEffectsString(json, "fx.json");
    }
    catch (const InputError& error)
    {
        for (const Diagnostic& problem : error.Diagnostics())
        {
            EXPECT_EQ(problem.file, "fx.json");
            lines.push_back(problem.path + ": " + problem.message);
        }
    }
    return lines;
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

// Reading problems (a misspelt field) and semantic ones (ranges, names) in one pass: the seven independent
// problems of issue 15 are all reported, each with its path.
TEST(EffectsJson, ReadingAndSemanticProblemsAreReportedTogether)
{
    EXPECT_EQ(
        PathsOf(R"({"materials": ["steel", "stone"],
        "particleTypes": [{"name": "sparks", "lifetime": 0, "drag": -1, "radus": 0.1}],
        "rules": [{"materialA": "steel", "materialB": "stone", "particleType": "sparks", "threshold": -1},
                  {"materialA": "steel", "materialB": "steel", "particleType": "smoke"},
                  {"materialA": "stone", "materialB": "glass", "particleType": "sparks"}],
        "budget": {"capacity": 0}})"),
        (std::vector<std::string>{"particleTypes[0].radus", "budget.capacity", "particleTypes[0].lifetime",
                                  "particleTypes[0].drag", "rules[0].threshold", "rules[1].particleType",
                                  "rules[2].materialB"}));
    // A bad element keeps the indices of the ones after it, and what it breaks is reported once.
    EXPECT_EQ(PathsOf(R"({"materials": ["a"], "particleTypes": [3, {"name": "p", "radius": -1}]})"),
              (std::vector<std::string>{"particleTypes[0]", "particleTypes[1].radius"}));
}

// Every number has a range that keeps the simulation finite and its cost bounded (docs/effects-config.md).
TEST(EffectsJson, HugeNumbersAreOutOfRange)
{
    auto problemsOf = [](const std::string& particle, const std::string& rule)
    {
        try
        {
            LoadEffectsString(
                R"({"materials": ["a"], "particleTypes": [{"name": "p")" + particle +
                    R"(}], "rules": [{"materialA": "a", "materialB": "a", "particleType": "p")" + rule +
                    "}]}",
                "fx.json");
        }
        catch (const InputError& error)
        {
            return error.Diagnostics();
        }
        return std::vector<Diagnostic>{};
    };
    auto has = [](const std::vector<Diagnostic>& problems, const std::string& path, const std::string& part)
    {
        for (const Diagnostic& problem : problems)
        {
            if (problem.path == path && problem.message.find(part) != std::string::npos)
            {
                return true;
            }
        }
        return false;
    };
    EXPECT_TRUE(has(problemsOf(R"(, "radius": 3e9)", ""), "particleTypes[0].radius",
                    "expected a number between 0.001 and 10, found 3e+09"));
    const auto extremes = problemsOf(R"(, "gravityScale": 3.4e38, "normalSpeed": -3.4e38, "spread": 3.4e38,
        "inheritA": 3.4e38, "inheritB": -3.4e38, "slipFactor": 3.4e38, "drag": 1e9, "lifetime": 1e9,
        "lifeFromIntensity": 1e9, "friction": 1e9, "density": 1e9, "sizeStart": 1e9, "sizeEnd": 1e9,
        "streak": 1e9)",
                                     R"(, "ratePerIntensity": 1e9, "maxRate": 1e9, "threshold": 1e9,
        "scrapeEndDelay": 1e9, "impactThreshold": 1e9, "burstPerSpeed": 1e9, "burstMax": 1e9,
        "intensity": {"impulseWeight": 1e9})");
    for (const char* field :
         {"gravityScale", "normalSpeed", "spread", "inheritA", "inheritB", "slipFactor", "drag", "lifetime",
          "lifeFromIntensity", "friction", "density", "sizeStart", "sizeEnd", "streak"})
    {
        EXPECT_TRUE(has(extremes, std::string("particleTypes[0].") + field, "expected a number")) << field;
    }
    for (const char* field : {"ratePerIntensity", "maxRate", "threshold", "scrapeEndDelay", "impactThreshold",
                              "burstPerSpeed", "burstMax", "intensity.impulseWeight"})
    {
        EXPECT_TRUE(has(extremes, std::string("rules[0].") + field, "expected a number")) << field;
    }
    EXPECT_TRUE(has(extremes, "rules[0].maxRate", "between 0 and 1e+05, found 1e+09"));
    EXPECT_EQ(extremes.size(), 22U);
    // Generous for real use: the bounds themselves are fine.
    EXPECT_TRUE(problemsOf(R"(, "radius": 10, "gravityScale": -100, "normalSpeed": 1000, "lifetime": 3600)",
                           R"(, "ratePerIntensity": 1e6, "maxRate": 1e5, "burstMax": 1e5)")
                    .empty());
}

// A required name left out is reported as missing, not as an unknown name "", and every one at once: a rule
// without a particle type used to match a particle type without a name and went unreported.
TEST(EffectsJson, MissingRequiredFieldsAreReportedAsMissing)
{
    EXPECT_EQ(ProblemsOf(R"({"materials": ["a", "b"], "particleTypes": [{"lifetime": 2}],
        "rules": [{"materialA": "a"}], "assignments": [{"bodyType": "static"}]})"),
              (std::vector<std::string>{
                  "particleTypes[0].name: expected a non-empty name, but the required field is missing",
                  "rules[0].materialB: expected a material name, but the required field is missing",
                  "rules[0].particleType: expected a particle type name, but the required field is missing",
                  "assignments[0].material: expected a material name, but the required field is missing"}));
    // Given but empty: never a match, even for an entry that has no name (itself an error).
    EXPECT_EQ(ProblemsOf(R"({"materials": ["a"], "particleTypes": [{"name": ""}],
        "rules": [{"materialA": "a", "materialB": "", "particleType": ""}]})"),
              (std::vector<std::string>{"particleTypes[0].name: expected a non-empty name",
                                        "rules[0].materialB: expected a material name, found \"\"",
                                        "rules[0].particleType: expected a particle type name, found \"\""}));
}

// Every required field of every table (IsRequired), left out of an otherwise empty object.
TEST(EffectsJson, EveryRequiredFieldIsReportedWhenMissing)
{
    std::vector<std::string> expected;
    auto required = [&](const std::string& at, auto fields)
    {
        for (const auto& field : fields)
        {
            if (IsRequired(field))
            {
                expected.push_back(at + "." + std::string(field.name) + ": expected " +
                                   std::string(ExpectedText(field.text)) +
                                   ", but the required field is missing");
            }
        }
    };
    required("particleTypes[0]", ParticleTypeFields());
    required("rules[0]", RuleFields());
    required("assignments[0]", AssignmentFields());
    required("sound.rules[0]", SoundRuleFields());
    ASSERT_EQ(expected.size(),
              7u); // a particle type's name, two materials per rule, a particle type, a material
    EXPECT_EQ(ProblemsOf(R"({"materials": ["a"], "particleTypes": [{}], "rules": [{}], "assignments": [{}],
        "sound": {"rules": [{}]}})"),
              expected);
}

// budget.capacity said "an integer between 0 and 1073741824" for some wrong values and "[1, 4000000]" (the
// documented range) for others: every wrong value of an integer field now gets the documented range.
TEST(EffectsJson, IntegerFieldsStateTheirDocumentedRangeForEveryWrongValue)
{
    auto withCapacity = [](const std::string& capacity)
    { return R"({"materials": ["a"], "budget": {"capacity": )" + capacity + "}}"; };
    for (const std::string value : {"-5", "0", "5000000", "2000000000", "18446744073709551615", "1.5"})
    {
        EXPECT_EQ(ProblemsOf(withCapacity(value)),
                  (std::vector<std::string>{"budget.capacity: expected an integer in [1, 4000000], found " +
                                            value}));
    }
    EXPECT_EQ(
        ProblemsOf(withCapacity("1e20")),
        (std::vector<std::string>{"budget.capacity: expected an integer in [1, 4000000], found 1e+20"}));
    EXPECT_EQ(ProblemsOf(withCapacity("\"many\"")),
              (std::vector<std::string>{
                  "budget.capacity: expected an integer in [1, 4000000], found string \"many\""}));
    // The bounds and a whole number written as a float are fine; Validate says the same for API values.
    EXPECT_EQ(LoadEffectsString(withCapacity("4000000"), "x").budget.capacity, 4000000u);
    EXPECT_EQ(LoadEffectsString(withCapacity("1"), "x").budget.capacity, 1u);
    EXPECT_EQ(LoadEffectsString(withCapacity("2.0"), "x").budget.capacity, 2u);
    EffectsConfig config;
    config.budget.capacity = 0;
    ASSERT_EQ(Validate(config).size(), 1u);
    EXPECT_EQ(Validate(config)[0].message, "expected an integer in [1, 4000000], found 0");

    // Every integer field of every table: just outside its range, either side.
    const nlohmann::json preset = nlohmann::json::parse(SaveEffectsString(DefaultPreset()));
    int checked = 0;
    auto outside = [&]<typename S>(std::span<const Field<S>> fields, auto locate)
    {
        for (const Field<S>& field : fields)
        {
            if (!std::holds_alternative<std::uint32_t S::*>(field.member) &&
                !std::holds_alternative<std::uint16_t S::*>(field.member))
            {
                continue;
            }
            for (const long long value :
                 {static_cast<long long>(field.range.min) - 1, static_cast<long long>(field.range.max) + 1})
            {
                nlohmann::json root = preset;
                locate(root)[std::string(field.name)] = value;
                const std::vector<std::string> problems = ProblemsOf(root.dump());
                ASSERT_EQ(problems.size(), 1u) << field.name << " = " << value;
                EXPECT_NE(problems[0].find(": expected " + ExpectedInteger(field.range) + ", found " +
                                           std::to_string(value)),
                          std::string::npos)
                    << problems[0];
                ++checked;
            }
        }
    };
    outside(ParticleTypeFields(),
            [](nlohmann::json& root) -> nlohmann::json& { return root["particleTypes"][0]; });
    outside(BudgetFields(), [](nlohmann::json& root) -> nlohmann::json& { return root["budget"]; });
    outside(SoundFields(), [](nlohmann::json& root) -> nlohmann::json& { return root["sound"]; });
    EXPECT_EQ(checked,
              2 * 7); // categoryBits, maskBits; capacity, contacts, particleHits; maxVoices, trackedPairs
}

// A named value of the wrong JSON type was reported twice ("expected a string" and "expected one of"):
// once, with the names it takes, whatever the value.
TEST(EffectsJson, ANamedValueOfAnyWrongKindIsOneProblem)
{
    const std::string names = "expected one of \"rate\", \"perStep\", found ";
    for (const auto& [value, found] :
         std::vector<std::pair<std::string, std::string>>{{"null", "null"},
                                                          {"5", "number 5"},
                                                          {"[\"rate\"]", "an array"},
                                                          {"\"Rate\"", "string \"Rate\""}})
    {
        const std::string config = R"({"materials": ["a"], "particleTypes": [{"name": "p"}],
            "rules": [{"materialA": "a", "materialB": "a", "particleType": "p", "emission": )" +
                                   value + "}]}";
        EXPECT_EQ(ProblemsOf(config), std::vector<std::string>{"rules[0].emission: " + names + found});
    }
    EXPECT_EQ(
        ProblemsOf(R"({"materials": ["a"], "budget": {"recycle": null}})"),
        (std::vector<std::string>{"budget.recycle: expected one of \"oldest\", \"lowestLife\", found null"}));
}

// A colour's element is named as the file has it, for a value out of range as for one of the wrong kind
// (a user's trial found `colorEnd.g` for the one and `colorStart[1]` for the other).
TEST(EffectsJson, AColourElementIsNamedByItsIndexInTheFile)
{
    EXPECT_EQ(
        ProblemsOf(R"({"materials": ["a"], "particleTypes": [{"name": "p", "colorEnd": [0.5, 2, 0.5, 1]}]})"),
        (std::vector<std::string>{
            "particleTypes[0].colorEnd[1]: expected a number between 0 and 1, found 2"}));
    const std::vector<std::string> wrongKind = ProblemsOf(
        R"({"materials": ["a"], "particleTypes": [{"name": "p", "colorStart": [0.5, "x", 0.5, 1]}]})");
    ASSERT_EQ(wrongKind.size(), 1u);
    EXPECT_EQ(wrongKind[0].rfind("particleTypes[0].colorStart[1]: ", 0), 0u) << wrongKind[0];
}

// A trial's colour with one element of the wrong kind got only that one reported; its elements out of range
// went unsaid until it was mended. Every problem comes at once, both kinds in the file's order of elements.
TEST(EffectsJson, AColoursRangeProblemsComeWithItsWrongKindOfElement)
{
    const std::vector<std::string> problems = ProblemsOf(
        R"({"materials": ["a"], "particleTypes": [{"name": "p", "colorStart": [1.01, -0.01, "1", 2]}]})");
    ASSERT_EQ(problems.size(), 4u);
    EXPECT_EQ(problems[0].rfind("particleTypes[0].colorStart[2]: expected a number", 0), 0u) << problems[0];
    EXPECT_EQ(problems[1], "particleTypes[0].colorStart[0]: expected a number between 0 and 1, found 1.01");
    EXPECT_EQ(problems[2], "particleTypes[0].colorStart[1]: expected a number between 0 and 1, found -0.01");
    EXPECT_EQ(problems[3], "particleTypes[0].colorStart[3]: expected a number between 0 and 1, found 2");
}

// A trial's names with a line break forged lines of validate's output, and a NUL cut the run summary's
// (a later trial did it with the config's own name). Names may not hold control characters, and a name a
// message quotes is escaped.
TEST(EffectsJson, NamesWithControlCharactersAreRefusedAndQuotedEscaped)
{
    const std::vector<std::string> problems = ProblemsOf(
        R"({"name": "x\ny.effects.json: ok", "materials": ["a\nb: ok", "st\u0000eel", "gl\u0085ass", "gl\u009bass", "gl\u00a0ass", "li\u2028ne"], "particleTypes": [{"name": "p\tq"}],
            "rules": [{"materialA": "a\nb: ok", "materialB": "zz\nfake.json: ok", "particleType": "p\tq"}]})");
    const std::vector<std::string> expected = {
        "name: expected a name without control characters, found \"x\\ny.effects.json: ok\"",
        "materials[0]: expected a name without control characters, found \"a\\nb: ok\"",
        "materials[1]: expected a name without control characters, found \"st\\u0000eel\"",
        "materials[2]: expected a name without control characters, found \"gl\\u0085ass\"",
        "materials[3]: expected a name without control characters, found \"gl\\u009bass\"",
        "materials[5]: expected a name without control characters, found \"li\\u2028ne\"",
        "particleTypes[0].name: expected a name without control characters, found \"p\\tq\"",
        "rules[0].materialB: unknown material \"zz\\nfake.json: ok\" (materials: a\\nb: ok, st\\u0000eel, "
        "gl\\u0085ass, gl\\u009bass, gl\xC2\xA0"
        "ass, li\\u2028ne)"};
    EXPECT_EQ(problems, expected);
}

// A sound rule tunes the voices of the pair rule with its two materials (docs/sound.md): one for a pair that
// no rule makes particles for would never apply.
TEST(EffectsJson, ASoundRuleForAPairWithoutARuleIsAnError)
{
    const std::string config = R"({"materials": ["steel", "stone"], "particleTypes": [{"name": "sparks"}],
        "rules": [{"materialA": "steel", "materialB": "stone", "particleType": "sparks"}], "sound": {"rules": [
            {"materialA": "stone", "materialB": "steel"}, {"materialA": "steel", "materialB": "steel"},
            {"materialA": "steel", "materialB": "glass"}]}})";
    EXPECT_EQ(
        ProblemsOf(config),
        (std::vector<std::string>{"sound.rules[1]: no rule for the pair steel+steel in \"rules\": this "
                                  "sound rule would never apply",
                                  "sound.rules[2].materialB: unknown material \"glass\" (materials: steel, "
                                  "stone)"}));
}

// nlohmann keeps the last of a repeated key: the first would silently do nothing.
TEST(EffectsJson, DuplicateKeysAreErrorsWithTheirPath)
{
    EXPECT_EQ(
        ProblemsOf(R"({"name": "x", "name": "y", "materials": ["a"],
        "particleTypes": [{"name": "p"}, {"name": "q", "radius": 0.1, "radius": 0.2}]})"),
        (std::vector<std::string>{
            "name: duplicate key \"name\": each key may appear once in an object",
            "particleTypes[1].radius: duplicate key \"radius\": each key may appear once in an object"}));
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

// JSON holds no NaN or infinity: an invalid config is refused, naming its fields, and nothing is written.
TEST(EffectsJson, AnInvalidConfigIsNotSaved)
{
    EffectsConfig config = DefaultPreset();
    config.particleTypes[0].radius = std::numeric_limits<float>::quiet_NaN();
    config.rules[0].threshold = std::numeric_limits<float>::infinity();
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "contactfx_invalid_save.json";
    std::filesystem::remove(file);
    try
    {
        SaveEffectsFile(config, file);
        ADD_FAILURE() << "saved";
    }
    catch (const InputError& error)
    {
        EXPECT_TRUE(test::HasDiagnostic(error.Diagnostics(), "particleTypes[0].radius", "found NaN"))
            << test::Dump(error.Diagnostics());
        EXPECT_TRUE(test::HasDiagnostic(error.Diagnostics(), "rules[0].threshold", "found inf"))
            << test::Dump(error.Diagnostics());
    }
    EXPECT_FALSE(std::filesystem::exists(file));
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

// An empty particle type name in code is not a match for a particle type without a name.
TEST(ConfigValidate, EmptyNamesMatchNothing)
{
    EffectsConfig config;
    config.materials = {"a"};
    config.particleTypes.push_back(ParticleTypeDef{});
    RuleDef rule;
    rule.materialA = "a";
    rule.materialB = "a";
    config.rules.push_back(rule);
    std::vector<std::string> paths;
    for (const Diagnostic& problem : Validate(config))
    {
        paths.push_back(problem.path);
    }
    EXPECT_EQ(paths, (std::vector<std::string>{"particleTypes[0].name", "rules[0].particleType"}));
}

} // namespace cfx
