// contactfx internal: from tracked contacts to particles, once per step.
//
// For every tracked contact with manifold points: one sample per manifold point (or only the first,
// per the rule's model) -> intensity -> a count of particles (one per step in the tutorial's mode, or a
// rate accumulated across steps so the count does not depend on the step rate) -> one start point per
// sample, found outside both surfaces -> velocities and lives per particle. The same pass decides the
// contact's scrape (began / changed / ended) and reports its impact (with a burst of particles) when it
// began touching fast enough since the last step. Randomness comes from one
// seeded generator drawn in a fixed order (rules, then contacts in tracking order, then points), so
// the same inputs and seed give the same particles bit for bit.
#pragma once

#include "contact_tracker.h"
#include "contactfx/config.h"
#include "contactfx/intensity.h"
#include "contactfx/particle_system.h"
#include "contactfx/stats.h"
#include "random.h"

#include <cstdint>
#include <vector>

namespace cfx::detail
{

class Emitter
{
public:
    /// `config` must be valid (Validate) and is the one Emit will be given.
    Emitter(const EffectsConfig& config, std::uint64_t seed);

    /// For every tracked contact of every rule: emits into `particles`, appends scrape and impact events
    /// to `events` (events.h gives the order), updates `stats`.
    void Emit(b2World& world, const EffectsConfig& config, ContactTracker& tracker, ParticleSystem& particles,
              EffectsStats& stats, std::vector<EffectEvent>& events, float dt);

private:
    struct RuleContext;
    void UpdateContact(RuleContext& context, TrackedContact& tracked);
    void UpdateScrape(RuleContext& context, TrackedContact& tracked, const ContactSample& loudest,
                      float intensity, float impulseSum);
    void Impact(RuleContext& context, TrackedContact& tracked);
    static void FillContactFields(const RuleContext& context, const TrackedContact& tracked,
                                  EffectEvent& event);
    void SpawnParticles(RuleContext& context, const TrackedContact& tracked, const ContactSample& sample,
                        float intensity, int count);

    Random m_random;
    std::vector<ParticleTypeId> m_ruleTypes; // per rule: its particle type, resolved once by name
};

} // namespace cfx::detail
