// Unknown keys: warnings naming the nearest known key in scenes, errors in effects configs; a scene given as
// an effects config (or the reverse) is one error that says so.
#include "contactfx/scene/effects_json.h"
#include "nearest_name.h"
#include "scene/known_keys.h"
#include "scene/rube_test_util.h"

#include <gtest/gtest.h>

namespace cfx
{
namespace
{

using test::Box;
using test::Dump;
using test::HasDiagnostic;
using test::World;

std::vector<Diagnostic> WarningsOf(const std::string& json)
{
    std::vector<Diagnostic> warnings;
    const std::vector<Diagnostic> errors = ValidateRubeString(json, "scene.json", nullptr, &warnings);
    EXPECT_TRUE(errors.empty()) << Dump(errors);
    for (const Diagnostic& warning : warnings)
    {
        EXPECT_TRUE(warning.warning);
        EXPECT_EQ(warning.file, "scene.json");
    }
    return warnings;
}

// A trial's config of 20,000 materials with rules naming unknown ones took minutes to validate: every
// suggestion compared the name with every material. The suggestions of one file now spend a bounded
// budget of comparisons; every problem is still reported, the hints past the budget are left out.
TEST(NearestKey, SuggestionsSpendABoundedBudget)
{
    detail::SuggestionBudget budget{100};
    const std::vector<std::string> materials = {"steel", "stone"};
    EXPECT_EQ(detail::DidYouMean("stel", materials, budget), ", did you mean \"steel\"?");
    EXPECT_EQ(budget.cells, 100u - 2u * 5u * 6u) << "(4 + 1) x (5 + 1) cells for each material";
    detail::SuggestionBudget spent{59};
    EXPECT_EQ(detail::DidYouMean("stel", materials, spent), "") << "not enough for both";
    EXPECT_EQ(spent.cells, 59u) << "kept for shorter ones";

    EffectsConfig config;
    const auto name = [](char first, int i)
    {
        const std::string digits = std::to_string(100000 + i); // 6 characters, the first left out
        return first + digits.substr(1);
    };
    for (int i = 0; i < 20000; ++i)
    {
        config.materials.push_back(name('m', i));
    }
    config.particleTypes.push_back(ParticleTypeDef{});
    config.particleTypes.back().name = "p";
    for (int i = 0; i < 200; ++i)
    {
        RuleDef rule;
        rule.materialA = name('m', i);
        rule.materialB = name('x', i); // one edit from its 'm' name
        rule.particleType = "p";
        config.rules.push_back(rule);
    }
    std::size_t unknown = 0;
    std::size_t hinted = 0;
    for (const Diagnostic& problem : Validate(config, "many.json"))
    {
        unknown += problem.message.find("unknown material") != std::string::npos ? 1 : 0;
        hinted += problem.message.find("did you mean") != std::string::npos ? 1 : 0;
    }
    EXPECT_EQ(unknown, 200u);
    // Each hint compares a name of 6 characters with 20,000 of 6: 7 x 7 x 20,000 = 980,000 cells, so the
    // budget of 50,000,000 holds 51 of them.
    EXPECT_EQ(hinted, 51u);
}

TEST(NearestKey, FindsTyposOnly)
{
    using scene_detail::NearestKey;
    constexpr std::string_view kKeys[] = {"gravity", "body", "joint", "friction", "restitution"};
    EXPECT_EQ(NearestKey("gravty", kKeys), "gravity");
    EXPECT_EQ(NearestKey("Gravity", kKeys), "gravity");
    EXPECT_EQ(NearestKey("frcition", kKeys), "friction");
    EXPECT_EQ(NearestKey("restituion", kKeys), "restitution");
    EXPECT_FALSE(NearestKey("gravity", kKeys));
    EXPECT_FALSE(NearestKey("colour", kKeys));
    EXPECT_FALSE(NearestKey("x", kKeys));
}

TEST(SceneKeys, AMisspeltKeyIsAWarningNamingTheNearestKey)
{
    const std::string scene = R"({"gravty": {"x": 0, "y": -10}, "body": [)" + Box(0.0f) + "]}";
    const std::vector<Diagnostic> warnings = WarningsOf(scene);
    ASSERT_EQ(warnings.size(), 1U) << Dump(warnings);
    EXPECT_EQ(warnings[0].path, "gravty");
    EXPECT_EQ(warnings[0].message, "unknown key, did you mean `gravity`?");
    EXPECT_EQ(warnings[0].ToString(), "scene.json: gravty: warning: unknown key, did you mean `gravity`?");
    // It still loads (b2dJson ignores unknown keys), and the scene carries the warning.
    const Scene loaded = LoadRubeString(scene, "scene.json");
    ASSERT_EQ(loaded.warnings.size(), 1U);
    EXPECT_EQ(loaded.warnings[0].path, "gravty");
}

TEST(SceneKeys, EveryLevelIsChecked)
{
    const std::string body = R"({"type": 2, "angularDamping": 0.1, "angulrVelocity": 1, "fixture": [
        {"density": 1, "frcition": 0.5, "circle": {"radius": 1, "centre": 0},
         "customProperties": [{"name": "material", "string": "steel", "strng": "steel"}]},
        {"polygon": {"vertices": {"x": [0, 1, 0], "y": [0, 0, 1], "z": [0, 0, 0]}}}]})";
    const std::string joint = R"({"type": "revolute", "bodyA": 0, "bodyB": 1, "motorSped": 1,
        "jointSpeed": 0, "frequency": 3})";
    const std::vector<Diagnostic> warnings = WarningsOf(
        World(body + "," + Box(3.0f), joint, R"("image": [{"opacty": 1}], "collisionbitplanes": {})"));
    EXPECT_TRUE(HasDiagnostic(warnings, "body[0].angulrVelocity", "did you mean `angularVelocity`?"));
    EXPECT_TRUE(HasDiagnostic(warnings, "body[0].fixture[0].frcition", "did you mean `friction`?"));
    EXPECT_TRUE(HasDiagnostic(warnings, "body[0].fixture[0].circle.centre", "did you mean `center`?"));
    EXPECT_TRUE(
        HasDiagnostic(warnings, "body[0].fixture[0].customProperties[0].strng", "did you mean `string`?"));
    EXPECT_TRUE(HasDiagnostic(warnings, "body[0].fixture[1].polygon.vertices.z", "unknown key"));
    EXPECT_TRUE(HasDiagnostic(warnings, "joint[0].motorSped", "did you mean `motorSpeed`?"));
    // A key of another joint type is unknown for this one.
    EXPECT_TRUE(HasDiagnostic(warnings, "joint[0].frequency", "unknown key"));
    EXPECT_TRUE(HasDiagnostic(warnings, "image[0].opacty", "did you mean `opacity`?"));
    EXPECT_EQ(warnings.size(), 8U) << Dump(warnings);
}

TEST(SceneKeys, RealScenesHaveNoUnknownKeys)
{
    for (const std::filesystem::path& file : test::SampleFiles())
    {
        std::vector<Diagnostic> warnings;
        EXPECT_TRUE(ValidateRubeFile(file, nullptr, &warnings).empty()) << file;
        for (const Diagnostic& warning : warnings)
        {
            EXPECT_EQ(warning.message.find("unknown key"), std::string::npos) << warning.ToString();
        }
    }
}

TEST(SceneKeys, AnEffectsConfigIsNotAScene)
{
    const std::filesystem::path effects =
        std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes" / "default.effects.json";
    std::vector<Diagnostic> warnings;
    const std::vector<Diagnostic> errors = ValidateRubeFile(effects, nullptr, &warnings);
    ASSERT_EQ(errors.size(), 1U) << Dump(errors);
    EXPECT_EQ(errors[0].path, "");
    EXPECT_NE(errors[0].message.find("expected a RUBE scene, found an effects config"), std::string::npos)
        << errors[0].message;
    EXPECT_TRUE(warnings.empty());
    EXPECT_THROW(LoadRubeFile(effects), InputError);
}

TEST(EffectsKeys, ASceneIsNotAnEffectsConfig)
{
    const std::vector<Diagnostic> errors =
        ValidateEffectsFile(std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes" / "grinder.json");
    ASSERT_EQ(errors.size(), 1U) << Dump(errors);
    EXPECT_EQ(errors[0].path, "");
    EXPECT_NE(errors[0].message.find("expected an effects config, found a RUBE scene"), std::string::npos)
        << errors[0].message;
}

TEST(EffectsKeys, AnUnknownFieldIsAnErrorNamingTheNearestField)
{
    try
    {
        LoadEffectsString(R"({"materials": ["a"], "particleTypes": [{"name": "p", "lifetme": 2}],
                              "budgte": {}})",
                          "fx.json");
        FAIL();
    }
    catch (const InputError& error)
    {
        EXPECT_TRUE(HasDiagnostic(error.Diagnostics(), "particleTypes[0].lifetme",
                                  "unknown field, did you mean `lifetime`?"))
            << Dump(error.Diagnostics());
        EXPECT_TRUE(HasDiagnostic(error.Diagnostics(), "budgte", "unknown field, did you mean `budget`?"));
    }
}

} // namespace
} // namespace cfx
