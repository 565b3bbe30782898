// Scene fixtures -> materials: the `material` property first, then the config's assignment rules, so that
// the tutorial scene without a single `material` property gets exactly the tutorial's materials.
#include "contactfx/files/text_file.h"
#include "harness/simulation.h"
#include "scene/rube_test_util.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cfx
{

namespace
{

const std::filesystem::path kTutorialScene =
    std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes/physics_driven_particles.json";

// The scene's JSON with every fixture custom property named `material` removed; counts them in `removed`.
std::string WithoutMaterialProperties(const std::string& text, int& removed)
{
    nlohmann::json scene = nlohmann::json::parse(text);
    removed = 0;
    for (nlohmann::json& body : scene["body"])
    {
        for (nlohmann::json& fixture : body["fixture"])
        {
            if (!fixture.contains("customProperties"))
            {
                continue;
            }
            nlohmann::json& properties = fixture["customProperties"];
            for (std::size_t k = properties.size(); k-- > 0;)
            {
                if (properties[k]["name"] == "material")
                {
                    properties.erase(k);
                    ++removed;
                }
            }
        }
    }
    return scene.dump();
}

std::vector<std::string> MaterialNames(const Scene& scene, const EffectsConfig& config)
{
    std::vector<std::string> names;
    for (MaterialId id : ResolveSceneMaterials(scene, config, "scene.json"))
    {
        names.push_back(id.IsValid() ? config.materials[id.index] : "none");
    }
    return names;
}

std::vector<Diagnostic> ResolveErrors(const Scene& scene, const EffectsConfig& config)
{
    try
    {
        ResolveSceneMaterials(scene, config, "scene.json");
    }
    catch (const InputError& error)
    {
        return error.Diagnostics();
    }
    ADD_FAILURE() << "expected InputError";
    return {};
}

} // namespace

TEST(SceneMaterials, StrippedTutorialSceneGetsTheSameMaterials)
{
    const std::string text = ReadTextFile(kTutorialScene);
    int removed = 0;
    const std::string stripped = WithoutMaterialProperties(text, removed);
    const Scene original = LoadRubeString(text, "tutorial.json");
    const Scene plain = LoadRubeString(stripped, "plain.json");
    ASSERT_EQ(static_cast<std::size_t>(removed), original.fixtures.size()) << "every fixture had one";

    for (const EffectsConfig& config : {TutorialPreset(), DefaultPreset()})
    {
        SCOPED_TRACE(config.name);
        const std::vector<std::string> expected = MaterialNames(original, config);
        EXPECT_EQ(MaterialNames(plain, config), expected);
        for (std::size_t f = 0; f < original.fixtures.size(); ++f)
        {
            EXPECT_EQ(expected[f], *original.fixtures[f].properties.FindString("material"))
                << "the property decides when present";
        }
        EffectsConfig noRules = config;
        noRules.assignments.clear();
        for (const std::string& name : MaterialNames(plain, noRules))
        {
            EXPECT_EQ(name, "none") << "without assignments nothing is guessed";
        }
    }
}

TEST(SceneMaterials, StrippedTutorialSceneRunsIdentically)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "contactfx_scene_materials";
    std::filesystem::create_directories(dir);
    int removed = 0;
    WriteTextFileAtomically(dir / "plain.json",
                            WithoutMaterialProperties(ReadTextFile(kTutorialScene), removed));
    std::string stats[2];
    const std::filesystem::path scenes[2] = {kTutorialScene, dir / "plain.json"};
    for (int i = 0; i < 2; ++i)
    {
        SimulationDef def;
        def.scene = scenes[i];
        def.config = TutorialPreset();
        def.drive = TutorialDrive();
        Simulation simulation(def);
        for (int step = 0; step < 240; ++step)
        {
            simulation.Step();
        }
        stats[i] = StatsJson(simulation.GetEffects(), def.hz);
        EXPECT_GT(simulation.GetEffects().Stats().spawnedByType[0] +
                      simulation.GetEffects().Stats().spawnedByType[2],
                  0u);
    }
    EXPECT_EQ(stats[1], stats[0]);
    std::filesystem::remove_all(dir);
}

TEST(SceneMaterials, PropertyTakesPrecedenceAndNamesAreMatched)
{
    const std::string bodies =
        test::Box(0.0f, 2, R"("name": "crate")") + "," +
        R"({"type": 2, "position": {"x": 3, "y": 0}, "awake": true, "name": "crate", "fixture": [{"name": "lid",
            "density": 1, "friction": 0.5, "customProperties": [{"name": "material", "string": "a"}],
            "circle": {"radius": 1}}]})" +
        "," + test::Box(6.0f, 0, R"("name": "floor")");
    const Scene scene = LoadRubeString(test::World(bodies), "scene.json");
    EffectsConfig config;
    config.materials = {"a", "b"};
    MaterialAssignment crates;
    crates.material = "b";
    crates.bodyName = "cr?te";
    config.assignments = {crates};
    EXPECT_EQ(MaterialNames(scene, config), (std::vector<std::string>{"b", "a", "none"}));
}

// A body's `material` property goes to its fixtures without one of their own (a RUBE user sets it once on
// the body); a fixture's own property and then the body's come before the assignments.
TEST(SceneMaterials, ABodysMaterialGoesToItsFixturesWithoutOne)
{
    const std::string bodies =
        R"({"type": 2, "position": 0, "awake": true, "name": "crate", "customProperties": [{"name": "material",
            "string": "b"}], "fixture": [{"density": 1, "circle": {"radius": 1}}, {"density": 1,
            "customProperties": [{"name": "material", "string": "a"}], "circle": {"radius": 1}}]})";
    const Scene scene = LoadRubeString(test::World(bodies), "scene.json");
    EffectsConfig config;
    config.materials = {"a", "b", "c"};
    MaterialAssignment crates;
    crates.material = "c";
    crates.bodyName = "crate";
    config.assignments = {crates};
    EXPECT_EQ(MaterialNames(scene, config), (std::vector<std::string>{"b", "a"}));

    const std::string bad =
        R"({"type": 2, "position": 0, "awake": true, "customProperties": [{"name": "material", "string": "d"}],
            "fixture": [{"density": 1, "circle": {"radius": 1}}]})";
    const std::vector<Diagnostic> problems =
        ResolveErrors(LoadRubeString(test::World(bad), "scene.json"), config);
    EXPECT_TRUE(test::HasDiagnostic(problems, "body[0].customProperties[0].string", "unknown material \"d\""))
        << test::Dump(problems);

    // Two `material` properties on one object: which one is meant? (The last one silently won.)
    const std::string twice =
        R"({"type": 2, "position": 0, "awake": true, "customProperties": [{"name": "material", "string": "a"},
            {"name": "material", "string": "b"}], "fixture": [{"density": 1, "circle": {"radius": 1}}]})";
    const std::vector<Diagnostic> both =
        ResolveErrors(LoadRubeString(test::World(twice), "scene.json"), config);
    EXPECT_TRUE(test::HasDiagnostic(both, "body[0].customProperties[1].name",
                                    "a second `material` property (the first is customProperties[0])"))
        << test::Dump(both);
}

// A trial's scenes failed on properties of their own whose names are near `material` ("materialId",
// "subMaterial", "material_fx") and on "materials" beside a `material`: only a string property one edit from
// the name, on a body or fixture without a `material` property, is taken for a typo.
TEST(SceneMaterials, OnlyALikelyTypoOfMaterialIsAnError)
{
    const auto problemsWith = [](const std::string& properties)
    {
        const std::string bodies = R"({"type": 2, "position": 0, "awake": true, "fixture": [{"density": 1,
            "customProperties": [)" +
                                   properties + R"(], "circle": {"radius": 1}}]})";
        const Scene scene = LoadRubeString(test::World(bodies), "scene.json");
        try
        {
            ResolveSceneMaterials(scene, TutorialPreset(), "scene.json");
        }
        catch (const InputError& error)
        {
            return error.Diagnostics();
        }
        return std::vector<Diagnostic>{};
    };
    for (const char* fine :
         {R"({"name": "material", "string": "steel"}, {"name": "materials", "string": "a b"})",
          R"({"name": "Material", "string": "x"}, {"name": "material", "string": "steel"})",
          R"({"name": "materialId", "string": "7"})", R"({"name": "subMaterial", "string": "oak"})",
          R"({"name": "material_fx", "string": "sparks"})", R"({"name": "materal", "int": 3})"})
    {
        EXPECT_TRUE(problemsWith(fine).empty()) << fine << test::Dump(problemsWith(fine));
    }
    for (const char* typo :
         {R"({"name": "Material", "string": "steel"})", R"({"name": "materials", "string": "steel"})",
          R"({"name": "materal", "string": "steel"})"})
    {
        EXPECT_TRUE(test::HasDiagnostic(problemsWith(typo), "body[0].fixture[0].customProperties[0].name",
                                        "did you mean `material`?"))
            << typo << test::Dump(problemsWith(typo));
    }
}

// A chain's back side (the reversed chain that makes it two-sided, see SceneFixture::backSide) is the same
// surface: it gets the chain's material, so that a body on either side makes the same effects.
TEST(SceneMaterials, AChainsBackSideGetsTheChainsMaterial)
{
    const Scene scene =
        LoadRubeString(test::World(R"({"type": 0, "fixture": [{"name": "road", "customProperties":
        [{"name": "material", "string": "b"}], "chain": {"vertices": {"x": [-5, 0, 5], "y": [0, 0, 0]}}}]})"),
                       "scene.json");
    ASSERT_EQ(scene.fixtures.size(), 1u);
    ASSERT_NE(scene.fixtures[0].backSide, nullptr);
    EffectsConfig config = TutorialPreset();
    config.materials.push_back("b");
    Effects effects(*scene.world, EffectsDef{config});
    AssignSceneMaterials(scene, effects, "scene.json");
    const MaterialId road = effects.Material(scene.fixtures[0].fixture);
    ASSERT_TRUE(road.IsValid());
    EXPECT_EQ(effects.Material(scene.fixtures[0].backSide), road);
}

// A trial's config of 20,000 materials made every unknown material's message list all of them (900 kB a
// fixture); and a material name with a line break forged a second line of validate's output.
TEST(SceneMaterials, AnUnknownMaterialsMessageIsOneLineOfBoundedLength)
{
    const std::string bodies =
        R"({"type": 2, "position": 0, "awake": true, "fixture": [{"density": 1, "customProperties": [{"name":
            "material", "string": "zz\nfake.json: ok"}], "circle": {"radius": 1}}]})";
    const Scene scene = LoadRubeString(test::World(bodies), "scene.json");
    EffectsConfig config = TutorialPreset();
    while (config.materials.size() < 25)
    {
        config.materials.push_back("m" + std::to_string(config.materials.size()));
    }
    const std::vector<Diagnostic> problems = ResolveErrors(scene, config);
    ASSERT_EQ(problems.size(), 1u) << test::Dump(problems);
    EXPECT_EQ(problems[0].message.find('\n'), std::string::npos) << problems[0].message;
    EXPECT_NE(problems[0].message.find("unknown material \"zz\\nfake.json: ok\""), std::string::npos)
        << problems[0].message;
    EXPECT_NE(problems[0].message.find(", m19 and 5 more)"), std::string::npos) << problems[0].message;
}

// A trial misspelt the property on one fixture ("materal"): it silently got no material, even under
// validate --strict, and the scene lost 80 % of its dust.
TEST(SceneMaterials, AMisspeltMaterialPropertyIsAnError)
{
    const std::string bodies =
        R"({"type": 2, "position": 0, "awake": true, "fixture": [{"density": 1, "customProperties": [{"name":
            "materal", "string": "steel"}, {"name": "colour", "string": "red"}], "circle": {"radius": 1}}]})";
    const Scene scene = LoadRubeString(test::World(bodies), "scene.json");
    const std::vector<Diagnostic> problems = ResolveErrors(scene, TutorialPreset());
    ASSERT_EQ(problems.size(), 1u) << test::Dump(problems) << "another property is no error";
    EXPECT_TRUE(test::HasDiagnostic(problems, "body[0].fixture[0].customProperties[0].name",
                                    "a custom property named \"materal\", did you mean `material`?"))
        << test::Dump(problems);
}

// A misspelt material name is named with the nearest material of the config, as in effects configs.
TEST(SceneMaterials, AMisspeltMaterialNameNamesTheNearestMaterial)
{
    const std::string bodies =
        R"({"type": 2, "position": 0, "awake": true, "fixture": [{"density": 1, "customProperties": [{"name":
            "material", "string": "rubbr"}], "circle": {"radius": 1}}]})";
    const Scene scene = LoadRubeString(test::World(bodies), "scene.json");
    const std::vector<Diagnostic> problems = ResolveErrors(scene, TutorialPreset());
    EXPECT_TRUE(
        test::HasDiagnostic(problems, "body[0].fixture[0].customProperties[0].string",
                            "unknown material \"rubbr\", did you mean \"rubber\"? (the effects config"))
        << test::Dump(problems);
}

TEST(SceneMaterials, BadPropertiesAreAllReportedAndNothingIsAssigned)
{
    const std::string bodies =
        R"({"type": 2, "position": 0, "awake": true, "fixture": [{"density": 1, "customProperties": [{"name":
            "material", "string": "glass"}], "circle": {"radius": 1}}, {"density": 1, "customProperties": [{"name":
            "x", "int": 1}, {"name": "material", "int": 4}], "circle": {"radius": 1}}]})";
    const Scene scene = LoadRubeString(test::World(bodies), "scene.json");
    const std::vector<Diagnostic> problems = ResolveErrors(scene, TutorialPreset());
    EXPECT_TRUE(
        test::HasDiagnostic(problems, "body[0].fixture[0].customProperties[0].string",
                            "unknown material \"glass\" (the effects config \"tutorial\" has: steel, rubber"))
        << test::Dump(problems);
    EXPECT_TRUE(test::HasDiagnostic(problems, "body[0].fixture[1].customProperties[1]",
                                    "expected the material as a string property, found int property 4"))
        << test::Dump(problems);
    for (const Diagnostic& problem : problems)
    {
        EXPECT_EQ(problem.file, "scene.json");
    }

    Effects effects(*scene.world, EffectsDef{TutorialPreset()});
    EXPECT_THROW(AssignSceneMaterials(scene, effects, "scene.json"), InputError);
    for (const SceneFixture& fixture : scene.fixtures)
    {
        EXPECT_FALSE(effects.Material(fixture.fixture).IsValid());
    }
}

TEST(SceneMaterials, APlainRubeSceneGetsMaterialsFromTheDefaultAssignments)
{
    // The tutorial scene with every custom property removed, as RUBE writes a scene made without us.
    nlohmann::json json = test::ReadJson(test::ProjectScene("physics_driven_particles.json"));
    for (nlohmann::json& body : json["body"])
    {
        for (nlohmann::json& fixture : body["fixture"])
        {
            fixture.erase("customProperties");
        }
    }
    const Scene plain = LoadRubeString(json.dump(), "plain.json");
    std::vector<std::string> names = MaterialNames(plain, DefaultPreset());
    EXPECT_GT(
        std::count_if(names.begin(), names.end(), [](const std::string& name) { return name != "none"; }), 0);
}

TEST(SceneMaterials, PlainRubeSamplesGetMaterialsFromTheDefaultAssignments)
{
    CONTACTFX_REQUIRE_RUBE_SAMPLES();
    const Scene car = LoadRubeFile(test::RubeSamplesDir() / "car.json");
    int assigned = 0;
    for (const std::string& name : MaterialNames(car, DefaultPreset()))
    {
        assigned += name != "none" ? 1 : 0;
    }
    EXPECT_GT(assigned, 0);
}

} // namespace cfx
