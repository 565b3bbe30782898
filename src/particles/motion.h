// contactfx internal: one step of a contiguous run of particles, the loop every step spends its time in.
//
// A run is a range of logical indices (spawn order) of the ring; each particle in it is advanced by
// itself, reading only its own slot, its type's step constants and the (read-only) world geometry, so
// runs can go to different threads and the result does not depend on how the particles were split.
// The living are written back in order at the start of the run (the dead are squeezed out as the loop
// goes, in the same pass), and the caller joins the runs.
#pragma once

#include "particles/world_geometry.h"

#include <cstdint>
#include <limits>
#include <vector>

class b2Body;

namespace cfx::particles
{

/// The clearance of a particle just spawned or that touched something: below zero, so that its next step
/// sweeps it, even if it does not move (it may have been spawned overlapping a shape).
inline constexpr float kUnknownClearance = -std::numeric_limits<float>::min();

/// The clearance of a particle spawned since the last step (kUnknownClearance otherwise): it was placed
/// where the moving bodies stand at the end of the world step, so its first step does not sweep their
/// motion of that step over it. Still below zero after a step's flight is taken off it.
inline constexpr float kSpawnedClearance = -std::numeric_limits<float>::max();

/// PoolArrays::stepFlags: the particle was just spawned and taken as placed after the bodies moved (the
/// moving bodies' motion was not swept against it: StepTrust::spawnsAfterMoving).
inline constexpr std::uint8_t kPlacedAfterFlag = 1;
/// PoolArrays::stepFlags: a moving body pushed it (from via; a resting particle's via is its start).
inline constexpr std::uint8_t kPushedFlag = 2;

/// The ring of particle arrays. Slot of logical index i: (head + i) mod capacity.
struct PoolArrays
{
    float* positionX;
    float* positionY;
    float* velocityX;
    float* velocityY;
    float* life;
    std::uint16_t* type;
    /// How far (m) the particle's centre can move before its disc can touch a static shape (a lower
    /// bound; +infinity when it never touches one). Negative: the particle is swept in the next step;
    /// kUnknownClearance when nothing is known (it even lists a particle that does not move),
    /// kSpawnedClearance (or a step's flight below it) when just spawned, -infinity
    /// when resting: (position, zero velocity) is a fixed point of the static sweep.
    float* clearance;
    b2Body** body; ///< null when no type is body-backed
    /// Where each particle was at the start of the last step (for the particle check); null unless
    /// checking. Moved with its particle like the other arrays.
    float* startX;
    float* startY;
    /// Where a moving body's push took each particle from in the last step (its position after the static
    /// sweeps), its start when nothing pushed it: the path was start -> via -> end, not a straight line.
    /// Null unless checking, with startX.
    float* viaX;
    float* viaY;
    /// Where along start -> via the push began (0..1; 1: at via, the flight's end; the touch's fraction
    /// when it began where the flight met the body). Null unless checking.
    float* pushFraction;
    /// What the check needs to know of each particle's last step: kPlacedAfterFlag, kPushedFlag. Null
    /// unless checking.
    std::uint8_t* stepFlags;
    std::uint32_t capacity;
    std::uint32_t head;

    std::uint32_t Slot(std::uint32_t i) const
    {
        const std::uint32_t slot = head + i;
        return slot >= capacity ? slot - capacity : slot;
    }
};

/// What a particle type does in this step (dt folded in).
struct TypeStep
{
    b2Vec2 gravityDelta; ///< velocity added by gravity this step (m/s)
    float damping;       ///< velocity factor of drag, 1 / (1 + dt * drag)
    b2Vec2 restVelocity; ///< what gravity and drag make of a zero velocity: (0 + gravityDelta) * damping
    float lifeLoss;      ///< life lost this step
    ParticleSide side;
    /// The least approach speed (m/s) of a touch recorded as a ParticleHit.
    float hitSpeed;
    bool bodyBacked;
    bool sweeps; ///< a pool particle that collides: moved through the geometry here
};

/// A pool particle's hardest touch of a step (static or moving), recorded when its approach speed reaches
/// its type's hitSpeed. 24 bytes.
struct ParticleHit
{
    const b2Body* body; ///< the body of the fixture it touched; valid during the step
    float speed;        ///< approach speed (m/s, > 0): -dot(velocity - surface velocity, normal) before it
    float x, y;         ///< where (m, world) the disc touched the surface
    std::uint16_t type; ///< the particle's type
};

/// Where a run records its hits: `hits[0, count)`, room for one per particle of the run (a particle has
/// at most one hit a step).
struct HitSink
{
    ParticleHit* hits;
    std::uint32_t count;
};

/// What the marks a step left still say in this step.
struct StepTrust
{
    /// dt, gravity and the static geometry are the same as in the previous step, so a particle marked
    /// resting would come out of the static sweep exactly as it went in, and the sweep is skipped (the
    /// result is the same bits either way).
    bool resting = false;
    /// The static geometry is the same as in the previous step, so the clearances hold.
    bool clearance = false;
    /// The particles spawned since the last step were placed where they are after the bodies moved (the
    /// usual order: b2World::Step, spawns, this step); else before (spawns, b2World::Step, this step), and
    /// the bodies' motion is swept against them like against any other particle.
    bool spawnsAfterMoving = true;
};

/// What a run of a step counts.
struct StepCounts
{
    std::uint64_t crushed = 0;   ///< particles squeezed by a moving body with no free place (they died)
    std::uint64_t nonFinite = 0; ///< particles whose position or velocity was not Sane (they died)
};

/// Advances logical indices [begin, end) by `dt` seconds; pool particles collide with `geometry` when
/// it is not null. A particle whose clearance covers its motion flies freely, which is the same bits as
/// sweeping it. Returns how many live; they are now at [begin, begin + kept) in order. Bodies of
/// body-backed particles that died are appended to `dead` (which must have room: no allocation) for the
/// caller to destroy on its thread. Adds what it counts to `counts`. With `hits` (not null), appends the
/// hits of the particles that collide, in particle order (null: nothing is recorded, at no cost).
std::uint32_t AdvanceRange(const PoolArrays& pool, const TypeStep* types, const WorldGeometry* geometry,
                           float dt, const StepTrust& trust, std::uint32_t begin, std::uint32_t end,
                           std::vector<b2Body*>& dead, StepCounts& counts, HitSink* hits);

/// Moves `count` particles from logical index `from` to `to` (to < from), keeping their order.
void MoveParticles(const PoolArrays& pool, std::uint32_t from, std::uint32_t to, std::uint32_t count);

} // namespace cfx::particles
