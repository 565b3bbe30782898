// contactfx: the counters an Effects object keeps (Effects::Stats()).
//
// Plain data, updated at the end of each Effects::Step. Threading: read on the thread that steps.
#pragma once

#include <cstdint>
#include <vector>

namespace cfx
{

/// Counters of one rule.
struct RuleStats
{
    std::uint32_t contacts = 0;    ///< tracked contacts now
    std::uint32_t contactsMax = 0; ///< most tracked contacts at once
    std::uint64_t spawned = 0;     ///< particles emitted in all
    std::uint32_t spawnedLastStep = 0;
    /// The largest intensity in the last step: of a sample (perStep emission), or of a body pair's
    /// weighted mean of its samples (rate emission).
    float intensityMaxLastStep = 0.0f;
    /// m/s: the fastest approach of a new touch of the rule's pairs in the last step, whether or not it
    /// reached impactThreshold (0: no new touch). What the tuning plot sets impactThreshold against.
    float approachMaxLastStep = 0.0f;
    std::uint64_t impacts = 0;         ///< impact events (EffectEventType::impact) made in all
    std::uint32_t impactsLastStep = 0; ///< impact events made in the last step
    /// Particles of the rule (its scrapes and bursts) not spawned because no start outside every solid
    /// existed near their contact (EffectsStats::spawnRejected, which sums them).
    std::uint64_t spawnRejected = 0;
    float intensityMax = 0.0f; ///< the largest intensityMaxLastStep since creation
    float approachMax = 0.0f;  ///< m/s: the largest approachMaxLastStep since creation
};

/// Counters since creation.
struct EffectsStats
{
    std::uint64_t steps = 0;                  ///< Effects::Step calls that stepped (dt accepted)
    double time = 0.0;                        ///< s, sum of step times
    std::vector<std::uint64_t> spawnedByType; ///< per particle type
    std::vector<RuleStats> rules;             ///< per rule
    std::uint32_t live = 0;                   ///< particles live after the last step (pool and bodies)
    std::uint32_t liveMax = 0;                ///< the most live after any step
    /// With ParticleSystemOptions::checkParticles (EffectsDef::particles) only, else 0: particles whose
    /// start disc overlapped a solid fixture by Box2D's own b2TestOverlap, an audit independent of the
    /// placement's search (which never starts a particle inside; spawnRejected counts those it could not
    /// place). Costs a world query per spawn, so it is off by default.
    std::uint64_t spawnedInsideSolid = 0;
    std::uint64_t recycled = 0; ///< live particles replaced because the pool was full
    /// Pool particles squeezed by a moving body against other geometry with no free place: they died
    /// (ParticleCounters::crushed).
    std::uint64_t crushed = 0;
    /// Only with EffectsDef::particles.checkParticles (else 0): particle steps that ended with the centre
    /// inside a solid fixture, and particle steps whose path crossed a static edge or chain
    /// (ParticleCounters).
    std::uint64_t particleStepsInside = 0;
    std::uint64_t crossings = 0;
    /// Only with checkParticles (else 0): particle steps that went through a moving body
    /// (ParticleCounters::passedThroughMoving).
    std::uint64_t passedThroughMoving = 0;
    /// Particles not spawned because no start outside every solid existed near their contact (piles,
    /// crevices): a particle never starts inside.
    std::uint64_t spawnRejected = 0;
    /// Particles not spawned because a step's emission owed more than the pool's capacity (budget.capacity):
    /// one step spawns at most that many, as more would only recycle each other within the step.
    std::uint64_t spawnOverCapacity = 0;
    /// Particles that died, or were never stored, because their position or velocity was not finite or
    /// beyond 1e7 (m, m/s): thrown out of the world by absurd numbers (ParticleCounters::nonFinite).
    std::uint64_t nonFinite = 0;
    /// Body steps in which a body was left out of particle collision because its state, or its pose at
    /// the start of the step, was not finite or beyond 1e7 (ParticleCounters::skippedBodies).
    std::uint64_t skippedBodies = 0;
    /// Particle hit groups left out of a step's events because it had more than budget.particleHits
    /// (ParticleCounters::droppedHitGroups); the groups with the most hits were kept.
    std::uint64_t droppedHitGroups = 0;
    /// Times the particles' static geometry cache was built (docs/particles.md, Static geometry): once for
    /// a level that never changes, and once more after each change of its static fixtures.
    std::uint64_t staticGeometryBuilds = 0;
    /// Materials dropped because their fixture had been destroyed without Effects::ForgetFixture and a
    /// different fixture (another body, shape or geometry) took its address: it did not inherit them.
    /// Non-zero means a missing ForgetFixture call (docs/api.md).
    std::uint64_t staleMaterials = 0;
    /// Manifold points, impacts and particles skipped because something they are made of was not
    /// finite: a body with a NaN or infinite velocity or position, a NaN friction, an impulse beyond the
    /// float range, a start velocity that overflowed. Nothing non-finite reaches an intensity, a particle
    /// or an event.
    std::uint64_t nonFiniteSamples = 0;
};

} // namespace cfx
