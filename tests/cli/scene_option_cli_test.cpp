// run --scene NAME: a registered scene (harness/scenes.h) with its scripted drive, per-step action and
// effects, the same code path as demo; a scene file runs as it is.
#include "cli/cli_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cfx::test
{

TEST(CliScene, RunSceneDrivesTheRegisteredScene)
{
    const std::filesystem::path dir = ScratchDir("run_scene_skidpad");
    const CliResult scene =
        RunCli("run --scene skidpad --seconds 3 --stats " + (dir / "scene.json").string());
    ASSERT_EQ(scene.exitCode, 0) << scene.output;
    EXPECT_NE(scene.output.find("contactfx run --scene skidpad:"), std::string::npos) << scene.output;
    EXPECT_GT(Spawned(dir / "scene.json", "smoke"), 0u) << "the skid pad's drive spins and locks the tyres";

    // The file itself still runs, without the drive.
    const CliResult file =
        RunCli("run " + Scene("skidpad.json") + " --seconds 3 --stats " + (dir / "file.json").string());
    ASSERT_EQ(file.exitCode, 0) << file.output;
    EXPECT_LT(Spawned(dir / "file.json", "smoke"), Spawned(dir / "scene.json", "smoke"));
}

// A scene file's own step rate is not the run's (--hz, default 60): run and render say so, naming the file
// and the field, and say nothing when the two agree.
TEST(CliScene, ASceneStepRateOtherThanTheRunsIsAWarning)
{
    const std::filesystem::path dir = ScratchDir("run_scene_rate");
    nlohmann::json scene = nlohmann::json::parse(FileText(Scene("grinder.json")));
    scene["stepsPerSecond"] = 30;
    const std::filesystem::path file = dir / "grinder30.json";
    WriteTestFile(file, scene.dump());
    const std::string warning = file.string() +
                                ": stepsPerSecond: warning: the scene steps at 30 Hz; this "
                                "run steps at --hz 60 (give --hz 30 to step as the scene says)";
    const CliResult run = RunCli("run " + file.string() + " --seconds 0.1");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find(warning), std::string::npos) << run.output;
    const CliResult render =
        RunCli("render " + file.string() + " --seconds 0.1 --width 32 --height 32 --out " +
               (dir / "frame.png").string());
    ASSERT_EQ(render.exitCode, 0) << render.output;
    EXPECT_NE(render.output.find(warning), std::string::npos) << render.output;

    const CliResult agreed = RunCli("run " + file.string() + " --seconds 0.1 --hz 30");
    ASSERT_EQ(agreed.exitCode, 0) << agreed.output;
    EXPECT_EQ(agreed.output.find("warning"), std::string::npos) << agreed.output;

    // The rate as the file has it (a float), and no warning for a registered scene run at another rate.
    scene["stepsPerSecond"] = 59.99;
    WriteTestFile(file, scene.dump());
    const CliResult odd = RunCli("run " + file.string() + " --seconds 0.1");
    EXPECT_NE(odd.output.find("the scene steps at 59.99 Hz; this run steps at --hz 60 (give --hz 59.99 "),
              std::string::npos)
        << odd.output;
    const CliResult matching = RunCli("run " + file.string() + " --seconds 0.1 --hz 59.99");
    ASSERT_EQ(matching.exitCode, 0) << matching.output;
    EXPECT_EQ(matching.output.find("warning"), std::string::npos)
        << "59.99 is 59.99 as a float too: " << matching.output;
    const CliResult registered = RunCli("run --scene grinder --seconds 0.1 --hz 30");
    ASSERT_EQ(registered.exitCode, 0) << registered.output;
    EXPECT_EQ(registered.output.find("warning"), std::string::npos) << registered.output;
}

TEST(CliScene, RunSceneTutorialIsTheDemo)
{
    const std::filesystem::path dir = ScratchDir("run_scene_tutorial");
    ASSERT_EQ(
        RunCli("run --scene tutorial --seconds 2 --preset tutorial --stats " + (dir / "run.json").string())
            .exitCode,
        0);
    ASSERT_EQ(RunCli("demo --seconds 2 --preset tutorial --stats " + (dir / "demo.json").string()).exitCode,
              0);
    EXPECT_EQ(FileText(dir / "run.json"), FileText(dir / "demo.json"));
}

TEST(CliScene, UnknownSceneListsTheRegisteredOnes)
{
    for (const char* command : {"run --scene grindr --seconds 1", "render --scene grindr --out x.png"})
    {
        const CliResult result = RunCli(command);
        EXPECT_EQ(result.exitCode, 1) << command << "\n" << result.output;
        for (const char* text : {"contactfx: error:", "--scene", "\"grindr\"", "did you mean 'grinder'?",
                                 "tutorial, grinder, skidpad, rockslide"})
        {
            EXPECT_NE(result.output.find(text), std::string::npos)
                << "'" << text << "' missing for '" << command << "' in:\n"
                << result.output;
        }
    }
}

TEST(CliScene, SceneFileAndSceneNameExcludeEachOther)
{
    CliResult result = RunCli("run --scene skidpad " + Scene("skidpad.json") + " --seconds 1");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("not both"), std::string::npos) << result.output;
    result = RunCli("run --seconds 1");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("--scene NAME"), std::string::npos) << result.output;
    // A registered name given as the file (a trial's `contactfx-testbed grinder`): the hint, not only
    // "cannot open for reading".
    result = RunCli("run grinder --seconds 1");
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("<command line>: scene: no file \"grinder\"; for the registered scene give "
                                 "--scene grinder"),
              std::string::npos)
        << result.output;
}

} // namespace cfx::test
