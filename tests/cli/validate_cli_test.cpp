// contactfx validate: every problem of every file, with file, JSON path, expected and found (line and
// column for malformed JSON), exit code 1 on any error, one JSON object per file with --json, and no
// file ever modified.
#include "cli/cli_support.h"

#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace cfx::test
{

namespace
{

// `--json` output: one object per line, keyed by file name.
std::map<std::string, nlohmann::json> JsonLines(const std::string& output)
{
    std::map<std::string, nlohmann::json> byFile;
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
    {
        nlohmann::json object = nlohmann::json::parse(line);
        byFile[object["file"].get<std::string>()] = object;
    }
    return byFile;
}

bool HasError(const nlohmann::json& report, const std::string& path, const std::string& messagePart)
{
    for (const nlohmann::json& error : report["errors"])
    {
        if (error["path"] == path &&
            error["message"].get<std::string>().find(messagePart) != std::string::npos)
        {
            return true;
        }
    }
    return false;
}

std::string Fixture(const std::string& fixture, const std::string& bodyMore = "")
{
    return R"({"gravity": {"x": 0, "y": -10}, "body": [{"type": 2, "fixture": [)" + fixture + "]" + bodyMore +
           "}]}";
}

std::string Polygon(const std::string& xs, const std::string& ys)
{
    return Fixture(R"({"density": 1, "polygon": {"vertices": {"x": [)" + xs + R"(], "y": [)" + ys + "]}}}");
}

const std::string kCircle = R"({"density": 1, "circle": {"radius": 0.5}})";

std::string TwoBodiesAndJoint(const std::string& joint)
{
    return R"({"body": [{"type": 2, "fixture": [)" + kCircle + R"(]}, {"type": 2, "fixture": [)" + kCircle +
           R"(]}], "joint": [)" + joint + "]}";
}

std::string Effects(const std::string& rules, const std::string& more = "")
{
    return R"({"materials": ["steel", "stone"], "particleTypes": [{"name": "sparks"}], "rules": [)" + rules +
           "]" + more + "}";
}

struct BadFile
{
    const char* name;
    std::string text;
    const char* path;    ///< expected JSON path ("" for malformed JSON: then line and column are expected)
    const char* message; ///< part of the expected message
};

// The issue's list of bad input, one file each.
std::vector<BadFile> BadFiles()
{
    const std::string tutorial = FileText(Scene("physics_driven_particles.json"));
    std::string glass = tutorial;
    glass.replace(glass.find("\"string\": \"steel\""), 17, "\"string\": \"glass\"");
    const std::string preset = FileText(Scene("default.effects.json"));
    return {
        {"truncated.json", tutorial.substr(0, tutorial.size() / 2), "", "malformed JSON"},
        {"truncated.effects.json", preset.substr(0, preset.size() / 3), "", "malformed JSON"},
        {"wrong_type.json", Fixture(R"({"friction": "abc", "circle": {"radius": 1}})"),
         "body[0].fixture[0].friction", "expected a number, found string \"abc\""},
        {"nan.json", Fixture(kCircle, R"(, "angle": "7FC00000")"), "body[0].angle", "finite"},
        {"infinity.json", Fixture(kCircle, R"(, "linearVelocity": {"x": "7F800000", "y": 0})"),
         "body[0].linearVelocity.x", "finite"},
        {"too_big.json", Fixture(kCircle, R"(, "position": {"x": 1e39, "y": 0})"), "body[0].position.x",
         "float range"},
        {"out_of_range.json", Fixture(kCircle, R"(, "position": {"x": 1e30, "y": 0})"), "body[0].position.x",
         "between"},
        {"negative_density.json", Fixture(R"({"density": -1, "circle": {"radius": 1}})"),
         "body[0].fixture[0].density", "between 0 and 1e+06"},
        {"negative_radius.json", Fixture(R"({"density": 1, "circle": {"radius": -1}})"),
         "body[0].fixture[0].circle.radius", "> 0"},
        {"one_vertex.json", Polygon("0", "0"), "body[0].fixture[0].polygon.vertices", "found 1"},
        {"nine_vertices.json",
         Polygon("1, 0.77, 0, -0.77, -1, -0.77, 0, 0.77, 0.9", "0, 0.77, 1, 0.77, 0, -0.77, -1, -0.77, -0.3"),
         "body[0].fixture[0].polygon.vertices", "found 9"},
        {"degenerate.json", Polygon("0, 1, 2", "0, 0, 0"), "body[0].fixture[0].polygon.vertices",
         "collinear"},
        {"welded.json", Polygon("0, 1, 1.001", "0, 0, 0.001"), "body[0].fixture[0].polygon.vertices",
         "only 2 vertices are left after welding"},
        {"huge_restitution.json", Fixture(R"({"restitution": 1e30, "circle": {"radius": 1}})"),
         "body[0].fixture[0].restitution", "expected a number between 0 and 10, found 1e+30"},
        {"huge_radius.effects.json",
         R"({"materials": ["steel"], "particleTypes": [{"name": "sparks", "radius": 3e9}]})",
         "particleTypes[0].radius", "expected a number between 0.001 and 10, found 3e+09"},
        {"huge_rate.effects.json",
         Effects(R"({"materialA": "steel", "materialB": "stone", "particleType": "sparks",
                     "ratePerIntensity": 1e9, "maxRate": 1e9})"),
         "rules[0].maxRate", "expected a number between 0 and 1e+05, found 1e+09"},
        {"joint_body.json", TwoBodiesAndJoint(R"({"type": "revolute", "bodyA": 0, "bodyB": 7})"),
         "joint[0].bodyB", "between 0 and 1"},
        {"glass.json", glass, "body[3].fixture[0].customProperties[0].string", "unknown material \"glass\""},
        {"unknown_material.effects.json",
         Effects(R"({"materialA": "steel", "materialB": "wood", "particleType": "sparks"})"),
         "rules[0].materialB", "unknown material \"wood\" (materials: steel, stone)"},
        {"unknown_type.effects.json",
         Effects(R"({"materialA": "steel", "materialB": "stone", "particleType": "smoke"})"),
         "rules[0].particleType", "unknown particle type \"smoke\" (particle types: sparks)"},
        {"unknown_burst_type.effects.json",
         Effects(R"({"materialA": "steel", "materialB": "stone", "particleType": "sparks",
                     "burstParticleType": "splinters"})"),
         "rules[0].burstParticleType", "unknown particle type \"splinters\" (particle types: sparks)"},
        {"same_pair.effects.json",
         Effects(R"({"materialA": "steel", "materialB": "stone", "particleType": "sparks"},
                    {"materialA": "stone", "materialB": "steel", "particleType": "sparks"})"),
         "rules[1]", "a second rule for the pair steel+stone (the first is rules[0])"},
        {"same_pair_name.effects.json",
         R"({"materials": ["a+b", "c", "a", "b+c"], "particleTypes": [{"name": "p"}], "rules": [
             {"materialA": "a+b", "materialB": "c", "particleType": "p"},
             {"materialA": "a", "materialB": "b+c", "particleType": "p"}]})",
         "rules[1]", "the pair name \"a+b+c\" is also rules[0]'s"},
        {"line_break_in_a_key.effects.json",
         Effects(
             R"({"materialA": "steel", "materialB": "stone", "particleType": "sparks", "lifetime\n": 2})"),
         "rules[0].lifetime\\n", "unknown field"},
        {"misspelt_material.effects.json",
         Effects(R"({"materialA": "steel", "materialB": "stnoe", "particleType": "sparks"})"),
         "rules[0].materialB",
         "unknown material \"stnoe\", did you mean \"stone\"? (materials: steel, stone)"},
        {"misspelt_type.effects.json",
         Effects(R"({"materialA": "steel", "materialB": "stone", "particleType": "Sparks"})"),
         "rules[0].particleType", "unknown particle type \"Sparks\", did you mean \"sparks\"?"},
        {"type_field_in_rule.effects.json",
         Effects(R"({"materialA": "steel", "materialB": "stone", "particleType": "sparks", "lifetime": 2})"),
         "rules[0].lifetime", "unknown field here (a field of particleTypes[])"},
        {"intensity_field_in_rule.effects.json",
         Effects(
             R"({"materialA": "steel", "materialB": "stone", "particleType": "sparks", "speed": "full"})"),
         "rules[0].speed", "unknown field here (a field of rules[].intensity)"},
        {"near_key_first.effects.json",
         Effects(R"({"material": "steel", "materialB": "stone", "particleType": "sparks"})"),
         "rules[0].material", "unknown field, did you mean `materialA`?"},
        {"rule_field_in_type.effects.json",
         R"({"materials": ["steel"], "particleTypes": [{"name": "sparks", "materialA": "steel"}]})",
         "particleTypes[0].materialA", "unknown field here (a field of rules[] and of sound.rules[])"},
        {"nan.effects.json",
         Effects(
             R"({"materialA": "steel", "materialB": "stone", "particleType": "sparks", "threshold": "7FC00000"})"),
         "rules[0].threshold", "finite"},
        {"negative.effects.json", Effects("", R"(, "budget": {"capacity": 0})"), "budget.capacity",
         "expected an integer in [1, 4000000], found 0"},
        {"assignment.effects.json", Effects("", R"(, "assignments": [{"material": "glass"}])"),
         "assignments[0].material", "unknown material \"glass\""},
    };
}

/// Validates `files` in one run, as text and as JSON: every one is ok and of the right kind.
void ExpectAllValid(const std::vector<std::string>& files)
{
    std::string args = "validate";
    for (const std::string& file : files)
    {
        args += " " + file;
    }
    const CliResult text = RunCli(args);
    EXPECT_EQ(text.exitCode, 0) << text.output;
    for (const std::string& file : files)
    {
        EXPECT_NE(text.output.find(file + ": ok: "), std::string::npos) << file << "\n" << text.output;
    }

    const CliResult json = RunCli("validate --json " + args.substr(9));
    ASSERT_EQ(json.exitCode, 0) << json.output;
    const std::map<std::string, nlohmann::json> reports = JsonLines(json.output);
    EXPECT_EQ(reports.size(), files.size());
    for (const std::string& file : files)
    {
        ASSERT_TRUE(reports.contains(file)) << file;
        const nlohmann::json& report = reports.at(file);
        EXPECT_EQ(report["ok"], true);
        EXPECT_TRUE(report["errors"].empty());
        const bool effects = file.ends_with(".effects.json");
        EXPECT_EQ(report["kind"], effects ? "effects" : "scene") << file;
        if (effects)
        {
            continue;
        }
        // Counts as the file itself has them.
        const nlohmann::json scene = nlohmann::json::parse(FileText(file));
        std::size_t fixtures = 0;
        for (const nlohmann::json& body : scene.value("body", nlohmann::json::array()))
        {
            fixtures += body.value("fixture", nlohmann::json::array()).size();
        }
        EXPECT_EQ(report["bodies"], scene.value("body", nlohmann::json::array()).size()) << file;
        EXPECT_EQ(report["fixtures"], fixtures) << file;
        EXPECT_EQ(report["joints"], scene.value("joint", nlohmann::json::array()).size()) << file;
        EXPECT_EQ(report["images"], scene.value("image", nlohmann::json::array()).size()) << file;
    }
}

std::vector<std::string> JsonFilesIn(const std::filesystem::path& folder)
{
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
    {
        if (entry.path().extension() == ".json")
        {
            files.push_back(entry.path().string());
        }
    }
    return files;
}

} // namespace

TEST(CliValidate, ShippedFilesAreValid)
{
    ExpectAllValid(JsonFilesIn(std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes"));
}

TEST(CliValidate, RealRubeSamplesAreValid)
{
    CONTACTFX_REQUIRE_RUBE_SAMPLES();
    ExpectAllValid(JsonFilesIn(test::RubeSamplesDir()));
}

TEST(CliValidate, EveryProblemOfEveryFileIsReportedAndNoFileIsTouched)
{
    const std::filesystem::path dir = ScratchDir("validate_bad");
    const std::vector<BadFile> bad = BadFiles();
    std::string args;
    std::map<std::string, std::filesystem::file_time_type> times;
    for (const BadFile& file : bad)
    {
        WriteTestFile(dir / file.name, file.text);
        times[file.name] = std::filesystem::last_write_time(dir / file.name);
        args += " " + (dir / file.name).string();
    }
    const std::string good = Scene("physics_driven_particles.json");

    const CliResult json = RunCli("validate --json" + args + " " + good);
    EXPECT_EQ(json.exitCode, 1) << json.output;
    const std::map<std::string, nlohmann::json> reports = JsonLines(json.output);
    EXPECT_EQ(reports.at(good)["ok"], true);
    for (const BadFile& file : bad)
    {
        SCOPED_TRACE(file.name);
        const nlohmann::json& report = reports.at((dir / file.name).string());
        EXPECT_EQ(report["ok"], false);
        if (std::string(file.path).empty())
        {
            ASSERT_EQ(report["errors"].size(), 1u) << report;
            EXPECT_GT(report["errors"][0]["line"], 0);
            EXPECT_GT(report["errors"][0]["column"], 0);
            EXPECT_NE(report["errors"][0]["message"].get<std::string>().find(file.message),
                      std::string::npos);
        }
        else
        {
            EXPECT_TRUE(HasError(report, file.path, file.message)) << report.dump(2);
        }
        EXPECT_EQ(FileText(dir / file.name), file.text) << "modified";
        EXPECT_EQ(std::filesystem::last_write_time(dir / file.name), times[file.name]) << "touched";
    }
    EXPECT_EQ(static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir),
                                                     std::filesystem::directory_iterator())),
              bad.size())
        << "validate wrote a file";

    // Text mode: the same problems as `file: path: message` or `file:line:column: message`.
    const CliResult text = RunCli("validate" + args);
    EXPECT_EQ(text.exitCode, 1);
    for (const BadFile& file : bad)
    {
        const std::string where = (dir / file.name).string() + (std::string(file.path).empty() ? ":" : ": ");
        EXPECT_NE(text.output.find(where + file.path), std::string::npos) << where << "\n" << text.output;
        EXPECT_NE(text.output.find(file.message), std::string::npos) << file.message;
    }
    EXPECT_EQ(text.output.find("terminate"), std::string::npos);
}

TEST(CliValidate, SeveralProblemsInOneFileAreAllListed)
{
    const std::filesystem::path dir = ScratchDir("validate_several");
    WriteTestFile(
        dir / "several.json",
        R"({"body": [{"type": 5, "angle": "7FC00000", "fixture": [{"friction": "abc", "circle": {"radius": -1}},
                  {"density": -1, "polygon": {"vertices": {"x": [0], "y": [0]}}}]}],
                  "joint": [{"type": "weld", "bodyA": 0, "bodyB": 9}]})");
    const CliResult result = RunCli("validate --json " + (dir / "several.json").string());
    EXPECT_EQ(result.exitCode, 1);
    const nlohmann::json report = JsonLines(result.output).begin()->second;
    for (const char* path :
         {"body[0].type", "body[0].angle", "body[0].fixture[0].friction", "body[0].fixture[0].circle.radius",
          "body[0].fixture[1].density", "body[0].fixture[1].polygon.vertices", "joint[0].bodyB"})
    {
        EXPECT_TRUE(HasError(report, path, "")) << path << "\n" << report.dump(2);
    }
}

TEST(CliValidate, AFileWithMoreProblemsThanAreListedGivesTheirTotal)
{
    // 1,500 bodies of a bad type: the first 999 problems are listed, a last line counts the other 501, and
    // the summary gives all 1,500.
    const std::filesystem::path dir = ScratchDir("validate_too_many");
    std::string bodies;
    for (int i = 0; i < 1500; ++i)
    {
        bodies += std::string(i == 0 ? "" : ",") + R"({"type": 5})";
    }
    WriteTestFile(dir / "many.json", R"({"body": [)" + bodies + "]}");
    const std::string file = (dir / "many.json").string();
    const CliResult result = RunCli("validate " + file);
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find(file + ": too many problems: 501 more not listed (1500 in all)\n"),
              std::string::npos)
        << result.output.substr(result.output.size() - 300);
    EXPECT_NE(result.output.find(file + ": 1500 problems\n"), std::string::npos)
        << result.output.substr(result.output.size() - 300);
}

TEST(CliValidate, ScenesAreCheckedAgainstTheSelectedEffectsConfig)
{
    const std::filesystem::path dir = ScratchDir("validate_effects");
    std::string scene = FileText(Scene("physics_driven_particles.json"));
    scene.replace(scene.find("\"string\": \"steel\""), 17, "\"string\": \"glass\"");
    WriteTestFile(dir / "glass.json", scene);
    const std::string glass = (dir / "glass.json").string();
    EXPECT_EQ(RunCli("validate " + glass).exitCode, 1) << "the default preset has no glass";
    EXPECT_EQ(RunCli("validate --preset tutorial " + glass).exitCode, 1);

    nlohmann::json config = nlohmann::json::parse(FileText(Scene("default.effects.json")));
    config["materials"].push_back("glass");
    WriteTestFile(dir / "glass.effects.json", config.dump(2));
    const CliResult ok = RunCli("validate --effects " + (dir / "glass.effects.json").string() + " " + glass);
    EXPECT_EQ(ok.exitCode, 0) << ok.output;

    // A broken --effects file is itself reported, and still every scene is checked.
    WriteTestFile(dir / "broken.effects.json", R"({"materials": ["a"], "budget": {"capacity": "lots"}})");
    const CliResult broken =
        RunCli("validate --json --effects " + (dir / "broken.effects.json").string() + " " + glass);
    EXPECT_EQ(broken.exitCode, 1);
    const std::map<std::string, nlohmann::json> reports = JsonLines(broken.output);
    EXPECT_TRUE(HasError(reports.at((dir / "broken.effects.json").string()), "budget.capacity", "expected"));
    // The scene's structure is checked, but not its materials: not "ok", and it says why.
    EXPECT_EQ(reports.at(glass)["ok"], false) << broken.output;
    EXPECT_TRUE(HasError(reports.at(glass), "", "materials not checked")) << broken.output;
}

// The text report of a scene checked without its effects config: not "ok" with "0 with a material".
TEST(CliValidate, AFailedEffectsConfigLeavesTheSceneNotChecked)
{
    const std::filesystem::path dir = ScratchDir("validate_effects_failed");
    nlohmann::json config = nlohmann::json::parse(FileText(Scene("default.effects.json")));
    config["particleTypes"][0]["gravityScale"] = "nan";
    WriteTestFile(dir / "bad.effects.json", config.dump());
    const std::string grinder = Scene("grinder.json");
    const CliResult result =
        RunCli("validate --effects " + (dir / "bad.effects.json").string() + " " + grinder);
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_EQ(result.output.find(grinder + ": ok"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(grinder + ": materials not checked: the effects config \"" +
                                 (dir / "bad.effects.json").string() + "\" (--effects) has problems"),
              std::string::npos)
        << result.output;
    // The same scene with a good config is ok.
    EXPECT_EQ(RunCli("validate " + grinder).exitCode, 0);
}

// Issue 15: a config with seven independent problems reports all seven, each with its path.
TEST(CliValidate, EveryProblemOfAnEffectsConfigInOnePass)
{
    const std::filesystem::path dir = ScratchDir("validate_one_pass");
    nlohmann::json config = nlohmann::json::parse(FileText(Scene("default.effects.json")));
    config["particleTypes"][0]["lifetime"] = 0;
    config["particleTypes"][0]["drag"] = -1;
    config["particleTypes"][1]["lifetme"] = 2;
    config["rules"][0]["threshold"] = -1;
    config["rules"][1]["particleType"] = "glitter";
    config["rules"][2]["materialB"] = "glass";
    config["budget"]["capacity"] = 0;
    WriteTestFile(dir / "seven.effects.json", config.dump(1));
    const CliResult result = RunCli("validate --json " + (dir / "seven.effects.json").string());
    EXPECT_EQ(result.exitCode, 1);
    const nlohmann::json report = JsonLines(result.output).begin()->second;
    EXPECT_EQ(report["errors"].size(), 7U) << report.dump(2);
    EXPECT_TRUE(HasError(report, "particleTypes[0].lifetime", "> 0"));
    EXPECT_TRUE(HasError(report, "particleTypes[0].drag", "found -1"));
    EXPECT_TRUE(HasError(report, "particleTypes[1].lifetme", "unknown field, did you mean `lifetime`?"));
    EXPECT_TRUE(HasError(report, "rules[0].threshold", "found -1"));
    EXPECT_TRUE(HasError(report, "rules[1].particleType", "unknown particle type \"glitter\""));
    EXPECT_TRUE(HasError(report, "rules[2].materialB", "unknown material \"glass\""));
    EXPECT_TRUE(HasError(report, "budget.capacity", "found 0"));
}

// Unknown keys in scenes and polygon vertices Box2D drops are warnings: listed, exit 0; --strict fails.
TEST(CliValidate, WarningsAreListedAndStrictMakesThemErrors)
{
    const std::filesystem::path dir = ScratchDir("validate_warnings");
    nlohmann::json scene = nlohmann::json::parse(FileText(Scene("grinder.json")));
    scene["gravty"] = scene["gravity"];
    scene.erase("gravity");
    const std::string file = (dir / "gravty.json").string();
    WriteTestFile(file, scene.dump());

    const CliResult text = RunCli("validate " + file);
    EXPECT_EQ(text.exitCode, 0) << text.output;
    EXPECT_NE(text.output.find(file + ": gravty: warning: unknown key, did you mean `gravity`?"),
              std::string::npos)
        << text.output;
    EXPECT_NE(text.output.find(file + ": ok: scene"), std::string::npos);
    EXPECT_NE(text.output.find("(1 warning)"), std::string::npos);

    const CliResult json = RunCli("validate --json " + file);
    EXPECT_EQ(json.exitCode, 0);
    const nlohmann::json report = JsonLines(json.output).at(file);
    EXPECT_EQ(report["ok"], true);
    ASSERT_EQ(report["warnings"].size(), 1U) << report.dump(2);
    EXPECT_EQ(report["warnings"][0]["path"], "gravty");
    EXPECT_EQ(report["warnings"][0]["message"], "unknown key, did you mean `gravity`?");

    const CliResult strict = RunCli("validate --strict --json " + file);
    EXPECT_EQ(strict.exitCode, 1);
    const nlohmann::json strictReport = JsonLines(strict.output).at(file);
    EXPECT_EQ(strictReport["ok"], false);
    EXPECT_TRUE(HasError(strictReport, "gravty", "did you mean `gravity`?")) << strictReport.dump(2);
    EXPECT_TRUE(strictReport["warnings"].empty());

    const std::string arrow = (dir / "arrow.json").string();
    WriteTestFile(arrow, Polygon("0, 2, 0, 0.5", "0, 1, 2, 1"));
    const CliResult repaired = RunCli("validate " + arrow);
    EXPECT_EQ(repaired.exitCode, 0) << repaired.output;
    EXPECT_NE(repaired.output.find("body[0].fixture[0].polygon.vertices: warning: vertex 3 is not a corner"),
              std::string::npos)
        << repaired.output;
    EXPECT_EQ(RunCli("validate --strict " + arrow).exitCode, 1);
    EXPECT_EQ(RunCli("validate --strict " + Scene("grinder.json")).exitCode, 0);

    // `run` and `render` go on, but say what they ignored.
    for (const std::string& command : {std::string("run "), "render --out " + (dir / "f.png").string() + " "})
    {
        const CliResult ran = RunCli(command + file + " --seconds 0.1");
        EXPECT_EQ(ran.exitCode, 0) << ran.output;
        EXPECT_NE(
            ran.output.find("contactfx: " + file + ": gravty: warning: unknown key, did you mean `gravity`?"),
            std::string::npos)
            << command << ran.output;
    }
}

// An effects config where a scene belongs, and the reverse, fail with a message that says so.
TEST(CliValidate, AnEffectsConfigIsNotASceneAndTheReverse)
{
    const CliResult asScene = RunCli("run " + Scene("default.effects.json") + " --seconds 0.1");
    EXPECT_NE(asScene.exitCode, 0);
    EXPECT_NE(asScene.output.find("expected a RUBE scene, found an effects config"), std::string::npos)
        << asScene.output;
    const CliResult asEffects =
        RunCli("run --scene grinder --seconds 0.1 --effects " + Scene("grinder.json"));
    EXPECT_NE(asEffects.exitCode, 0);
    EXPECT_NE(asEffects.output.find("expected an effects config, found a RUBE scene"), std::string::npos)
        << asEffects.output;
    const CliResult validated = RunCli("validate --as scene " + Scene("default.effects.json"));
    EXPECT_EQ(validated.exitCode, 1);
    EXPECT_NE(validated.output.find("default.effects.json: expected a RUBE scene, found an effects config"),
              std::string::npos)
        << validated.output;
}

// Numbers out of their documented ranges are refused by run as by validate.
TEST(CliValidate, RunRefusesNumbersOutOfRange)
{
    const std::filesystem::path dir = ScratchDir("validate_ranges");
    nlohmann::json scene = nlohmann::json::parse(FileText(Scene("grinder.json")));
    scene["body"][0]["fixture"][0]["restitution"] = 1e30;
    WriteTestFile(dir / "bouncy.json", scene.dump());
    const CliResult bouncy = RunCli("run " + (dir / "bouncy.json").string() + " --seconds 0.1");
    EXPECT_NE(bouncy.exitCode, 0);
    EXPECT_NE(bouncy.output.find("body[0].fixture[0].restitution: expected a number between 0 and 10"),
              std::string::npos)
        << bouncy.output;

    nlohmann::json config = nlohmann::json::parse(FileText(Scene("default.effects.json")));
    config["particleTypes"][0]["gravityScale"] = 3.4e38;
    config["rules"][0]["ratePerIntensity"] = 1e9;
    WriteTestFile(dir / "huge.effects.json", config.dump());
    const CliResult huge =
        RunCli("run --scene grinder --seconds 0.1 --effects " + (dir / "huge.effects.json").string());
    EXPECT_NE(huge.exitCode, 0);
    EXPECT_NE(huge.output.find("particleTypes[0].gravityScale: expected a number between -100 and 100"),
              std::string::npos)
        << huge.output;
    EXPECT_NE(huge.output.find("rules[0].ratePerIntensity"), std::string::npos) << huge.output;
}

TEST(CliValidate, KindComesFromAsNameOrContent)
{
    const std::filesystem::path dir = ScratchDir("validate_kind");
    WriteTestFile(dir / "fx.json", FileText(Scene("tutorial.effects.json")));
    const CliResult byContent = RunCli("validate --json " + (dir / "fx.json").string());
    EXPECT_EQ(byContent.exitCode, 0) << byContent.output;
    EXPECT_EQ(JsonLines(byContent.output).begin()->second["kind"], "effects");

    const CliResult forced = RunCli("validate --json --as scene " + (dir / "fx.json").string());
    EXPECT_EQ(JsonLines(forced.output).begin()->second["kind"], "scene");
    const CliResult asEffects = RunCli("validate --as effects " + Scene("physics_driven_particles.json"));
    EXPECT_EQ(asEffects.exitCode, 1);
    EXPECT_NE(asEffects.output.find("expected an effects config, found a RUBE scene"), std::string::npos)
        << asEffects.output;
}

TEST(CliValidate, MissingFilesAndBadFlagsFail)
{
    const std::filesystem::path dir = ScratchDir("validate_missing");
    const CliResult missing = RunCli("validate " + (dir / "nope.json").string());
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.output.find((dir / "nope.json").string()), std::string::npos);
    EXPECT_EQ(RunCli("validate").exitCode, 1);
    EXPECT_EQ(RunCli("validate --as picture " + Scene("physics_driven_particles.json")).exitCode, 1);
}

} // namespace cfx::test
