#include "effects_editor.h"

#include "contactfx/scene/effects_json.h"
#include "harness/command_line.h"

#include <algorithm>

namespace cfx::testbed
{

SoundRuleDef EffectsEditor::NewSoundRule(const EffectsConfig& config)
{
    auto samePair = [](const std::string& a1, const std::string& b1, const std::string& a2,
                       const std::string& b2) { return (a1 == a2 && b1 == b2) || (a1 == b2 && b1 == a2); };
    SoundRuleDef rule;
    for (const RuleDef& pair : config.rules)
    {
        const bool sounded =
            std::any_of(config.sound.rules.begin(), config.sound.rules.end(),
                        [&](const SoundRuleDef& sound) {
                            return samePair(sound.materialA, sound.materialB, pair.materialA, pair.materialB);
                        });
        if (!sounded)
        {
            rule.materialA = pair.materialA;
            rule.materialB = pair.materialB;
            return rule;
        }
    }
    if (!config.rules.empty())
    {
        rule.materialA = config.rules.front().materialA;
        rule.materialB = config.rules.front().materialB;
    }
    return rule;
}

void EffectsEditor::Follow(const Session& session, bool force)
{
    if (force || generation != session.Generation())
    {
        generation = session.Generation();
        draft = session.Sim().GetEffects().Config();
        problems.clear();
        message.clear();
        messageIsError = false;
    }
}

bool EffectsEditor::DraftIsValid(const char* refused)
{
    problems = Validate(draft, "<testbed>");
    if (!problems.empty())
    {
        message = std::string(refused) + ": fix the problems below";
        messageIsError = true;
    }
    return problems.empty();
}

void EffectsEditor::Apply(Session& session)
{
    if (!DraftIsValid("not applied"))
    {
        return;
    }
    try
    {
        session.ApplyConfig(draft);
        message = "applied: particles start afresh";
        messageIsError = false;
    }
    catch (const InputError& error)
    {
        problems = error.Diagnostics();
        message = "not applied: the scene needs what the draft lacks";
        messageIsError = true;
    }
}

void EffectsEditor::Save(const Session& session)
{
    if (!DraftIsValid("not saved"))
    {
        return;
    }
    if (SameFile(savePath, session.SceneFile()))
    {
        message = savePath + ": is the scene file on show: not overwritten";
        messageIsError = true;
        return;
    }
    try
    {
        SaveEffectsFile(draft, savePath);
        std::error_code error;
        message = "saved " + std::filesystem::absolute(savePath, error).lexically_normal().string();
        messageIsError = false;
    }
    catch (const InputError& error)
    {
        message = error.what();
        messageIsError = true;
    }
}

} // namespace cfx::testbed
