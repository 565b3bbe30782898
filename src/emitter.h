// contactfx internal: from tracked contacts to particles, once per step.
//
// For every tracked contact with manifold points: one sample per manifold point (or only the first,
// per the rule's model) -> intensity -> a count of particles (one per step in the tutorial's mode, or a
// rate accumulated across steps so the count does not depend on the step rate) -> one start point per
// sample, found outside both surfaces -> velocities and lives per particle. Randomness comes from one
// seeded generator drawn in a fixed order (rules, then contacts in tracking order, then points), so
// the same inputs and seed give the same particles bit for bit.
#pragma once

#include "contactfx/effects.h"
#include "random.h"

#include <cstdint>

namespace cfx::detail
{

class Emitter
{
public:
    explicit Emitter(std::uint64_t seed) : m_random(seed) {}

    /// Emits for every tracked contact of every rule into `particles`; updates `stats`.
    void Emit(b2World& world, const EffectsConfig& config, ContactTracker& tracker, ParticleSystem& particles,
              EffectsStats& stats, float dt);

private:
    Random m_random;
};

} // namespace cfx::detail
