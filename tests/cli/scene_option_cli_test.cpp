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
}

} // namespace cfx::test
