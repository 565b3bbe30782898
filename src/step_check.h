// contactfx internal: the one check of a step time every Step of the API makes (Effects, ParticleSystem,
// SoundVoices).
#pragma once

#include "contactfx/error.h"
#include "float_text.h"

#include <cmath>

namespace cfx::detail
{

/// Throws InputError (file "<api>", field "dt") unless `dt` is a finite step time > 0 s.
inline void CheckStepTime(float dt)
{
    if (!(dt > 0.0f) || !std::isfinite(dt))
    {
        throw InputError("<api>", "dt", "expected a finite step time > 0 s, found " + FloatText(dt));
    }
}

} // namespace cfx::detail
