// contactfx-testbed: the effects configuration being edited, apart from its widgets.
//
// The panel edits a draft. Apply puts a valid draft into force at once (Session::ApplyConfig, which
// keeps the world); an invalid one is never applied, and its problems are kept for display, field by
// field. Save writes the draft as an effects config JSON file that `contactfx run --effects` reads.
#pragma once

#include "contactfx/config.h"
#include "session.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cfx::testbed
{

struct EffectsEditor
{
    EffectsConfig draft;          ///< what the widgets edit
    std::uint64_t generation = 0; ///< Session::Generation() the draft was taken from; 0: none
    std::string savePath = "testbed.effects.json";
    std::string message; ///< what became of the last apply or save
    bool messageIsError = false;
    std::vector<Diagnostic> problems; ///< of the draft, after the last apply

    /// Takes a fresh draft from the session's simulation when it is not the one the draft came from
    /// (another scene, a restart) or when `force` (revert).
    void Follow(const Session& session, bool force = false);
    /// Validates the draft and, when valid, puts it into force.
    void Apply(Session& session);
    /// Writes the draft to savePath, unless it has problems, or savePath is a file the session's scenes are
    /// read from (Session::SceneFiles, also through a link) or in the registered scenes' folder. The
    /// message names the file written, absolute.
    void Save(const Session& session);
    /// What "Add sound rule" adds: a sound rule for the first pair rule (in order) that has none yet, else
    /// for the first pair rule, else with no materials (a sound rule applies only to a pair rule's pair).
    static SoundRuleDef NewSoundRule(const EffectsConfig& config);

private:
    /// Validates the draft into `problems`; when invalid, says so in `message`, starting with `refused`.
    bool DraftIsValid(const char* refused);
};

} // namespace cfx::testbed
