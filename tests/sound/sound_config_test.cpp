// The `sound` section of an effects config file: bad values are errors naming their JSON path, all at once.
#include "contactfx/presets.h"
#include "contactfx/scene/effects_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace cfx::test
{

namespace
{

// The problems of the default preset with `sound` replaced, as "path: message" lines.
std::vector<std::string> Problems(const nlohmann::json& sound)
{
    nlohmann::json root = nlohmann::json::parse(SaveEffectsString(DefaultPreset()));
    root["sound"] = sound;
    std::vector<std::string> lines;
    try
    {
        LoadEffectsString(root.dump(), "bad.effects.json");
    }
    catch (const InputError& error)
    {
        for (const Diagnostic& problem : error.Diagnostics())
        {
            EXPECT_EQ(problem.file, "bad.effects.json");
            lines.push_back(problem.path + ": " + problem.message);
        }
    }
    return lines;
}

} // namespace

TEST(SoundConfig, TheDefaultPresetRoundTripsWithItsSoundSection)
{
    EffectsConfig config = DefaultPreset();
    config.sound.maxVoices = 5;
    config.sound.rules.push_back(
        SoundRuleDef{.materialA = "steel", .materialB = "dirt", .scrapeStart = 0.2f});
    config.sound.rules.back().timbre = SoundTimbre::squeal;
    EXPECT_EQ(LoadEffectsString(SaveEffectsString(config), "x.json"), config);
}

TEST(SoundConfig, BadValuesAreErrorsWithTheirJsonPath)
{
    const std::vector<std::string> problems = Problems({
        {"maxVoices", 0},
        {"impactMergeWindow", -0.01},
        {"gian", 1.0},
        {"rules",
         {{{"materialA", "steel"}, {"materialB", "concrete"}, {"scrapeStart", 1.5}, {"timbre", "whistle"}},
          {{"materialA", "concrete"}, {"materialB", "steel"}, {"release", "long"}},
          {{"materialA", "glass"}, {"materialB", "steel"}, {"impactLength", 0}}}},
    });
    const std::vector<std::string> expected = {
        "sound.gian: unknown field, did you mean `gain`?",
        "sound.maxVoices: expected an integer in [1, 4096], found 0",
        "sound.rules[0].timbre: expected one of \"auto\", \"hiss\", \"squeal\", \"rumble\", found "
        "string \"whistle\"",
        "sound.rules[1].release: expected a number, found string \"long\"",
        "sound.impactMergeWindow: expected a number between 0 and 10, found -0.01",
        "sound.rules[0].scrapeStart: expected a number between 0 and 1, found 1.5",
        "sound.rules[1]: a second sound rule for the pair concrete+steel (the first is sound.rules[0])",
        "sound.rules[2].materialA: unknown material \"glass\" (materials: steel, rubber, concrete, dirt)",
        "sound.rules[2].impactLength: expected a number > 0 and <= 10, found 0",
    };
    EXPECT_EQ(problems, expected);
}

} // namespace cfx::test
