// contactfx internal: from tracked contacts to particles, once per step.
//
// The unit of emission is the body pair (TrackedPair): all tracked contacts of one rule between the same
// two bodies, with all their manifold points, are one sliding contact. Cutting a ground into boxes, chain
// segments or more manifold points must not multiply the particles of one block sliding over it, so per
// pair and step:
//
//   samples  every sampled manifold point of every contact of the pair (only point 0 of each contact
//            with the `first` model); each gets the pair's whole normal force (every manifold point's
//            impulse over the step time) as its pressure, since splitting one load over more points or
//            sampling fewer of them must not change it;
//   intensity the normal-impulse-weighted mean of the samples' intensities (the plain mean when no point
//            pressed): where the pair presses, it rubs; the number of points does not change it;
//   count    rate = ratePerIntensity * (intensity - threshold), integrated with the fraction owed
//            carried in the pair, so it survives the contact moving from one segment to the next, and
//            capped by maxRate * dt plus what the pair saved of earlier steps' allowances, up to
//            kMaxRateWindow's worth (the cap holds over time, so a one-step pressure spike, or a pair
//            starting above its cap, gives the same count at any step rate);
//   where    the count is shared out over the samples by their normal impulse (systematic sampling:
//            one random offset, each sample gets the floor or the ceiling of its share), and each sample
//            with particles finds one start point outside every solid (spawn_point.h).
//
// The tutorial's `perStep` emission stays per contact by definition: one particle per sample per step,
// with the sample's own intensity, so it grows with the manifold points and segments as the tutorial's
// does. When no start point outside every solid exists near a sample (piles, crevices), its particles are
// not spawned and are counted as rejected.
//
// Events follow the pair too, but the emitter only measures: per pair it hands the event tracker
// (events.h) its fastest new touch, then whether it sleeps or its intensity and loudest point; the
// tracker decides impacts and scrapes and keeps their ids. An impact it accepts bursts particles here.
//
// Bounds: one Emit spawns at most the pool's capacity (more would only recycle each other; rates and
// bursts are clamped before any float becomes an int; what is owed beyond it is counted in
// EffectsStats::spawnOverCapacity), and a manifold point with non-finite inputs (a body
// with a NaN or infinite velocity, a NaN friction or impulse) is skipped and counted
// (EffectsStats::nonFiniteSamples): nothing non-finite reaches a particle, an intensity or an event.
//
// Determinism: one seeded generator drawn in a fixed order: rules, pairs in the order of their first
// contact in tracking order, samples, particles. Allocation: the scratch arrays only grow, so a warmed-up
// world emits without touching the heap.
#pragma once

#include "contact_tracker.h"
#include "contactfx/config.h"
#include "contactfx/intensity.h"
#include "contactfx/particle_system.h"
#include "contactfx/stats.h"
#include "events.h"
#include "random.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace cfx::detail
{

class Emitter
{
public:
    /// `config` must be valid (Validate) and is the one Emit will be given. `auditStarts`: check every
    /// start with DiscOverlapsSolid and count those inside in EffectsStats::spawnedInsideSolid (a world
    /// query per spawn: with ParticleSystemOptions::checkParticles only).
    Emitter(const EffectsConfig& config, std::uint64_t seed, bool auditStarts = false);

    /// For every body pair of every rule: emits into `particles`, reports to `events` (after its
    /// BeginStep for this step), updates `stats`. Without a world step since the last Emit (no
    /// PreSolve while a tracked contact has an awake body) only the step's statistics are reset.
    void Emit(b2World& world, const EffectsConfig& config, const ContactTracker& tracker,
              EventTracker& events, ParticleSystem& particles, EffectsStats& stats, float dt);
    /// The fraction of a particle the pair in `slot` owes (rate emission), in [0, 1).
    float EmissionCarry(std::uint32_t slot) const
    {
        return slot < m_rates.size() ? m_rates[slot].carry : 0.0f;
    }

private:
    struct RuleContext;

    static constexpr std::uint32_t kNone = 0xFFFFFFFFu; // no sample, no contact

    // One sampled manifold point of this step.
    struct Sample
    {
        ContactSample sample;       // normalForce: the pair's total
        std::uint32_t contact = 0;  // index in the rule's tracked contacts
        std::uint32_t next = kNone; // next sample of the same pair, kNone at the end
        float impulse = 0.0f;       // N*s, this point's normal impulse
        float ownIntensity = 0.0f;  // with the point's own normal force (perStep emission)
        float intensity = 0.0f;     // with the pair's normal force
    };

    // What rate emission keeps of one pair across steps; a new pair starts from the defaults.
    struct RateState
    {
        float carry = 0.0f;   // fraction of a particle owed, in [0, 1)
        float unsaved = 0.0f; // how far its maxRate savings are below the window's worth (0: full)
    };
    // A step's allowance (maxRate * dt) the pair leaves unused all goes into its savings.
    static void Save(RateState& state, float stepAllowance)
    {
        state.unsaved = std::max(state.unsaved - stepAllowance, 0.0f);
    }

    // What one pair gathered this step; valid while `stamp` is the step's.
    struct PairStep
    {
        std::uint64_t stamp = 0;
        std::uint32_t first = kNone; // first sample, kNone when none
        std::uint32_t last = kNone;
        std::uint32_t impactContact = kNone; // fastest finite new touch (TrackedContact), kNone: none
        float impactSpeed = 0.0f;
        float impulse = 0.0f;        // N*s, sum over every manifold point of the pair's contacts
        float sampledImpulse = 0.0f; // N*s, sum over the sampled points: the weights' total
        bool asleep = false;
    };

    void Gather(RuleContext& context, std::uint32_t contactIndex);
    void UpdatePair(RuleContext& context, std::uint32_t pairSlot);
    /// The whole particles of `owed` this Emit may still spawn (at most what is left of the pool's
    /// capacity); those beyond it are added to stats.spawnOverCapacity.
    int Budgeted(float owed, EffectsStats& stats) const;
    void EmitRate(RuleContext& context, std::uint32_t pairSlot, const PairStep& step, float intensity);
    void Burst(RuleContext& context, const TrackedContact& tracked);
    /// What particles are spawned for: a scrape (the rule's type) or an impact (its burst type; `intensity`
    /// is then the approach speed).
    enum class SpawnFor : std::uint8_t
    {
        scrape,
        impact
    };
    /// Spawns `count` particles at the sample.
    void SpawnParticles(RuleContext& context, const TrackedContact& tracked, const ContactSample& sample,
                        float intensity, int count, SpawnFor what);

    Random m_random;
    bool m_auditStarts;
    std::vector<ParticleTypeId> m_ruleTypes;  // per rule: its particle type, resolved once by name
    std::vector<ParticleTypeId> m_burstTypes; // per rule: the type its impacts burst
    std::uint64_t m_stamp = 0;                // one per rule per Emit
    std::vector<PairStep> m_pairSteps;        // by pair slot
    std::vector<RateState> m_rates;           // by pair slot
    std::vector<std::uint32_t> m_order;       // pair slots of the rule, in order of their first contact
    std::vector<Sample> m_samples;            // this rule's samples
    int m_spawnBudget = 0;                    // particles this Emit may still spawn (the pool's capacity)
};

} // namespace cfx::detail
