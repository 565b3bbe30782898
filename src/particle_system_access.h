// contactfx internal: what the rest of the library (Effects: deferred particle-body destruction, the
// spawn checks), its benchmarks and its tests may do with a ParticleSystem beyond its public API. Not
// installed.
#pragma once

#include "contactfx/particle_system.h"
#include "spawn_point.h"

namespace cfx::detail
{

struct ParticleSystemAccess
{
    /// A step without collision for pool particles: gravity, drag, motion and ageing over the same
    /// arrays. The reference that measures what collision costs (contactfx bench); effects never call it.
    static void IntegrateWithoutCollision(ParticleSystem& system, float dt, b2Vec2 gravity);
    /// From here until DestroyDeferredBodies, the bodies of the body-backed particles Spawn recycles are
    /// kept instead of destroyed (Effects reads the world's contacts meanwhile; destroying a body ends
    /// its contacts). DestroyDeferredBodies destroys them, in the order they were recycled.
    static void DeferBodyDestruction(ParticleSystem& system);
    /// The spawns until the next step are placed after the bodies moved (Effects emits after b2World::Step),
    /// without the moving bodies' poses being hashed to find out (ParticleSystem::Spawn).
    static void SpawnAfterWorldStep(ParticleSystem& system);
    static void DestroyDeferredBodies(ParticleSystem& system);
    /// Destroys the bodies of every body-backed particle now, as the destructor would: Effects' destructor
    /// does it first, while its destruction listener still forwards to the application's and the
    /// application may still call into it.
    static void DestroyAllBodies(ParticleSystem& system);
};

/// Ignores the bodies of a particle system's body-backed particles in spawn point tests.
class ParticleBodyFilter final : public BodyFilter
{
public:
    explicit ParticleBodyFilter(const ParticleSystem& system) : m_system(system) {}
    bool Ignore(const b2Body* body) const override { return m_system.IsParticleBody(body); }

private:
    const ParticleSystem& m_system;
};

} // namespace cfx::detail
