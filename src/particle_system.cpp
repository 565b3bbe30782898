#include "contactfx/particle_system.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <cmath>
#include <vector>

namespace cfx
{

namespace
{

// What the hot loop needs of a particle type, flat.
struct TypeParams
{
    float gravityScale;
    float drag;
    float restitution;
    float friction;
    float radius;
    float lifeRate; // life lost per second
    float density;
    std::uint16_t categoryBits;
    std::uint16_t maskBits;
    bool collide;
    bool bodyBacked;
};

// Below this approach speed (m/s) a hit does not bounce: particles come to rest instead of jittering.
constexpr float kRestSpeed = 0.5f;

} // namespace

struct ParticleSystem::Impl
{
    explicit Impl(b2World& w) : world(w) {}

    b2World& world;
    std::vector<TypeParams> types;
    bool anyBodyBacked = false;

    // Hot: touched by every step, one entry per slot.
    std::vector<float> positionX, positionY, velocityX, velocityY, life;
    std::vector<std::uint16_t> type;
    // Cold: bodies of body-backed particles (empty when no type is body-backed).
    std::vector<b2Body*> body;
    detail::PointerMap bodySet;
    std::uint32_t head = 0;

    void CopySlot(std::uint32_t from, std::uint32_t to)
    {
        positionX[to] = positionX[from];
        positionY[to] = positionY[from];
        velocityX[to] = velocityX[from];
        velocityY[to] = velocityY[from];
        life[to] = life[from];
        type[to] = type[from];
        if (anyBodyBacked)
        {
            body[to] = body[from];
        }
    }

    void ReleaseBody(std::uint32_t slot)
    {
        if (anyBodyBacked && body[slot] != nullptr)
        {
            bodySet.Erase(body[slot]);
            world.DestroyBody(body[slot]);
            body[slot] = nullptr;
        }
    }

    b2Body* CreateBody(const TypeParams& params, b2Vec2 position, b2Vec2 velocity)
    {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position = position;
        def.linearVelocity = velocity;
        def.fixedRotation = true;
        def.linearDamping = params.drag;
        def.gravityScale = params.gravityScale;
        b2Body* created = world.CreateBody(&def);
        b2CircleShape circle;
        circle.m_radius = params.radius;
        b2FixtureDef fixtureDef;
        fixtureDef.shape = &circle;
        fixtureDef.density = params.density;
        fixtureDef.friction = params.friction;
        fixtureDef.restitution = params.restitution;
        fixtureDef.filter.categoryBits = params.categoryBits;
        fixtureDef.filter.maskBits = params.collide ? params.maskBits : 0;
        created->CreateFixture(&fixtureDef);
        bodySet.Set(created, 1);
        return created;
    }

    void MovePoolParticle(const TypeParams& params, std::uint32_t slot, float dt, b2Vec2 gravity);
};

namespace
{

// Closest fixture a particle of a type may hit along a segment.
class SweepCallback final : public b2RayCastCallback
{
public:
    SweepCallback(const TypeParams& params, const detail::PointerMap& particleBodies)
        : m_params(params), m_particleBodies(particleBodies)
    {
    }

    float ReportFixture(b2Fixture* fixture, const b2Vec2& point, const b2Vec2& normal,
                        float fraction) override
    {
        const b2Filter& filter = fixture->GetFilterData();
        if (fixture->IsSensor() || (filter.maskBits & m_params.categoryBits) == 0 ||
            (filter.categoryBits & m_params.maskBits) == 0 ||
            m_particleBodies.Find(fixture->GetBody()) != nullptr)
        {
            return -1.0f;
        }
        hitFixture = fixture;
        hitPoint = point;
        hitNormal = normal;
        return fraction;
    }

    b2Fixture* hitFixture = nullptr;
    b2Vec2 hitPoint{0.0f, 0.0f};
    b2Vec2 hitNormal{0.0f, 0.0f};

private:
    const TypeParams& m_params;
    const detail::PointerMap& m_particleBodies;
};

} // namespace

void ParticleSystem::Impl::MovePoolParticle(const TypeParams& params, std::uint32_t slot, float dt,
                                            b2Vec2 gravity)
{
    b2Vec2 velocity(velocityX[slot], velocityY[slot]);
    velocity += (dt * params.gravityScale) * gravity;
    velocity *= 1.0f / (1.0f + dt * params.drag);
    b2Vec2 position(positionX[slot], positionY[slot]);
    b2Vec2 move = dt * velocity;
    float length = move.Length();
    if (params.collide && length > 0.0f)
    {
        b2Vec2 direction = (1.0f / length) * move;
        SweepCallback sweep(params, bodySet);
        world.RayCast(&sweep, position, position + move + params.radius * direction);
        if (sweep.hitFixture != nullptr)
        {
            b2Vec2 normal = sweep.hitNormal;
            b2Vec2 surfaceVelocity =
                sweep.hitFixture->GetBody()->GetLinearVelocityFromWorldPoint(sweep.hitPoint);
            b2Vec2 relative = velocity - surfaceVelocity;
            float approach = b2Dot(relative, normal);
            if (approach < 0.0f)
            {
                b2Vec2 tangential = relative - approach * normal;
                float bounce = -approach > kRestSpeed ? -params.restitution * approach : 0.0f;
                float normalChange = bounce - approach; // > 0
                float slide = tangential.Length();
                float slideAfter = std::max(0.0f, slide - params.friction * normalChange);
                b2Vec2 tangentialAfter =
                    slide > 0.0f ? (slideAfter / slide) * tangential : b2Vec2(0.0f, 0.0f);
                velocity = surfaceVelocity + tangentialAfter + bounce * normal;
            }
            position = sweep.hitPoint + params.radius * normal;
        }
        else
        {
            position += move;
        }
    }
    else
    {
        position += move;
    }
    positionX[slot] = position.x;
    positionY[slot] = position.y;
    velocityX[slot] = velocity.x;
    velocityY[slot] = velocity.y;
}

ParticleSystem::ParticleSystem(b2World& world, std::span<const ParticleTypeDef> types,
                               const ParticleBudget& budget)
    : m_impl(std::make_unique<Impl>(world)), m_capacity(budget.capacity)
{
    Impl& impl = *m_impl;
    for (const ParticleTypeDef& def : types)
    {
        TypeParams params{};
        params.gravityScale = def.gravityScale;
        params.drag = def.drag;
        params.restitution = def.restitution;
        params.friction = def.friction;
        params.radius = def.radius;
        params.lifeRate = 1.0f / def.lifetime;
        params.density = def.density;
        params.categoryBits = def.categoryBits;
        params.maskBits = def.maskBits;
        params.collide = def.collide;
        params.bodyBacked = def.backend == ParticleBackend::body;
        impl.anyBodyBacked = impl.anyBodyBacked || params.bodyBacked;
        impl.types.push_back(params);
    }
    impl.positionX.resize(m_capacity);
    impl.positionY.resize(m_capacity);
    impl.velocityX.resize(m_capacity);
    impl.velocityY.resize(m_capacity);
    impl.life.resize(m_capacity);
    impl.type.resize(m_capacity);
    if (impl.anyBodyBacked)
    {
        impl.body.assign(m_capacity, nullptr);
        impl.bodySet.Reserve(m_capacity);
    }
}

ParticleSystem::~ParticleSystem()
{
    for (std::uint32_t i = 0; i < m_count; ++i)
    {
        m_impl->ReleaseBody(View().Slot(i));
    }
}

void ParticleSystem::Spawn(const ParticleSpawn& spawn)
{
    if (!(spawn.life > 0.0f))
    {
        return;
    }
    Impl& impl = *m_impl;
    std::uint32_t slot;
    if (m_count < m_capacity)
    {
        slot = View().Slot(m_count);
        ++m_count;
    }
    else
    {
        // Full: the oldest particle (at the head of the ring) makes room, and the ring turns by one,
        // so the new particle is the newest in order.
        slot = impl.head;
        impl.ReleaseBody(slot);
        impl.head = impl.head + 1 == m_capacity ? 0 : impl.head + 1;
        ++m_recycled;
    }
    const TypeParams& params = impl.types[spawn.type.index];
    impl.positionX[slot] = spawn.position.x;
    impl.positionY[slot] = spawn.position.y;
    impl.velocityX[slot] = spawn.velocity.x;
    impl.velocityY[slot] = spawn.velocity.y;
    impl.life[slot] = std::min(spawn.life, 1.0f);
    impl.type[slot] = spawn.type.index;
    if (impl.anyBodyBacked)
    {
        impl.body[slot] =
            params.bodyBacked ? impl.CreateBody(params, spawn.position, spawn.velocity) : nullptr;
    }
}

void ParticleSystem::Step(float dt, b2Vec2 gravity)
{
    Impl& impl = *m_impl;
    ParticleView view = View();
    std::uint32_t kept = 0;
    for (std::uint32_t i = 0; i < m_count; ++i)
    {
        std::uint32_t slot = view.Slot(i);
        const TypeParams& params = impl.types[impl.type[slot]];
        if (params.bodyBacked)
        {
            const b2Body* body = impl.body[slot];
            impl.positionX[slot] = body->GetPosition().x;
            impl.positionY[slot] = body->GetPosition().y;
            impl.velocityX[slot] = body->GetLinearVelocity().x;
            impl.velocityY[slot] = body->GetLinearVelocity().y;
        }
        else
        {
            impl.MovePoolParticle(params, slot, dt, gravity);
        }
        impl.life[slot] -= dt * params.lifeRate;
        if (impl.life[slot] <= 0.0f)
        {
            impl.ReleaseBody(slot);
            continue;
        }
        std::uint32_t target = view.Slot(kept++);
        if (target != slot)
        {
            impl.CopySlot(slot, target);
        }
    }
    m_count = kept;
}

ParticleView ParticleSystem::View() const
{
    const Impl& impl = *m_impl;
    ParticleView view;
    view.positionX = impl.positionX.data();
    view.positionY = impl.positionY.data();
    view.velocityX = impl.velocityX.data();
    view.velocityY = impl.velocityY.data();
    view.life = impl.life.data();
    view.type = impl.type.data();
    view.head = impl.head;
    view.count = m_count;
    view.capacity = m_capacity;
    return view;
}

bool ParticleSystem::Ignore(const b2Body* body) const
{
    return m_impl->bodySet.Find(body) != nullptr;
}

} // namespace cfx
