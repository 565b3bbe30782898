#include "effects_editor.h"

#include "contactfx/scene/effects_json.h"
#include "harness/command_line.h"

#include <algorithm>

namespace cfx::testbed
{

namespace
{

// `path` absolute, with every symbolic link in it followed (those of the folders above it, then its own,
// dangling or not) and `.` and `..` taken as the file system does.
std::filesystem::path Resolved(const std::filesystem::path& path)
{
    std::error_code error; // a part that is missing stays as written
    return std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
}

// The file a write to `name` lands in: its own symbolic links followed too (up to 40, as the kernel).
std::filesystem::path WhereWritten(const std::filesystem::path& name)
{
    std::error_code error;
    std::filesystem::path path = Resolved(name);
    for (int link = 0; link < 40 && std::filesystem::is_symlink(path, error); ++link)
    {
        const std::filesystem::path target = std::filesystem::read_symlink(path, error);
        path = Resolved(target.is_absolute() ? target : path.parent_path() / target);
    }
    return path;
}

} // namespace

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
    const std::filesystem::path target = WhereWritten(savePath);
    for (const std::filesystem::path& file : session.SceneFiles())
    {
        if (SameFile(target, file))
        {
            message = savePath + ": is a file the testbed's scenes are read from (" + file.string() +
                      "): not overwritten";
            messageIsError = true;
            return;
        }
    }
    const std::filesystem::path bundled = Resolved(session.ScenesDir());
    for (std::filesystem::path folder = target.parent_path(); !folder.empty(); folder = folder.parent_path())
    {
        if (folder == bundled)
        {
            message = savePath + ": is in the bundled scenes' folder (" + session.ScenesDir().string() +
                      "): save it elsewhere";
            messageIsError = true;
            return;
        }
        if (folder == folder.parent_path())
        {
            break;
        }
    }
    try
    {
        SaveEffectsFile(draft, savePath);
        message = "saved " + target.string();
        messageIsError = false;
    }
    catch (const InputError& error)
    {
        message = error.what();
        messageIsError = true;
    }
}

} // namespace cfx::testbed
