// contactfx internal: the particle step loop (see motion.h).
//
// A pool particle's step: gravity and drag change its velocity; then up to two sweeps against the static
// geometry (the second continues with what is left of the step after a bounce, so particles slide
// instead of stopping at every touch of the ground); then one sweep against moving bodies in their own
// frames from where the particle was at the start of the step to where it is now. Most particles are far
// from all geometry, and the grids send those back after one box test.
#include "particles/motion.h"

#include <box2d/b2_body.h>
#include <cmath>

namespace cfx::particles
{

namespace
{

constexpr int kStaticSweeps = 2;

SurfaceResponse Mix(const ParticleSide& side, const SurfaceMaterial& material, b2Vec2 surfaceVelocity)
{
    SurfaceResponse response;
    response.velocity = surfaceVelocity;
    response.restitution = side.restitution > material.restitution ? side.restitution : material.restitution;
    response.friction = std::sqrt(side.friction * material.friction);
    response.restSpeed = side.restSpeed < material.restSpeed ? side.restSpeed : material.restSpeed;
    return response;
}

// Returns whether (position, velocity) came out of the static sweep unchanged from zero velocity.
bool Collide(const TypeStep& type, const WorldGeometry& geometry, float dt, bool resting, b2Vec2& position,
             b2Vec2& velocity)
{
    const b2Vec2 start = position;
    bool fixedPoint = false;
    if (resting)
    {
        velocity.SetZero();
        fixedPoint = true;
    }
    else if (geometry.HasStatic())
    {
        const bool fromRest =
            velocity == b2Vec2(type.gravityDelta.x * type.damping, type.gravityDelta.y * type.damping);
        float remaining = dt;
        for (int sweep = 0; sweep < kStaticSweeps; ++sweep)
        {
            const SweepInput in{position, remaining * velocity, type.side.radius};
            if (sweep > 0 && in.d.x == 0.0f && in.d.y == 0.0f)
            {
                break; // stopped by the first touch: nothing left to sweep
            }
            SweepResult hit;
            if (!geometry.SweepStatic(in, type.side, hit))
            {
                position += in.d;
                break;
            }
            position = hit.touch.position;
            velocity =
                Respond(velocity, hit.touch.normal, Mix(type.side, *hit.material, hit.surfaceVelocity));
            remaining *= 1.0f - hit.touch.t;
        }
        fixedPoint = fromRest && position == start && velocity.x == 0.0f && velocity.y == 0.0f;
    }
    else
    {
        position += dt * velocity;
    }
    if (geometry.HasMoving())
    {
        SweepResult hit;
        if (geometry.SweepMoving(start, position, type.side, hit))
        {
            position = hit.touch.position;
            velocity =
                Respond(velocity, hit.touch.normal, Mix(type.side, *hit.material, hit.surfaceVelocity));
            fixedPoint = false;
        }
    }
    return fixedPoint;
}

} // namespace

std::uint32_t AdvanceRange(const PoolArrays& pool, const TypeStep* types, const WorldGeometry* geometry,
                           float dt, bool trustResting, std::uint32_t begin, std::uint32_t end,
                           std::vector<b2Body*>& dead)
{
    std::uint32_t read = pool.Slot(begin);
    std::uint32_t write = read;
    std::uint32_t kept = 0;
    for (std::uint32_t i = begin; i < end; ++i)
    {
        const TypeStep& type = types[pool.type[read]];
        const float life = pool.life[read] - type.lifeLoss;
        b2Vec2 position(pool.positionX[read], pool.positionY[read]);
        b2Vec2 velocity(pool.velocityX[read], pool.velocityY[read]);
        std::uint8_t resting = 0;
        if (type.bodyBacked)
        {
            const b2Body* body = pool.body[read];
            position = body->GetPosition();
            velocity = body->GetLinearVelocity();
        }
        else
        {
            velocity.x = (velocity.x + type.gravityDelta.x) * type.damping;
            velocity.y = (velocity.y + type.gravityDelta.y) * type.damping;
            if (geometry != nullptr && type.collide)
            {
                resting =
                    Collide(type, *geometry, dt, trustResting && pool.resting[read] != 0, position, velocity)
                        ? 1
                        : 0;
            }
            else
            {
                position += dt * velocity;
            }
        }
        if (life > 0.0f)
        {
            pool.positionX[write] = position.x;
            pool.positionY[write] = position.y;
            pool.velocityX[write] = velocity.x;
            pool.velocityY[write] = velocity.y;
            pool.life[write] = life;
            pool.type[write] = pool.type[read];
            pool.resting[write] = resting;
            if (pool.body != nullptr)
            {
                pool.body[write] = pool.body[read];
            }
            write = write + 1 == pool.capacity ? 0 : write + 1;
            ++kept;
        }
        else if (type.bodyBacked)
        {
            dead.push_back(pool.body[read]);
        }
        read = read + 1 == pool.capacity ? 0 : read + 1;
    }
    return kept;
}

void MoveParticles(const PoolArrays& pool, std::uint32_t from, std::uint32_t to, std::uint32_t count)
{
    std::uint32_t read = pool.Slot(from);
    std::uint32_t write = pool.Slot(to);
    for (std::uint32_t i = 0; i < count; ++i)
    {
        pool.positionX[write] = pool.positionX[read];
        pool.positionY[write] = pool.positionY[read];
        pool.velocityX[write] = pool.velocityX[read];
        pool.velocityY[write] = pool.velocityY[read];
        pool.life[write] = pool.life[read];
        pool.type[write] = pool.type[read];
        pool.resting[write] = pool.resting[read];
        if (pool.body != nullptr)
        {
            pool.body[write] = pool.body[read];
        }
        write = write + 1 == pool.capacity ? 0 : write + 1;
        read = read + 1 == pool.capacity ? 0 : read + 1;
    }
}

} // namespace cfx::particles
