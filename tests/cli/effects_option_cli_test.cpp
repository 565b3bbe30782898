// Every simulating command takes any scene plus --effects, and plain RUBE scenes (no `material`
// property anywhere) get materials from the config's assignment rules.
#include "cli/cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cfx::test
{

namespace
{

// A plain RUBE scene: a long static floor (friction 0.8) and a 2 x 1 m steel-heavy block (density 2, so
// 4 kg) sliding along it at 12 m/s. No custom properties at all.
std::string SlidingBlock()
{
    return R"({"gravity": {"x": 0, "y": -10}, "body": [
        {"name": "floor", "type": 0, "fixture": [{"friction": 0.8, "density": 1,
            "polygon": {"vertices": {"x": [60, 60, -60, -60], "y": [-0.5, 0.5, 0.5, -0.5]}}}]},
        {"name": "block", "type": 2, "awake": true, "position": {"x": -40, "y": 1.0},
            "linearVelocity": {"x": 12, "y": 0}, "fixture": [{"friction": 0.5, "density": 2,
            "polygon": {"vertices": {"x": [1, 1, -1, -1], "y": [-0.5, 0.5, 0.5, -0.5]}}}]}]})";
}

} // namespace

TEST(CliEffects, DemoTakesEffectsLikeItsPreset)
{
    const std::filesystem::path dir = ScratchDir("demo_effects");
    const CliResult preset =
        RunCli("demo --seconds 3 --preset tutorial --stats " + (dir / "a.json").string());
    ASSERT_EQ(preset.exitCode, 0) << preset.output;
    const CliResult file = RunCli("demo --seconds 3 --effects " + Scene("tutorial.effects.json") +
                                  " --stats " + (dir / "b.json").string());
    ASSERT_EQ(file.exitCode, 0) << file.output;
    EXPECT_EQ(FileText(dir / "a.json"), FileText(dir / "b.json"));
    const CliResult other = RunCli("demo --seconds 3 --stats " + (dir / "c.json").string());
    ASSERT_EQ(other.exitCode, 0) << other.output;
    EXPECT_NE(FileText(dir / "a.json"), FileText(dir / "c.json")) << "--preset must make a difference";
}

TEST(CliEffects, DemoRefusesAConfigWithoutTheScenesMaterials)
{
    const std::filesystem::path dir = ScratchDir("demo_effects_bad");
    WriteTestFile(dir / "wood.effects.json", R"({"materials": ["wood"]})");
    const CliResult result = RunCli("demo --seconds 1 --effects " + (dir / "wood.effects.json").string() +
                                    " --stats " + (dir / "s.json").string());
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find("physics_driven_particles.json: body["), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("unknown material"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "s.json"));
}

TEST(CliEffects, PlainSceneGetsMaterialsFromAssignments)
{
    const std::filesystem::path dir = ScratchDir("plain_scene");
    WriteTestFile(dir / "block.json", SlidingBlock());
    const std::string scene = (dir / "block.json").string();

    const CliResult guessed = RunCli("run " + scene + " --seconds 2 --stats " + (dir / "a.json").string());
    ASSERT_EQ(guessed.exitCode, 0) << guessed.output;
    EXPECT_GT(Spawned(dir / "a.json", "sparks"), 0u) << "steel block on concrete floor, by mass and friction";

    nlohmann::json config = nlohmann::json::parse(FileText(Scene("default.effects.json")));
    config["assignments"] = nlohmann::json::array();
    WriteTestFile(dir / "none.effects.json", config.dump(2));
    const CliResult none =
        RunCli("run " + scene + " --seconds 2 --effects " + (dir / "none.effects.json").string() +
               " --stats " + (dir / "b.json").string());
    ASSERT_EQ(none.exitCode, 0) << none.output;
    EXPECT_EQ(Spawned(dir / "b.json", "sparks"), 0u) << "no property, no assignment: no material";

    // By name: the block is rubber now, and rubber on concrete smokes.
    config["assignments"] = nlohmann::json::parse(R"([{"material": "rubber", "bodyName": "bl*"},
        {"material": "concrete", "bodyType": "static"}])");
    WriteTestFile(dir / "named.effects.json", config.dump(2));
    const CliResult named =
        RunCli("run " + scene + " --seconds 2 --effects " + (dir / "named.effects.json").string() +
               " --stats " + (dir / "c.json").string());
    ASSERT_EQ(named.exitCode, 0) << named.output;
    EXPECT_EQ(Spawned(dir / "c.json", "sparks"), 0u);
    EXPECT_GT(Spawned(dir / "c.json", "smoke"), 0u);
}

TEST(CliEffects, BadAssignmentsAndRulesAreRefused)
{
    const std::filesystem::path dir = ScratchDir("bad_assignments");
    WriteTestFile(dir / "bad.effects.json", R"({"materials": ["a", "b"], "particleTypes": [{"name": "p"}],
        "rules": [{"materialA": "a", "materialB": "b", "particleType": "p"},
                  {"materialA": "b", "materialB": "a", "particleType": "q"}],
        "assignments": [{"material": "c", "bodyType": "floating", "frictionAbove": 1, "frictionBelow": 0}]})");
    const CliResult result =
        RunCli("run " + Scene("physics_driven_particles.json") + " --effects " +
               (dir / "bad.effects.json").string() + " --stats " + (dir / "s.json").string());
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find("bad.effects.json: assignments[0].bodyType: expected one of \"any\""),
              std::string::npos)
        << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "s.json"));

    WriteTestFile(dir / "semantic.effects.json",
                  R"({"materials": ["a", "b"], "particleTypes": [{"name": "p"}],
        "rules": [{"materialA": "a", "materialB": "b", "particleType": "p"},
                  {"materialA": "b", "materialB": "a", "particleType": "q"}],
        "assignments": [{"material": "c", "frictionAbove": 1, "frictionBelow": 0}]})");
    const CliResult semantic = RunCli("validate " + (dir / "semantic.effects.json").string());
    EXPECT_EQ(semantic.exitCode, 1);
    for (const char* path : {"rules[1].particleType", "rules[1]: a second rule", "assignments[0].material",
                             "assignments[0].frictionBelow"})
    {
        EXPECT_NE(semantic.output.find(path), std::string::npos) << path << "\n" << semantic.output;
    }
}

} // namespace cfx::test
