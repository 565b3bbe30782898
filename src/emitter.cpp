#include "emitter.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <cmath>

namespace cfx::detail
{

namespace
{

// The fixture particles start on: the one on a static or kinematic body, else the heavier body's.
bool SurfaceIsA(const b2Fixture* fixtureA, const b2Fixture* fixtureB)
{
    const b2Body* bodyA = fixtureA->GetBody();
    const b2Body* bodyB = fixtureB->GetBody();
    bool fixedA = bodyA->GetType() != b2_dynamicBody;
    bool fixedB = bodyB->GetType() != b2_dynamicBody;
    if (fixedA != fixedB)
    {
        return fixedA;
    }
    return bodyA->GetMass() >= bodyB->GetMass();
}

} // namespace

void Emitter::Emit(b2World& world, const EffectsConfig& config, ContactTracker& tracker,
                   ParticleSystem& particles, EffectsStats& stats, float dt)
{
    for (int ruleIndex = 0; ruleIndex < tracker.RuleCount(); ++ruleIndex)
    {
        const RuleId ruleId{static_cast<std::uint16_t>(ruleIndex)};
        const RuleDef& rule = config.rules[ruleIndex];
        const ParticleTypeId typeId = config.FindParticleType(rule.particleType);
        const ParticleTypeDef& type = config.particleTypes[typeId.index];
        RuleStats& ruleStats = stats.rules[ruleIndex];
        std::span<TrackedContact> contacts = tracker.Contacts(ruleId);
        ruleStats.contacts = static_cast<std::uint32_t>(contacts.size());
        ruleStats.contactsMax = std::max(ruleStats.contactsMax, ruleStats.contacts);
        ruleStats.spawnedLastStep = 0;
        ruleStats.intensityMaxLastStep = 0.0f;

        for (TrackedContact& tracked : contacts)
        {
            b2Contact* contact = tracked.contact;
            int pointCount = contact->GetManifold()->pointCount;
            if (pointCount < 1 || !contact->IsEnabled())
            {
                continue;
            }
            if (rule.intensity.points == ManifoldPoints::first)
            {
                pointCount = 1;
            }
            b2WorldManifold manifold;
            contact->GetWorldManifold(&manifold);
            const b2Fixture* fixtureA = contact->GetFixtureA();
            const b2Fixture* fixtureB = contact->GetFixtureB();
            const b2Body* bodyA = fixtureA->GetBody();
            const b2Body* bodyB = fixtureB->GetBody();
            const bool surfaceIsA = SurfaceIsA(fixtureA, fixtureB);

            for (int i = 0; i < pointCount; ++i)
            {
                ContactSample sample;
                sample.point = manifold.points[i];
                sample.normal = manifold.normal;
                sample.velocityA = bodyA->GetLinearVelocityFromWorldPoint(sample.point);
                sample.velocityB = bodyB->GetLinearVelocityFromWorldPoint(sample.point);
                sample.frictionA = fixtureA->GetFriction();
                sample.frictionB = fixtureB->GetFriction();
                sample.normalForce = tracked.normalImpulse[i] / dt;
                const float intensity = ComputeIntensity(sample, rule.intensity);
                ruleStats.intensityMaxLastStep = std::max(ruleStats.intensityMaxLastStep, intensity);
                if (!(intensity > rule.threshold))
                {
                    continue;
                }

                int count = 1;
                if (rule.emission == EmissionMode::rate)
                {
                    float rate = std::min(rule.maxRate, rule.ratePerIntensity * (intensity - rule.threshold));
                    float owed = tracked.emissionCarry[i] + rate * dt;
                    count = static_cast<int>(std::floor(owed));
                    tracked.emissionCarry[i] = owed - static_cast<float>(count);
                }
                if (count <= 0)
                {
                    continue;
                }

                // Seen from the surface: its normal points toward the other body; slip is the other
                // body's velocity over the surface, along it.
                const b2Vec2 surfaceNormal = surfaceIsA ? manifold.normal : -manifold.normal;
                b2Vec2 slip =
                    surfaceIsA ? sample.velocityB - sample.velocityA : sample.velocityA - sample.velocityB;
                slip -= b2Dot(slip, surfaceNormal) * surfaceNormal;

                SpawnPoint start;
                if (rule.placement == SpawnPlacement::tutorialDrop)
                {
                    start = TutorialDropPoint(world, sample.point);
                }
                else
                {
                    SpawnQuery query;
                    query.surface = surfaceIsA ? fixtureA : fixtureB;
                    query.surfaceChild = surfaceIsA ? contact->GetChildIndexA() : contact->GetChildIndexB();
                    query.point = sample.point;
                    query.normal = surfaceNormal;
                    query.slip = slip;
                    query.radius = type.radius;
                    start = FindSpawnPoint(world, query, &particles);
                }
                if (IsInsideSolid(world, start.position, &particles))
                {
                    stats.spawnedInsideSolid += static_cast<std::uint64_t>(count);
                }

                // The rule's materials name A and B; the contact's fixture order is Box2D's.
                const b2Vec2 ruleVelocityA = tracked.swapped ? sample.velocityB : sample.velocityA;
                const b2Vec2 ruleVelocityB = tracked.swapped ? sample.velocityA : sample.velocityB;
                const b2Vec2 baseVelocity = type.inheritA * ruleVelocityA + type.inheritB * ruleVelocityB +
                                            type.slipFactor * slip + type.normalSpeed * start.normal;
                const float life = std::clamp(type.lifeBase + type.lifeFromIntensity * intensity, 0.0f, 1.0f);
                for (int n = 0; n < count; ++n)
                {
                    ParticleSpawn spawn;
                    spawn.position = start.position;
                    spawn.velocity = baseVelocity;
                    spawn.velocity.x += m_random.Range(-type.spread, type.spread);
                    spawn.velocity.y += m_random.Range(-type.spread, type.spread);
                    spawn.life = life;
                    spawn.type = typeId;
                    particles.Spawn(spawn);
                }
                ruleStats.spawned += static_cast<std::uint64_t>(count);
                ruleStats.spawnedLastStep += static_cast<std::uint32_t>(count);
                stats.spawnedByType[typeId.index] += static_cast<std::uint64_t>(count);
            }
        }
    }
}

} // namespace cfx::detail
