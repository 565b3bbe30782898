// contactfx internal: the one check of a step time every Step of the API makes (Effects, ParticleSystem,
// SoundVoices).
#pragma once

#include "contactfx/error.h"

#include <cmath>
#include <sstream>

namespace cfx::detail
{

/// Throws InputError (file "<api>", field "dt") unless `dt` is a finite step time > 0 s.
inline void CheckStepTime(float dt)
{
    if (!(dt > 0.0f) || !std::isfinite(dt))
    {
        std::ostringstream found;
        found << dt;
        throw InputError("<api>", "dt", "expected a finite step time > 0 s, found " + found.str());
    }
}

} // namespace cfx::detail
