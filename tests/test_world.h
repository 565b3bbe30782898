// Test support: a small physics fixture (Jolt's habit) and a listener that records callbacks.
#pragma once

#include "contactfx/effects.h"
#include "contactfx/presets.h"

#include <box2d/box2d.h>
#include <memory>
#include <string>
#include <vector>

namespace cfx::test
{

/// A world with gravity (0, -10) and a wide static concrete-or-whatever ground box whose top is y = 0.
struct TestWorld
{
    explicit TestWorld(b2Vec2 gravity = b2Vec2(0.0f, -10.0f)) : world(std::make_unique<b2World>(gravity)) {}

    b2Body* CreateGround(float friction = 0.8f, float halfWidth = 50.0f)
    {
        b2BodyDef def;
        b2Body* body = world->CreateBody(&def);
        b2PolygonShape box;
        box.SetAsBox(halfWidth, 1.0f, b2Vec2(0.0f, -1.0f), 0.0f);
        b2FixtureDef fixture;
        fixture.shape = &box;
        fixture.friction = friction;
        body->CreateFixture(&fixture);
        return body;
    }

    b2Body* CreateBox(b2Vec2 position, float halfWidth, float halfHeight, float friction,
                      b2BodyType type = b2_dynamicBody)
    {
        b2BodyDef def;
        def.type = type;
        def.position = position;
        b2Body* body = world->CreateBody(&def);
        b2PolygonShape box;
        box.SetAsBox(halfWidth, halfHeight);
        b2FixtureDef fixture;
        fixture.shape = &box;
        fixture.density = 1.0f;
        fixture.friction = friction;
        body->CreateFixture(&fixture);
        return body;
    }

    b2Body* CreateCircle(b2Vec2 position, float radius, float friction, b2BodyType type = b2_dynamicBody)
    {
        b2BodyDef def;
        def.type = type;
        def.position = position;
        b2Body* body = world->CreateBody(&def);
        b2CircleShape circle;
        circle.m_radius = radius;
        b2FixtureDef fixture;
        fixture.shape = &circle;
        fixture.density = 1.0f;
        fixture.friction = friction;
        body->CreateFixture(&fixture);
        return body;
    }

    void Step(float dt = 1.0f / 60.0f)
    {
        world->Step(dt, 8, 3);
        if (effects)
        {
            effects->Step(dt);
        }
    }

    /// The effects' particle system options Attach uses: tests that expect spawnedInsideSolid or the
    /// particle check's counters to be 0 turn checkParticles on, or those counters are not counted.
    ParticleSystemOptions particles{};

    /// Creates the effects object with `config` (default preset when omitted).
    Effects& Attach(EffectsConfig config = DefaultPreset(), std::uint64_t seed = 1,
                    b2ContactListener* listener = nullptr)
    {
        EffectsDef def;
        def.config = std::move(config);
        def.seed = seed;
        def.contactListener = listener;
        def.particles = particles;
        effects = std::make_unique<Effects>(*world, def);
        return *effects;
    }

    /// Attach(config), then steel on `box` and concrete on `ground`: the scene of most emission tests.
    Effects& AttachSteelOnConcrete(EffectsConfig config, b2Body* ground, b2Body* box,
                                   b2ContactListener* listener = nullptr)
    {
        Effects& fx = Attach(std::move(config), 1, listener);
        fx.SetMaterial(ground, fx.FindMaterial("concrete"));
        fx.SetMaterial(box, fx.FindMaterial("steel"));
        return fx;
    }

    /// `config`'s sparks made to keep their start: no spread, normal speed, gravity or drag, no collision.
    static ParticleTypeDef& StillSparks(EffectsConfig& config)
    {
        ParticleTypeDef& sparks = config.particleTypes[config.FindParticleType("sparks").index];
        sparks.spread = sparks.normalSpeed = sparks.gravityScale = sparks.drag = 0.0f;
        sparks.collide = false;
        return sparks;
    }

    MaterialId Material(const char* name) const { return effects->FindMaterial(name); }

    std::uint64_t Spawned(const char* type) const
    {
        return effects->Stats().spawnedByType[effects->Config().FindParticleType(type).index];
    }

    std::unique_ptr<b2World> world;
    std::unique_ptr<Effects> effects; // declared after the world: destroyed first
};

/// Records every contact callback, in order, as text ("begin", "end", "pre", "post").
class RecordingListener final : public b2ContactListener
{
public:
    void BeginContact(b2Contact*) override { calls.push_back("begin"); }
    void EndContact(b2Contact*) override { calls.push_back("end"); }
    void PreSolve(b2Contact*, const b2Manifold*) override { calls.push_back("pre"); }
    void PostSolve(b2Contact*, const b2ContactImpulse*) override { calls.push_back("post"); }

    std::vector<std::string> calls;
};

/// A config with one rule between `a` and `b` emitting "sparks", all else from the default preset.
inline EffectsConfig OneRule(const char* a, const char* b, const char* particle = "sparks")
{
    EffectsConfig config = DefaultPreset();
    config.rules.clear();
    RuleDef rule = DefaultPreset().rules[0];
    rule.materialA = a;
    rule.materialB = b;
    rule.particleType = particle;
    config.rules.push_back(rule);
    return config;
}

} // namespace cfx::test
