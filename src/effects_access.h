// contactfx internal: what the library's own tests and tools may see of an Effects object beyond its
// public API. Not installed; users never need it.
#pragma once

#include "contact_tracker.h"
#include "contactfx/effects.h"

namespace cfx::detail
{

struct EffectsAccess
{
    /// The contacts Effects tracks now, per rule.
    static const ContactTracker& Tracker(const Effects& effects);
};

} // namespace cfx::detail
