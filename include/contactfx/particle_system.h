// contactfx: the particles.
//
// A pool of particles with a hard cap, in structure-of-arrays form: the arrays walked every step
// (position, velocity, life, type) apart from the rarely used (the Box2D body of body-backed particles).
// Live particles are kept in spawn order in a ring: a new particle goes after the newest, and when the
// pool is full it takes the oldest one's place, so "oldest first" recycling is O(1). Each step
// integrates gravity and drag, moves each pool particle along its path with a ray cast against the
// world's fixtures (bounce with restitution and friction, relative to moving bodies; one-sided edges and
// chains are only solid from their front), ages it and compacts the dead away, keeping the order.
// Particles never collide with each other. Body-backed particles are Box2D bodies created and destroyed
// here; their position and velocity are read back each step. No allocation after construction.
//
// Lifetime: the world must outlive the system. Threading: Step, Spawn and the destructor must not run
// while the world steps.
#pragma once

#include "contactfx/config.h"
#include "contactfx/materials.h"
#include "contactfx/spawn.h"

#include <box2d/b2_math.h>
#include <cstdint>
#include <memory>
#include <span>

class b2World;
class b2Body;

namespace cfx
{

/// A particle to add.
struct ParticleSpawn
{
    b2Vec2 position{0.0f, 0.0f}; ///< m, world
    b2Vec2 velocity{0.0f, 0.0f}; ///< m/s
    float life = 1.0f;           ///< (0, 1]; a particle with life <= 0 is not added
    ParticleTypeId type;         ///< must be valid
};

/// Read-only view of live particles, oldest first. Particle i (0 <= i < count) is at slot Slot(i) of
/// each array. Valid until the next Spawn or Step.
struct ParticleView
{
    const float* positionX = nullptr;
    const float* positionY = nullptr;
    const float* velocityX = nullptr;
    const float* velocityY = nullptr;
    const float* life = nullptr;
    const std::uint16_t* type = nullptr;
    std::uint32_t head = 0;
    std::uint32_t count = 0;
    std::uint32_t capacity = 0;

    std::uint32_t Slot(std::uint32_t i) const
    {
        std::uint32_t slot = head + i;
        return slot >= capacity ? slot - capacity : slot;
    }
};

class ParticleSystem final : public BodyFilter
{
public:
    /// `types` must be valid (see Validate); they are copied. Allocates every array once.
    ParticleSystem(b2World& world, std::span<const ParticleTypeDef> types, const ParticleBudget& budget);
    ~ParticleSystem() override;
    ParticleSystem(const ParticleSystem&) = delete;
    ParticleSystem& operator=(const ParticleSystem&) = delete;

    /// Adds a particle, recycling the oldest one when full.
    void Spawn(const ParticleSpawn& spawn);
    /// Advances every particle by `dt` seconds (> 0) under `gravity` (m/s^2).
    void Step(float dt, b2Vec2 gravity);

    ParticleView View() const;
    std::uint32_t Count() const { return m_count; }
    std::uint32_t Capacity() const { return m_capacity; }
    /// Particles that took the place of a live one because the pool was full.
    std::uint64_t Recycled() const { return m_recycled; }
    /// Body-backed particles' bodies are ignored by spawn point tests.
    bool Ignore(const b2Body* body) const override;

    struct Impl;

private:
    std::unique_ptr<Impl> m_impl;
    std::uint32_t m_count = 0;
    std::uint32_t m_capacity = 0;
    std::uint64_t m_recycled = 0;
};

} // namespace cfx
