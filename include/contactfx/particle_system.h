// contactfx: the particles.
//
// A pool of particles with a hard cap, in structure-of-arrays form. The arrays every step walks
// (position, velocity, life and clearance to the static geometry: 4-byte floats; type: a 2-byte index;
// 26 bytes a particle) are apart from the rarely used (the Box2D body of body-backed particles, only
// allocated when a type is body-backed).
// Colour and size are not stored: they are functions of life and type (LookAt). Live particles are kept
// in spawn order in a ring: a new particle goes after the newest, and when the pool is full the budget's
// policy picks the one that makes room: the oldest (O(1): the ring turns by one) or the one with the
// least time left to live (it takes that particle's place in the order).
//
// Each step integrates gravity and drag, then moves each pool particle along its path against the
// world's fixtures without creating bodies: a swept disc (nothing tunnels through static geometry, at
// any speed), bouncing with restitution and sliding with friction mixed from the particle type and the
// hit fixture as Box2D mixes them (max, sqrt of the product), relative to the surface's velocity. Static
// fixtures are cached in a grid that is rebuilt whenever the static geometry changes (see
// docs/particles.md for the contract); dynamic and kinematic bodies are met in their own frame, so a
// moving body carries or pushes particles away, never leaves one inside and never pushes one into or
// through static geometry: a particle with no free place is crushed (dies, and is counted). One-sided edges
// and chains are solid only from their front. Particles never collide with each other. Body-backed particles
// are Box2D bodies created and destroyed here (the tutorial's way, for particles that must push things);
// their position and velocity are read back each step. An application that destroys such a body itself
// tells the system with ForgetBody (Effects does it for its own system through its destruction
// listener): the particle goes, and the system never destroys that body again. Large pools are split across
// threads; the result does not depend on the number of threads, bit for bit. Each step also reports the pool
// particles that hit something, per particle type and body hit (Hits; docs/particles.md). No allocation per
// step once warmed up.
//
// Lifetime: the world must outlive the system. Threading: Step, Spawn and the destructor must not run
// while the world steps; the system's own helper threads only run inside Step.
#pragma once

#include "contactfx/config.h"
#include "contactfx/materials.h"

#include <box2d/b2_math.h>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

class b2World;
class b2Body;

namespace cfx
{

namespace detail
{
struct ParticleSystemAccess;
}

/// A particle to add.
struct ParticleSpawn
{
    b2Vec2 position{0.0f, 0.0f}; ///< m, world
    b2Vec2 velocity{0.0f, 0.0f}; ///< m/s
    float life = 1.0f;           ///< (0, 1]; a particle with life <= 0 is not added, one with NaN not
                                 ///< either (counted in ParticleCounters::nonFinite); above 1: 1
    ParticleTypeId type;         ///< one of the system's types (else Spawn throws)
};

/// Read-only view of live particles in spawn order, oldest first (under RecyclePolicy::lowestLife a
/// particle that recycled another takes its place in this order). Particle i (0 <= i < count) is at slot
/// Slot(i) of each array. Valid until the next Spawn or Step.
struct ParticleView
{
    const float* positionX = nullptr; ///< m, world, per slot
    const float* positionY = nullptr;
    const float* velocityX = nullptr; ///< m/s, world, per slot
    const float* velocityY = nullptr;
    /// Per slot, the part of its lifetime left, (0, 1]; 0 for a particle that died in the last step (a
    /// crushed one, or one thrown out of the world): the next Step or Spawn removes it, draw nothing for it.
    const float* life = nullptr;
    const std::uint16_t* type = nullptr; ///< per slot, the index of its particle type (ParticleTypeId)
    std::uint32_t head = 0;              ///< the slot of the oldest particle
    std::uint32_t count = 0;             ///< live particles, 0 .. capacity
    std::uint32_t capacity = 0;          ///< slots in each array

    std::uint32_t Slot(std::uint32_t i) const
    {
        std::uint32_t slot = head + i;
        return slot >= capacity ? slot - capacity : slot;
    }
};

/// The pool particles of one type that hit one body in one step (ParticleSystem::Hits): dirt pattering on
/// the ground, sparks ticking on steel. A particle's hit is its hardest touch of the step, counted when it
/// approached the surface at least at its type's hitSpeed.
struct ParticleHitGroup
{
    ParticleTypeId type;
    /// The body hit. Valid during the step that reported it; afterwards compare it, never dereference it
    /// (the application may have destroyed the body).
    const b2Body* body = nullptr;
    std::uint32_t count = 0;   ///< particles that hit it, >= 1
    float meanSpeed = 0.0f;    ///< m/s, mean approach speed of the hits
    b2Vec2 centre{0.0f, 0.0f}; ///< m, world: mean of the points where the particles touched the surface
};

/// How a particle system uses the machine.
struct ParticleSystemOptions
{
    /// Threads for one step, the caller's included; 0: one per hardware thread the process may run on (its
    /// CPU affinity: taskset, a container's cpuset). At most 8: more are taken as 8. The helper threads a
    /// full pool can use (capacity / minParticlesPerThread, at most threads - 1) are started with the
    /// system, so that no step ever starts one. A split pays only when the other cores are free: a server
    /// stepping several worlds at once, or several processes on one machine, should give 1 (measured: two
    /// processes that each split a 20,000-particle step took 0.91 ms a step against 0.31 ms with 1 thread
    /// each, on the project's 2-core machine). Fork no process while a system with helper threads
    /// exists: the child has no helpers, and its first split step waits for them forever.
    unsigned threads = 0;
    /// A step in which particles collide is split only when every thread gets at least this many
    /// particles (below that, waking a thread costs more than it saves). A step in which none collides
    /// costs about a sixth as much per particle and needs eight times as many (where a split of it was
    /// measured to pay). 0 is taken as 1.
    std::uint32_t minParticlesPerThread = 2048;
    /// Checks every pool particle after every step against the world's own fixtures (see
    /// ParticleCounters::stepsInside and ::crossings). Costs a world query per particle and step: for
    /// tests, benchmarks and debugging.
    bool checkParticles = false;
    /// Whether every step looks for changes of the static geometry (docs/particles.md, Static geometry):
    /// it hashes every fixture of every enabled static body, about 25 ns each (2.4 to 2.9 ms a step at
    /// 100,000 fixtures), and rebuilds the cache on any change. false: the cache is built once (at the first
    /// step that needs it, or BuildStaticGeometry()) and again only after InvalidateStaticGeometry() or a
    /// ShiftOrigin; static bodies then cost nothing per step (nor are they counted in
    /// ParticleCounters::skippedBodies). The application must then call InvalidateStaticGeometry() after
    /// every change of a static fixture or body (created, destroyed, moved, enabled, disabled, re-filtered,
    /// edited); until it does, pool particles meet the geometry as it was, and a hit on a destroyed fixture
    /// names its freed body. Effects says so itself for static fixtures destroyed through its destruction
    /// listener (b2World::DestroyBody) or after Effects::ForgetFixture.
    bool watchStaticGeometry = true;
};

/// What the system prevented or found, since creation.
struct ParticleCounters
{
    /// Pool particles a moving body squeezed against other geometry with no free place: they died
    /// (life 0 for the rest of that step) instead of being put inside or through something.
    std::uint64_t crushed = 0;
    /// With checkParticles: particle steps that ended with the particle's centre inside a solid circle
    /// or polygon fixture it collides with (static or moving).
    std::uint64_t stepsInside = 0;
    /// With checkParticles: particle steps whose centre's straight path crossed a static edge or chain it
    /// collides with (a two-sided edge from either side, a one-sided one from its front).
    std::uint64_t crossings = 0;
    /// With checkParticles: particle steps in which a particle went through a solid circle or polygon of a
    /// moving body it collides with, deeper than its radius, from outside to outside, as seen from the
    /// body (docs/particles.md, "Checking it").
    std::uint64_t passedThroughMoving = 0;
    /// Pool particles that died because their position or velocity was not finite, or beyond 1e7 (m,
    /// m/s): thrown out of the world by absurd numbers (a restitution of 1e30, a spawn at infinity); and
    /// spawns refused for such a position or velocity, or a life that is NaN.
    /// Nothing not finite reaches the collision or the draw data.
    std::uint64_t nonFinite = 0;
    /// Body steps in which a body was left out of particle collision because its position, rotation,
    /// centre or velocities were not finite, or beyond 1e7 (m, m/s, rad/s), or its pose at the start of the
    /// step (its centre less dt times its velocity, its angle less dt times its angular velocity) was: a
    /// step time too long for its speed (a body at 8 m/s with dt = 1e7 s).
    std::uint64_t skippedBodies = 0;
    /// Particle hit groups left out of Hits() because a step had more than ParticleBudget::particleHits.
    std::uint64_t droppedHitGroups = 0;
};

class ParticleSystem final
{
public:
    /// `types` and `budget` are checked by ValidateParticles (config.h): InputError listing every problem.
    /// They are copied. Allocates every array once.
    ParticleSystem(b2World& world, std::span<const ParticleTypeDef> types, const ParticleBudget& budget,
                   const ParticleSystemOptions& options = {});
    ~ParticleSystem();
    ParticleSystem(const ParticleSystem&) = delete;
    ParticleSystem& operator=(const ParticleSystem&) = delete;

    /// Adds a particle; when full, recycles one as budget.recycle says (the oldest, or the one with the
    /// least life left). Throws InputError (file "<api>", field "type")
    /// when spawn.type is not one of the system's types; nothing changes then.
    /// Spawn before or after b2World::Step, but keep one step's spawns on one side of it: at the next Step
    /// they are taken as placed after the bodies moved when no moving body (non-static, with a velocity,
    /// not a particle's own) moved since the first of them, else as there while the bodies moved, swept
    /// against their motion like any other particle. Told by a hash of the moving bodies' poses, taken at
    /// that first Spawn and again at the Step (O(bodies) each: 42 microseconds at 10,000 bodies).
    void Spawn(const ParticleSpawn& spawn);
    /// Advances every particle by `dt` seconds (> 0) under `gravity` (m/s^2). Throws InputError (file
    /// "<api>", field "dt" or "gravity") when dt is not finite and > 0 or gravity is not finite; nothing
    /// changes then.
    void Step(float dt, b2Vec2 gravity);
    /// The application destroyed (or is about to destroy) `body`, the Box2D body of one of this system's
    /// body-backed particles: the system forgets it at once and never destroys it; its particle leaves
    /// the pool at the next Spawn or Step. Call it from a b2DestructionListener's
    /// SayGoodbye(b2Fixture*) with fixture->GetBody(), or before b2World::DestroyBody. Any other body
    /// (or null): nothing happens. Effects calls it for its own system.
    void ForgetBody(const b2Body* body);
    /// Call right after b2World::ShiftOrigin(newOrigin), with the same vector (m): every pool particle
    /// moves by -newOrigin with the world (body-backed ones move with their bodies), and so do the
    /// centres of Hits(). The static geometry cache is built again at the next step, unless newOrigin is
    /// zero (then nothing changes). Throws InputError (file "<api>", field "newOrigin") when it is not
    /// finite; nothing changes then.
    void ShiftOrigin(b2Vec2 newOrigin);
    /// Removes every particle now (a level restarted in place), destroying the bodies of body-backed ones;
    /// Hits() is empty until the next step. Counters and the static cache stay. Returns false, changing
    /// nothing, when called inside b2World::Step (a contact listener: Box2D cannot destroy bodies then) or
    /// from a destruction listener while this system destroys a particle's body.
    bool Clear();
    /// Rebuilds the static geometry cache at the next step (or BuildStaticGeometry). Needed only with
    /// ParticleSystemOptions::watchStaticGeometry false; otherwise every change of the static geometry, a
    /// shape edited in place too, is detected.
    void InvalidateStaticGeometry();
    /// Builds the static geometry cache now if it is out of date (never built, changed when watched, or
    /// invalidated), instead of in the first step that needs it: call it after loading a level to take the
    /// build's cost there (about 0.6 microseconds a box fixture, 2.5 to 3 times that for a level's first
    /// build, which allocates: 60 and 155 ms for 100,000). Returns whether it built.
    /// Does nothing else: no particle moves.
    bool BuildStaticGeometry();

    ParticleView View() const;
    std::uint32_t Count() const { return m_count; }
    std::uint32_t Capacity() const { return m_capacity; }
    /// Particles that took the place of a live one because the pool was full.
    std::uint64_t Recycled() const { return m_recycled; }
    /// Crushed particles and, with ParticleSystemOptions::checkParticles, what the check found.
    const ParticleCounters& Counters() const { return m_counters; }
    /// Whether `body` is the Box2D body of one of this system's body-backed particles (spawn point
    /// tests and the static geometry cache ignore those; an application's own queries may too).
    bool IsParticleBody(const b2Body* body) const;

    /// The last Step's particle hits, one group per (particle type, body) in the order the groups first
    /// appear in spawn order (oldest particle first); at most ParticleBudget::particleHits, the groups with
    /// the most hits kept (ties: the first to appear). Only pool particles that collide hit; none when
    /// particleHits is 0. The same for any number of threads. Valid until the next Step.
    std::span<const ParticleHitGroup> Hits() const;

    /// Threads the last step used (1 when it was not split).
    unsigned ThreadsUsed() const { return m_threadsUsed; }
    /// Times the static geometry cache was built.
    std::uint64_t StaticGeometryBuilds() const;
    /// Heap bytes the system holds: per-particle arrays, geometry cache, scratch.
    std::size_t MemoryBytes() const;
    /// Heap bytes of the per-particle arrays for one slot.
    std::size_t BytesPerSlot() const;

private:
    friend struct detail::ParticleSystemAccess; // Effects, benchmarks, tests (src/particle_system_access.h)
    struct Impl;

    std::unique_ptr<Impl> m_impl;
    std::uint32_t m_count = 0;
    std::uint32_t m_capacity = 0;
    std::uint64_t m_recycled = 0;
    ParticleCounters m_counters;
    unsigned m_threadsUsed = 1;

    void Advance(float dt, b2Vec2 gravity, bool collide);
};

} // namespace cfx
