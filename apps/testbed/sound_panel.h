// contactfx-testbed: the sound panel. The voices (contactfx/sound.h) of the running simulation, each with
// a loudness meter, and, when the testbed was built with SDL2 and an audio device opens, the built-in
// synthesizer playing them live.
#pragma once

#include "session.h"

namespace cfx::testbed
{

/// Draws the panel; call once per frame after the frame's steps. Keeps its own voices, fed from the
/// session's event log, and starts them afresh when the scene, its time or its effects change.
void SoundPanel(const Session& session);

} // namespace cfx::testbed
