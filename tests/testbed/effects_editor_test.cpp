// The effects editor's "Add sound rule": a sound rule applies only to the pair of a pair rule (a sound
// rule for any other pair is an error), so a new one is for the first pair rule that has none yet.
#include "contactfx/presets.h"
#include "effects_editor.h"

#include <gtest/gtest.h>

namespace cfx::testbed
{
namespace
{

TEST(EffectsEditor, ANewSoundRuleIsForTheFirstPairRuleThatHasNone)
{
    EffectsConfig config = DefaultPreset();
    ASSERT_GE(config.rules.size(), 2u);
    config.sound.rules.clear();
    SoundRuleDef rule = EffectsEditor::NewSoundRule(config);
    EXPECT_EQ(rule.materialA, config.rules[0].materialA);
    EXPECT_EQ(rule.materialB, config.rules[0].materialB);

    // The first pair has one (written the other way round): the next pair without one.
    SoundRuleDef first;
    first.materialA = config.rules[0].materialB;
    first.materialB = config.rules[0].materialA;
    config.sound.rules.push_back(first);
    rule = EffectsEditor::NewSoundRule(config);
    EXPECT_EQ(rule.materialA, config.rules[1].materialA);
    EXPECT_EQ(rule.materialB, config.rules[1].materialB);

    // Every pair has one: the first pair's again; and no pair rule at all: no materials.
    for (std::size_t i = 1; i < config.rules.size(); ++i)
    {
        SoundRuleDef sound;
        sound.materialA = config.rules[i].materialA;
        sound.materialB = config.rules[i].materialB;
        config.sound.rules.push_back(sound);
    }
    rule = EffectsEditor::NewSoundRule(config);
    EXPECT_EQ(rule.materialA, config.rules[0].materialA);
    config.rules.clear();
    rule = EffectsEditor::NewSoundRule(config);
    EXPECT_TRUE(rule.materialA.empty());
    EXPECT_TRUE(rule.materialB.empty());
}

TEST(EffectsEditor, TheDefaultPresetWithANewSoundRuleIsValid)
{
    EffectsConfig config = DefaultPreset();
    config.sound.rules.push_back(EffectsEditor::NewSoundRule(config));
    EXPECT_TRUE(Validate(config).empty());
}

} // namespace
} // namespace cfx::testbed
