#include "effects_editor.h"

#include "contactfx/scene/effects_json.h"

namespace cfx::testbed
{

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

void EffectsEditor::Save()
{
    if (!DraftIsValid("not saved"))
    {
        return;
    }
    try
    {
        SaveEffectsFile(draft, savePath);
        message = "saved " + savePath;
        messageIsError = false;
    }
    catch (const InputError& error)
    {
        message = error.what();
        messageIsError = true;
    }
}

} // namespace cfx::testbed
