// Test support for particle tests: a particle type of radius 5 cm and a world with a particle system.
#pragma once

#include "test_world.h"

#include <memory>
#include <vector>

namespace cfx::test
{

inline constexpr float kDt = 1.0f / 60.0f;

inline ParticleTypeDef Ball(float restitution = 0.0f, float friction = 0.5f,
                            ParticleBackend backend = ParticleBackend::pool)
{
    ParticleTypeDef type;
    type.name = "ball";
    type.radius = 0.05f;
    type.restitution = restitution;
    type.friction = friction;
    type.lifetime = 100.0f;
    type.backend = backend;
    return type;
}

struct Pool : TestWorld
{
    explicit Pool(std::vector<ParticleTypeDef> particleTypes,
                  ParticleBudget budget = {64, RecyclePolicy::oldest}, ParticleSystemOptions options = {},
                  b2Vec2 gravity = b2Vec2(0.0f, -10.0f))
        : TestWorld(gravity), types(std::move(particleTypes))
    {
        system = std::make_unique<ParticleSystem>(*world, types, budget, options);
    }
    void Add(b2Vec2 position, b2Vec2 velocity = b2Vec2(0.0f, 0.0f), float life = 1.0f, std::uint16_t type = 0)
    {
        system->Spawn(ParticleSpawn{position, velocity, life, ParticleTypeId{type}});
    }
    void StepAll()
    {
        world->Step(kDt, 8, 3);
        system->Step(kDt, world->GetGravity());
    }
    b2Vec2 Position(std::uint32_t i) const
    {
        const ParticleView view = system->View();
        return b2Vec2(view.positionX[view.Slot(i)], view.positionY[view.Slot(i)]);
    }
    b2Vec2 Velocity(std::uint32_t i) const
    {
        const ParticleView view = system->View();
        return b2Vec2(view.velocityX[view.Slot(i)], view.velocityY[view.Slot(i)]);
    }
    float Life(std::uint32_t i) const { return system->View().life[system->View().Slot(i)]; }

    std::vector<ParticleTypeDef> types;
    std::unique_ptr<ParticleSystem> system; // destroyed before the world
};

} // namespace cfx::test
