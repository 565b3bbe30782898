#include "emitter.h"

#include "particle_system_access.h"

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

bool Asleep(const b2Body* body)
{
    return body->GetType() != b2_staticBody && !body->IsAwake();
}

// The sample of a contact at a world point, after the step.
ContactSample SampleAt(const b2Contact* contact, b2Vec2 point, b2Vec2 normal)
{
    ContactSample sample;
    sample.point = point;
    sample.normal = normal;
    sample.velocityA = contact->GetFixtureA()->GetBody()->GetLinearVelocityFromWorldPoint(point);
    sample.velocityB = contact->GetFixtureB()->GetBody()->GetLinearVelocityFromWorldPoint(point);
    sample.frictionA = contact->GetFixtureA()->GetFriction();
    sample.frictionB = contact->GetFixtureB()->GetFriction();
    return sample;
}

} // namespace

// Everything the per-contact work needs, for one rule.
struct Emitter::RuleContext
{
    b2World& world;
    ContactTracker& tracker;
    ParticleSystem& particles;
    ParticleBodyFilter particleBodies; // spawn point tests ignore body-backed particles' bodies
    EffectsStats& stats;
    std::vector<EffectEvent>& events;
    const RuleDef& rule;
    const ParticleTypeDef& type;
    ParticleTypeId typeId;
    RuleStats& ruleStats;
    float dt;
};

Emitter::Emitter(const EffectsConfig& config, std::uint64_t seed) : m_random(seed)
{
    for (const RuleDef& rule : config.rules)
    {
        m_ruleTypes.push_back(config.FindParticleType(rule.particleType));
    }
}

void Emitter::Emit(b2World& world, const EffectsConfig& config, ContactTracker& tracker,
                   ParticleSystem& particles, EffectsStats& stats, std::vector<EffectEvent>& events, float dt)
{
    for (int ruleIndex = 0; ruleIndex < tracker.RuleCount(); ++ruleIndex)
    {
        const RuleId ruleId{static_cast<std::uint16_t>(ruleIndex)};
        const RuleDef& rule = config.rules[ruleIndex];
        const ParticleTypeId typeId = m_ruleTypes[ruleIndex];
        RuleStats& ruleStats = stats.rules[ruleIndex];
        RuleContext context{
            world, tracker, particles, ParticleBodyFilter(particles), stats, events, rule,
            config.particleTypes[typeId.index], typeId, ruleStats, dt};
        std::span<TrackedContact> contacts = tracker.Contacts(ruleId);
        ruleStats.contacts = static_cast<std::uint32_t>(contacts.size());
        ruleStats.contactsMax = std::max(ruleStats.contactsMax, ruleStats.contacts);
        ruleStats.spawnedLastStep = 0;
        ruleStats.intensityMaxLastStep = 0.0f;
        for (TrackedContact& tracked : contacts)
        {
            UpdateContact(context, tracked);
        }
    }
}

void Emitter::UpdateContact(RuleContext& context, TrackedContact& tracked)
{
    const RuleDef& rule = context.rule;
    b2Contact* contact = tracked.contact;
    const b2Body* bodyA = contact->GetFixtureA()->GetBody();
    const b2Body* bodyB = contact->GetFixtureB()->GetBody();
    if (tracked.impactPending)
    {
        tracked.impactPending = false;
        if (tracked.approachSpeed >= rule.impactThreshold)
        {
            Impact(context, tracked);
        }
    }
    if (Asleep(bodyA) || Asleep(bodyB))
    {
        if (tracked.scrapeId != 0)
        {
            context.events.push_back(context.tracker.EndScrape(tracked, ScrapeEnd::asleep));
        }
        return;
    }

    // Every sampled manifold point emits on its own; the scrape follows the most intense one.
    int pointCount = contact->GetManifold()->pointCount;
    if (!contact->IsEnabled())
    {
        pointCount = 0;
    }
    if (rule.intensity.points == ManifoldPoints::first)
    {
        pointCount = std::min(pointCount, 1);
    }
    b2WorldManifold manifold;
    if (pointCount > 0)
    {
        contact->GetWorldManifold(&manifold);
    }
    ContactSample loudest;
    float loudestIntensity = -1.0f;
    float impulseSum = 0.0f;
    for (int i = 0; i < pointCount; ++i)
    {
        ContactSample sample = SampleAt(contact, manifold.points[i], manifold.normal);
        sample.normalForce = tracked.normalImpulse[i] / context.dt;
        impulseSum += tracked.normalImpulse[i];
        const float intensity = ComputeIntensity(sample, rule.intensity);
        context.ruleStats.intensityMaxLastStep = std::max(context.ruleStats.intensityMaxLastStep, intensity);
        if (intensity > loudestIntensity)
        {
            loudestIntensity = intensity;
            loudest = sample;
        }
        if (!(intensity > rule.threshold))
        {
            continue;
        }
        int count = 1;
        if (rule.emission == EmissionMode::rate)
        {
            const float rate = std::min(rule.maxRate, rule.ratePerIntensity * (intensity - rule.threshold));
            const float owed = tracked.emissionCarry[i] + rate * context.dt;
            count = static_cast<int>(std::floor(owed));
            tracked.emissionCarry[i] = owed - static_cast<float>(count);
        }
        SpawnParticles(context, tracked, sample, intensity, count);
    }
    UpdateScrape(context, tracked, loudest, std::max(loudestIntensity, 0.0f), impulseSum);
}

void Emitter::UpdateScrape(RuleContext& context, TrackedContact& tracked, const ContactSample& loudest,
                           float intensity, float impulseSum)
{
    EffectEvent event;
    if (intensity > context.rule.threshold)
    {
        tracked.quietTime = 0.0f;
        if (tracked.scrapeId == 0)
        {
            tracked.scrapeId = context.tracker.NewEventId();
            event.type = EffectEventType::scrapeBegan;
        }
        else
        {
            event.type = EffectEventType::scrapeChanged;
        }
    }
    else if (tracked.scrapeId != 0)
    {
        tracked.quietTime += context.dt;
        if (tracked.quietTime >= context.rule.scrapeEndDelay)
        {
            context.events.push_back(context.tracker.EndScrape(tracked, ScrapeEnd::belowThreshold));
            return;
        }
        event.type = EffectEventType::scrapeChanged;
    }
    else
    {
        return;
    }
    FillContactFields(context, tracked, event);
    event.id = tracked.scrapeId;
    event.point = loudest.point;
    event.normal = tracked.swapped ? -loudest.normal : loudest.normal;
    event.intensity = intensity;
    event.tangentialSpeed = TangentialVelocity(loudest).Length();
    event.normalImpulse = impulseSum;
    tracked.scrapePoint = event.point;
    tracked.scrapeNormal = event.normal;
    context.events.push_back(event);
}

void Emitter::Impact(RuleContext& context, TrackedContact& tracked)
{
    EffectEvent event;
    event.type = EffectEventType::impact;
    FillContactFields(context, tracked, event);
    event.id = context.tracker.NewEventId();
    event.point = tracked.approachPoint;
    event.normal = tracked.swapped ? -tracked.approachNormal : tracked.approachNormal;
    event.approachSpeed = tracked.approachSpeed;
    event.normalImpulse = tracked.normalImpulse[0] + tracked.normalImpulse[1];
    context.events.push_back(event);

    const float burst =
        std::min(context.rule.burstMax,
                 context.rule.burstPerSpeed * (tracked.approachSpeed - context.rule.impactThreshold));
    const int count = static_cast<int>(std::floor(burst));
    if (count > 0)
    {
        const ContactSample sample = SampleAt(tracked.contact, tracked.approachPoint, tracked.approachNormal);
        SpawnParticles(context, tracked, sample, tracked.approachSpeed, count);
    }
}

void Emitter::FillContactFields(const RuleContext& context, const TrackedContact& tracked, EffectEvent& event)
{
    event.rule = tracked.rule;
    event.fixtureA = context.tracker.RuleFixtureA(tracked);
    event.fixtureB = context.tracker.RuleFixtureB(tracked);
    event.materialA = context.tracker.Materials().Get(event.fixtureA);
    event.materialB = context.tracker.Materials().Get(event.fixtureB);
    event.step = context.tracker.Step();
}

void Emitter::SpawnParticles(RuleContext& context, const TrackedContact& tracked, const ContactSample& sample,
                             float intensity, int count)
{
    if (count <= 0)
    {
        return;
    }
    const RuleDef& rule = context.rule;
    const ParticleTypeDef& type = context.type;
    const b2Contact* contact = tracked.contact;
    const b2Fixture* fixtureA = contact->GetFixtureA();
    const b2Fixture* fixtureB = contact->GetFixtureB();
    const bool surfaceIsA = SurfaceIsA(fixtureA, fixtureB);

    // Seen from the surface: its normal points toward the other body; slip is the other body's
    // velocity over the surface, along it.
    const b2Vec2 surfaceNormal = surfaceIsA ? sample.normal : -sample.normal;
    b2Vec2 slip = surfaceIsA ? sample.velocityB - sample.velocityA : sample.velocityA - sample.velocityB;
    slip -= b2Dot(slip, surfaceNormal) * surfaceNormal;

    SpawnPoint start;
    if (rule.placement == SpawnPlacement::tutorialDrop)
    {
        start = TutorialDropPoint(context.world, sample.point);
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
        start = FindSpawnPoint(context.world, query, &context.particleBodies);
    }
    if (IsInsideSolid(context.world, start.position, &context.particleBodies))
    {
        context.stats.spawnedInsideSolid += static_cast<std::uint64_t>(count);
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
        spawn.type = context.typeId;
        context.particles.Spawn(spawn);
    }
    context.ruleStats.spawned += static_cast<std::uint64_t>(count);
    context.ruleStats.spawnedLastStep += static_cast<std::uint32_t>(count);
    context.stats.spawnedByType[context.typeId.index] += static_cast<std::uint64_t>(count);
}

} // namespace cfx::detail
