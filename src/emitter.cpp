#include "emitter.h"

#include "body_box.h"
#include "particle_system_access.h"

#include <algorithm>
#include <bit>
#include <box2d/b2_body.h>
#include <box2d/b2_circle_shape.h>
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

// The velocity of the other fixture's footprint on the surface (m/s, world): how its contact moves. A
// circle rolls, so its footprint stays under its centre whatever its spin; anything else drags its
// footprint along with the material at the contact point (`velocityAtPoint`).
b2Vec2 FootprintVelocity(const b2Fixture& other, b2Vec2 velocityAtPoint)
{
    const b2Shape& shape = *other.GetShape();
    if (shape.GetType() != b2Shape::e_circle)
    {
        return velocityAtPoint;
    }
    const b2Body& body = *other.GetBody();
    const b2Vec2 centre = b2Mul(body.GetTransform(), static_cast<const b2CircleShape&>(shape).m_p);
    return body.GetLinearVelocityFromWorldPoint(centre);
}

// How far along the surface a start is looked for, each way (m): a metre, or the larger side of the other
// body's box (all its fixtures) and a tenth of a metre when that is more. From one end of a body's footprint
// the side the particles leave to may be the body's whole length away (a block sliding on its front corner
// leaves its sparks behind its rear one), whatever fixtures it is made of, and the gap between a large convex
// body and the surface opens slowly (a 7.7 m wheel lifts by a dirt particle's 0.1 m only 1.2 m from its
// contact): its dirt starts at its rim instead of being rejected. Costs a box per child of the body (a
// dynamic body of many children is rare: grounds are the surface, not the other body).
float SearchDistance(const b2Body& other)
{
    constexpr float kLeast = 1.0f;
    constexpr float kBeyond = 0.1f;
    const b2AABB box = detail::BodyBox(other);
    const b2Vec2 extent = box.upperBound - box.lowerBound;
    const float across = std::max(extent.x, extent.y) + kBeyond;
    return std::isfinite(across) ? std::max(kLeast, across) : kLeast;
}

// A particle count from a float that may be absurd (a huge rate), infinite or NaN: clamped to [0, limit]
// (NaN to 0) before it is converted, since converting a float outside int's range is undefined.
int ClampedCount(float value, int limit)
{
    if (!(value >= 1.0f))
    {
        return 0;
    }
    if (value >= static_cast<float>(limit))
    {
        return limit;
    }
    return std::min(limit, static_cast<int>(value)); // value < limit <= 2^31: in range
}

bool Finite(b2Vec2 v)
{
    return std::isfinite(v.x) && std::isfinite(v.y);
}

// Whether every input of a sample is finite (a body given a NaN or infinite velocity, a NaN friction).
bool Finite(const ContactSample& sample)
{
    return Finite(sample.point) && Finite(sample.normal) && Finite(sample.velocityA) &&
           Finite(sample.velocityB) && std::isfinite(sample.frictionA) && std::isfinite(sample.frictionB) &&
           std::isfinite(sample.contactFriction) && std::isfinite(sample.normalForce);
}

bool Asleep(const b2Body* body)
{
    return body->GetType() != b2_staticBody && !body->IsAwake();
}

// m/s: a particle's motion along the surface, relative to the other body's footprint, slower than this
// tells no side to start on (SpawnQuery::leaving).
constexpr float kLeavingSpeed = 0.05f;
// An impact whose point slides along the surface slower than this share of its approach speed is a hit
// more than a slide: its burst starts outward from under the other body, beside the point that struck (a
// tilted slab slamming down creeps 0.24 m/s along the ground at 6.6 m/s: its burst walked the slab's whole
// length, under it, to start 4 m from the corner that struck). A faster slide's burst starts where the
// slide's own particles do.
constexpr float kHitSlideShare = 0.5f;
// m: a contact point nearer than this to under the other body's centre (a circle's) tells no side.
constexpr float kOffMiddle = 0.01f;

// The sample of a tracked contact at a world point, after the step, as Box2D solved it: with the contact's
// own friction when it is not the fixtures' mix (the application set it with b2Contact::SetFriction, at any
// time, or changed a fixture's friction without ResetFriction: either way it is what the solver uses), and
// with its tangent speed (a conveyor belt: b2Contact::SetTangentSpeed, which the solver takes as a slip of B
// over A) as a motion of the surface fixture's surface (SurfaceIsA) along the tangent: the belt moves,
// whether it is fixture A or B.
ContactSample SampleAt(const TrackedContact& tracked, b2Vec2 point, b2Vec2 normal)
{
    const b2Contact* contact = tracked.contact;
    const b2Fixture* fixtureA = contact->GetFixtureA();
    const b2Fixture* fixtureB = contact->GetFixtureB();
    ContactSample sample;
    sample.point = point;
    sample.normal = normal;
    sample.velocityA = fixtureA->GetBody()->GetLinearVelocityFromWorldPoint(point);
    sample.velocityB = fixtureB->GetBody()->GetLinearVelocityFromWorldPoint(point);
    const b2Vec2 belt =
        contact->GetTangentSpeed() * b2Cross(normal, 1.0f); // B over A, as the solver drives it
    if (SurfaceIsA(fixtureA, fixtureB))
    {
        sample.velocityA += belt;
    }
    else
    {
        sample.velocityB -= belt;
    }
    sample.frictionA = fixtureA->GetFriction();
    sample.frictionB = fixtureB->GetFriction();
    // Bit for bit: Box2D sets a contact's friction to this mix when it makes the contact and on
    // ResetFriction; a friction set to NaN differs too (its samples are then skipped as non-finite).
    const float mixed = b2MixFriction(sample.frictionA, sample.frictionB);
    const float friction = contact->GetFriction();
    sample.contactFriction =
        std::bit_cast<std::uint32_t>(friction) != std::bit_cast<std::uint32_t>(mixed) ? friction : -1.0f;
    return sample;
}

} // namespace

// Everything the per-pair work needs, for one rule.
struct Emitter::RuleContext
{
    b2World& world;
    const ContactTracker& tracker;
    EventTracker& events;
    ParticleSystem& particles;
    ParticleBodyFilter particleBodies; // spawn point tests ignore body-backed particles' bodies
    EffectsStats& stats;
    const RuleDef& rule;
    std::span<const ParticleTypeDef> types; // the config's, by ParticleTypeId
    ParticleTypeId typeId;                  // what the rule's scrapes emit
    ParticleTypeId burstTypeId;             // what its impacts burst: burstParticleType, else typeId
    RuleStats& ruleStats;
    std::span<const TrackedContact> contacts;
    float dt;
};

Emitter::Emitter(const EffectsConfig& config, std::uint64_t seed, bool auditStarts)
    : m_random(seed), m_auditStarts(auditStarts)
{
    for (const RuleDef& rule : config.rules)
    {
        const ParticleTypeId type = config.FindParticleType(rule.particleType);
        m_ruleTypes.push_back(type);
        m_burstTypes.push_back(
            rule.burstParticleType.empty() ? type : config.FindParticleType(rule.burstParticleType));
    }
    // Room for the configured number of touching contacts (budget.contacts for each rule), each a pair of
    // its own with both manifold points at most.
    m_pairSteps.reserve(config.ContactRoom());
    m_rates.reserve(config.ContactRoom());
    m_order.reserve(config.ContactRoom());
    m_samples.reserve(std::size_t{2} * config.ContactRoom());
}

void Emitter::Emit(b2World& world, const EffectsConfig& config, const ContactTracker& tracker,
                   EventTracker& events, ParticleSystem& particles, EffectsStats& stats, float dt)
{
    if (m_pairSteps.size() < tracker.PairSlots())
    {
        m_pairSteps.resize(tracker.PairSlots());
        m_rates.resize(tracker.PairSlots());
    }
    // A slot whose pair ended owes nothing to the next pair that takes it, and its savings are full.
    for (const EndedPair& ended : tracker.EndedPairs())
    {
        m_rates[ended.slot] = RateState{};
    }
    // Box2D calls PreSolve for every touching contact with an awake body in every world step: none since
    // the last step while a tracked contact has an awake body means the world did not step (a paused
    // game). Emitting from the contacts as the last world step left them would spray from a frozen
    // scrape: emission and scrapes wait for the world. (A body put to sleep between steps has no PreSolve
    // either, and its scrape ends as asleep.)
    const bool paused = !tracker.Solved() && tracker.AnyAwake();
    // More particles than the pool holds in one step would only recycle each other.
    m_spawnBudget = static_cast<int>(std::min<std::uint32_t>(particles.Capacity(), 0x7FFFFFFFu));
    for (int ruleIndex = 0; ruleIndex < tracker.RuleCount(); ++ruleIndex)
    {
        const RuleId ruleId{static_cast<std::uint16_t>(ruleIndex)};
        const RuleDef& rule = config.rules[ruleIndex];
        RuleStats& ruleStats = stats.rules[ruleIndex];
        std::span<const TrackedContact> contacts = tracker.Contacts(ruleId);
        RuleContext context{world,
                            tracker,
                            events,
                            particles,
                            ParticleBodyFilter(particles),
                            stats,
                            rule,
                            config.particleTypes,
                            m_ruleTypes[ruleIndex],
                            m_burstTypes[ruleIndex],
                            ruleStats,
                            contacts,
                            dt};
        ruleStats.contacts = static_cast<std::uint32_t>(contacts.size());
        ruleStats.contactsMax = std::max(ruleStats.contactsMax, ruleStats.contacts);
        ruleStats.spawnedLastStep = 0;
        ruleStats.intensityMaxLastStep = 0.0f;
        ruleStats.approachMaxLastStep = 0.0f;
        ruleStats.impactsLastStep = 0;
        if (paused)
        {
            continue;
        }

        // Gather the samples of every pair (in the order of each pair's first contact), then emit pair by
        // pair.
        ++m_stamp;
        m_order.clear();
        m_samples.clear();
        for (std::uint32_t i = 0; i < contacts.size(); ++i)
        {
            Gather(context, i);
        }
        for (std::uint32_t slot : m_order)
        {
            UpdatePair(context, slot);
        }
        ruleStats.intensityMax = std::max(ruleStats.intensityMax, ruleStats.intensityMaxLastStep);
        ruleStats.approachMax = std::max(ruleStats.approachMax, ruleStats.approachMaxLastStep);
    }
}

void Emitter::Gather(RuleContext& context, std::uint32_t contactIndex)
{
    const RuleDef& rule = context.rule;
    const TrackedContact& tracked = context.contacts[contactIndex];
    PairStep& step = m_pairSteps[tracked.pair];
    if (step.stamp != m_stamp)
    {
        step = PairStep{};
        step.stamp = m_stamp;
        m_order.push_back(tracked.pair);
    }
    if (tracked.newTouch)
    {
        if (!std::isfinite(tracked.approachSpeed) || !Finite(tracked.approachPoint) ||
            !Finite(tracked.approachNormal))
        {
            context.stats.nonFiniteSamples += 1; // no impact from a body with non-finite state
        }
        else if (step.impactContact == kNone || tracked.approachSpeed > step.impactSpeed)
        {
            step.impactContact = contactIndex;
            step.impactSpeed = tracked.approachSpeed;
        }
    }
    b2Contact* contact = tracked.contact;
    if (Asleep(contact->GetFixtureA()->GetBody()) || Asleep(contact->GetFixtureB()->GetBody()))
    {
        step.asleep = true;
        return;
    }
    int pointCount = contact->IsEnabled() ? contact->GetManifold()->pointCount : 0;
    for (int i = 0; i < pointCount; ++i)
    {
        // The pressure counts every point, sampled or not (a non-finite impulse: none; its sample goes).
        step.impulse += std::isfinite(tracked.normalImpulse[i]) ? tracked.normalImpulse[i] : 0.0f;
    }
    if (rule.intensity.points == ManifoldPoints::first)
    {
        pointCount = std::min(pointCount, 1);
    }
    if (pointCount <= 0)
    {
        return;
    }
    b2WorldManifold manifold;
    contact->GetWorldManifold(&manifold);
    for (int i = 0; i < pointCount; ++i)
    {
        Sample sample;
        sample.sample = SampleAt(tracked, manifold.points[i], manifold.normal);
        sample.sample.normalForce = tracked.normalImpulse[i] / context.dt;
        sample.ownIntensity = ComputeIntensity(sample.sample, rule.intensity);
        if (!Finite(sample.sample) || !std::isfinite(sample.ownIntensity))
        {
            context.stats.nonFiniteSamples += 1; // nothing non-finite reaches a particle or an event
            continue;
        }
        sample.impulse = tracked.normalImpulse[i];
        sample.contact = contactIndex;
        const auto index = static_cast<std::uint32_t>(m_samples.size());
        m_samples.push_back(sample);
        if (step.last == kNone)
        {
            step.first = index;
        }
        else
        {
            m_samples[step.last].next = index;
        }
        step.last = index;
        step.sampledImpulse += sample.impulse;
    }
}

void Emitter::UpdatePair(RuleContext& context, std::uint32_t pairSlot)
{
    const RuleDef& rule = context.rule;
    PairStep& step = m_pairSteps[pairSlot];
    if (!std::isfinite(step.impulse))
    {
        // Finite impulses that add up past the float range: the pair is heard as silent this step.
        context.stats.nonFiniteSamples += 1;
        step.impulse = 0.0f;
        step.sampledImpulse = 0.0f;
        step.first = kNone;
        step.impactContact = kNone;
    }
    if (step.impactContact != kNone)
    {
        const TrackedContact& tracked = context.contacts[step.impactContact];
        NewTouch touch;
        touch.rule = tracked.rule;
        touch.fixtureA = context.tracker.RuleFixtureA(tracked);
        touch.fixtureB = context.tracker.RuleFixtureB(tracked);
        touch.point = tracked.approachPoint;
        touch.normal = tracked.swapped ? -tracked.approachNormal : tracked.approachNormal;
        touch.approachSpeed = tracked.approachSpeed;
        context.ruleStats.approachMaxLastStep =
            std::max(context.ruleStats.approachMaxLastStep, touch.approachSpeed);
        if (context.events.Impact(rule, touch, step.impulse))
        {
            context.ruleStats.impacts += 1;
            context.ruleStats.impactsLastStep += 1;
            Burst(context, tracked);
        }
    }
    if (step.asleep)
    {
        Save(m_rates[pairSlot], rule.maxRate * context.dt); // time passes for the cap, asleep or not
        context.events.Asleep(pairSlot);
        return;
    }

    // The pair's intensity: every sample pressed by the pair's whole normal force, weighted by its own
    // normal impulse (plain mean when nothing pressed).
    const float pairForce = step.impulse / context.dt;
    float weighted = 0.0f;
    float plain = 0.0f;
    int samples = 0;
    const Sample* loudest = nullptr;
    for (std::uint32_t i = step.first; i != kNone; i = m_samples[i].next)
    {
        Sample& sample = m_samples[i];
        sample.sample.normalForce = pairForce;
        sample.intensity = ComputeIntensity(sample.sample, rule.intensity);
        weighted += sample.impulse * sample.intensity;
        plain += sample.intensity;
        ++samples;
        if (loudest == nullptr || sample.intensity > loudest->intensity)
        {
            loudest = &sample;
        }
    }
    float intensity = 0.0f;
    if (step.sampledImpulse > 0.0f)
    {
        intensity = weighted / step.sampledImpulse;
    }
    else if (samples > 0)
    {
        intensity = plain / static_cast<float>(samples);
    }
    if (!std::isfinite(intensity))
    {
        // Finite samples whose weighted sum overflowed: the pair is heard as silent this step.
        context.stats.nonFiniteSamples += static_cast<std::uint64_t>(samples);
        intensity = 0.0f;
        loudest = nullptr;
        step.first = kNone;
    }
    context.ruleStats.intensityMaxLastStep = std::max(context.ruleStats.intensityMaxLastStep, intensity);

    if (rule.emission == EmissionMode::perStep)
    {
        // The tutorial's: one particle per sample per step above the threshold, per contact.
        for (std::uint32_t i = step.first; i != kNone; i = m_samples[i].next)
        {
            const Sample& sample = m_samples[i];
            context.ruleStats.intensityMaxLastStep =
                std::max(context.ruleStats.intensityMaxLastStep, sample.ownIntensity);
            if (sample.ownIntensity > rule.threshold)
            {
                SpawnParticles(context, context.contacts[sample.contact], sample.sample, sample.ownIntensity,
                               1, SpawnFor::scrape);
            }
        }
    }
    else
    {
        EmitRate(context, pairSlot, step, intensity);
    }

    PairMeasure measure;
    measure.rule = context.tracker.Pair(pairSlot).rule;
    measure.intensity = intensity;
    measure.normalImpulse = step.impulse;
    LoudestPoint point;
    if (loudest != nullptr)
    {
        const TrackedContact& tracked = context.contacts[loudest->contact];
        point.fixtureA = context.tracker.RuleFixtureA(tracked);
        point.fixtureB = context.tracker.RuleFixtureB(tracked);
        point.point = loudest->sample.point;
        point.normal = tracked.swapped ? -loudest->sample.normal : loudest->sample.normal;
        point.tangentialSpeed = TangentialVelocity(loudest->sample).Length();
        measure.loudest = &point;
    }
    context.events.Scrape(rule, pairSlot, measure);
}

int Emitter::Budgeted(float owed, EffectsStats& stats) const
{
    const int budget = std::max(m_spawnBudget, 0);
    const int count = ClampedCount(owed, budget);
    if (owed >= static_cast<float>(budget) + 1.0f)
    {
        // Finite (rates and bursts are capped by the rule), and far below 2^64 after the min.
        const float whole = std::floor(std::min(owed, 1.0e18f));
        stats.spawnOverCapacity += static_cast<std::uint64_t>(whole) - static_cast<std::uint64_t>(count);
    }
    return count;
}

void Emitter::EmitRate(RuleContext& context, std::uint32_t pairSlot, const PairStep& step, float intensity)
{
    const RuleDef& rule = context.rule;
    // The cap holds over time: each step allows maxRate * dt, and the pair saves what it leaves unused, up
    // to kMaxRateWindow's worth, to spend later in one step (a landing's pressure spike). Cut per step, the
    // spike gave maxRate * dt: fewer particles the higher the step rate. A pair held above its cap gets its
    // savings once and then maxRate, at any step rate; one below it is granted all it asks, as before.
    const float window = rule.maxRate * kMaxRateWindow; // the most a pair saves
    const float stepAllowance = rule.maxRate * context.dt;
    RateState& state = m_rates[pairSlot];
    if (!(intensity > rule.threshold))
    {
        Save(state, stepAllowance);
        return;
    }
    const float allowance = (window - state.unsaved) + stepAllowance;
    const float granted =
        std::min(rule.ratePerIntensity * (intensity - rule.threshold) * context.dt, allowance);
    state.unsaved = std::max(window - (allowance - granted), 0.0f);
    const float owed = state.carry + granted;
    // At most what this step may still spawn; what is owed beyond it is dropped, not carried.
    const int count = Budgeted(owed, context.stats);
    const float carry = owed - static_cast<float>(count);
    state.carry = carry >= 0.0f && carry < 1.0f ? carry : 0.0f;
    if (count <= 0 || step.first == kNone)
    {
        return;
    }
    // Shared out over the samples by normal impulse (equally when nothing pressed): systematic sampling
    // from one random offset, so each sample gets the floor or the ceiling of its share.
    const bool byImpulse = step.sampledImpulse > 0.0f;
    float total = 0.0f;
    for (std::uint32_t i = step.first; i != kNone; i = m_samples[i].next)
    {
        total += byImpulse ? m_samples[i].impulse : 1.0f;
    }
    const float offset = m_random.NextFloat();
    float cumulative = 0.0f;
    int given = 0;
    for (std::uint32_t i = step.first; i != kNone; i = m_samples[i].next)
    {
        const Sample& sample = m_samples[i];
        cumulative += byImpulse ? sample.impulse : 1.0f;
        int upTo = count;
        if (sample.next != kNone)
        {
            upTo = ClampedCount(cumulative / total * static_cast<float>(count) + offset, count);
        }
        const int share = upTo - given;
        given = std::max(given, upTo);
        if (share > 0)
        {
            SpawnParticles(context, context.contacts[sample.contact], sample.sample, intensity, share,
                           SpawnFor::scrape);
        }
    }
}

void Emitter::Burst(RuleContext& context, const TrackedContact& tracked)
{
    const int count =
        Budgeted(static_cast<float>(context.rule.BurstSize(tracked.approachSpeed)), context.stats);
    if (count > 0)
    {
        const ContactSample sample = SampleAt(tracked, tracked.approachPoint, tracked.approachNormal);
        if (!Finite(sample))
        {
            context.stats.nonFiniteSamples += 1; // a body's velocity went non-finite since it touched
            return;
        }
        SpawnParticles(context, tracked, sample, tracked.approachSpeed, count, SpawnFor::impact);
    }
}

void Emitter::SpawnParticles(RuleContext& context, const TrackedContact& tracked, const ContactSample& sample,
                             float intensity, int count, SpawnFor what)
{
    if (count > m_spawnBudget)
    {
        context.stats.spawnOverCapacity += static_cast<std::uint64_t>(count - std::max(m_spawnBudget, 0));
        count = m_spawnBudget;
    }
    if (count <= 0)
    {
        return;
    }
    m_spawnBudget -= count;
    const RuleDef& rule = context.rule;
    const ParticleTypeId typeId = what == SpawnFor::impact ? context.burstTypeId : context.typeId;
    const ParticleTypeDef& type = context.types[typeId.index];
    const b2Contact* contact = tracked.contact;
    const b2Fixture* fixtureA = contact->GetFixtureA();
    const b2Fixture* fixtureB = contact->GetFixtureB();
    const bool surfaceIsA = SurfaceIsA(fixtureA, fixtureB);

    // Seen from the surface: its normal points toward the other body; slip is the other body's
    // velocity over the surface, along it.
    const b2Vec2 surfaceNormal = surfaceIsA ? sample.normal : -sample.normal;
    b2Vec2 slip = surfaceIsA ? sample.velocityB - sample.velocityA : sample.velocityA - sample.velocityB;
    slip -= b2Dot(slip, surfaceNormal) * surfaceNormal;

    // The rule's materials name A and B; the contact's fixture order is Box2D's.
    const b2Vec2 ruleVelocityA = tracked.swapped ? sample.velocityB : sample.velocityA;
    const b2Vec2 ruleVelocityB = tracked.swapped ? sample.velocityA : sample.velocityB;
    // In the surface's frame (VelocityFrame::surface): what a body does over a moving surface looks as it
    // does over a still one.
    const b2Vec2 frame = type.velocityFrame == VelocityFrame::surface
                             ? (surfaceIsA ? sample.velocityA : sample.velocityB)
                             : b2Vec2(0.0f, 0.0f);
    const b2Vec2 carried = frame + type.inheritA * (ruleVelocityA - frame) +
                           type.inheritB * (ruleVelocityB - frame) + type.slipFactor * slip;
    // Where the particles go, seen from the other body's footprint: a sliding block's sparks fall behind
    // it, a spinning wheel's dirt leaves where its rim rises (not where it comes down, which would crush
    // it). Nothing carried along the surface: the side the other body's surface moves to.
    const b2Fixture& other = surfaceIsA ? *fixtureB : *fixtureA;
    b2Vec2 leaving = carried - FootprintVelocity(other, surfaceIsA ? sample.velocityB : sample.velocityA);
    leaving -= b2Dot(leaving, surfaceNormal) * surfaceNormal;

    SpawnQuery query;
    query.surface = surfaceIsA ? fixtureA : fixtureB;
    query.surfaceChild = surfaceIsA ? contact->GetChildIndexA() : contact->GetChildIndexB();
    query.point = sample.point;
    query.normal = surfaceNormal;
    // A hit (see kHitSlideShare) off the other body's middle (a corner, not a circle, whose footprint is a
    // point with both sides alike), or nothing carried along the surface and no slip to speak of (a flat
    // landing, where rounding alone picked a side, often the far one across the whole body): outward from
    // under the other body, from its centre through the contact point.
    b2Vec2 outward = sample.point - other.GetBody()->GetWorldCenter();
    outward -= b2Dot(outward, surfaceNormal) * surfaceNormal;
    const float hitSlide = kHitSlideShare * intensity;
    const bool hit = what == SpawnFor::impact && slip.LengthSquared() <= hitSlide * hitSlide &&
                     outward.LengthSquared() > kOffMiddle * kOffMiddle;
    query.leaving = hit                                                       ? outward
                    : leaving.LengthSquared() > kLeavingSpeed * kLeavingSpeed ? leaving
                    : slip.LengthSquared() > kLeavingSpeed * kLeavingSpeed    ? slip
                                                                              : outward;
    query.otherBody = other.GetBody();
    query.radius = type.radius;
    // The tutorial's drop starts inside a wheel its particles do not collide with, as the tutorial does.
    const bool tutorialDrop = rule.placement == SpawnPlacement::tutorialDrop;
    const Solids solids{&context.particleBodies, type.categoryBits, type.maskBits, !tutorialDrop};
    SpawnPoint start;
    if (tutorialDrop) // looks 1 m each way, as documented
    {
        start = FindTutorialDropPoint(context.world, query, solids);
    }
    else
    {
        query.searchDistance = SearchDistance(*other.GetBody());
        start = FindSpawnPoint(context.world, query, solids);
    }
    if (!start.outside)
    {
        // No free start near the contact (a pile, a crevice): never inside a solid, so not at all.
        context.stats.spawnRejected += static_cast<std::uint64_t>(count);
        context.ruleStats.spawnRejected += static_cast<std::uint64_t>(count);
        return;
    }
    // The audit: Box2D's own overlap test on the particle's actual disc, not the placement's search.
    if (m_auditStarts && DiscOverlapsSolid(context.world, start.position, type.radius, solids))
    {
        context.stats.spawnedInsideSolid += static_cast<std::uint64_t>(count);
    }

    const b2Vec2 baseVelocity = carried + type.normalSpeed * start.normal;
    const float life = std::clamp(type.lifeBase + type.lifeFromIntensity * intensity, 0.0f, 1.0f);
    int spawned = 0;
    for (int n = 0; n < count; ++n)
    {
        ParticleSpawn spawn;
        spawn.position = start.position;
        spawn.velocity = baseVelocity;
        spawn.velocity.x += m_random.Range(-type.spread, type.spread);
        spawn.velocity.y += m_random.Range(-type.spread, type.spread);
        spawn.life = life;
        spawn.type = typeId;
        // Finite inputs times absurd factors (inheritance, spread) can still overflow: no such particle.
        if (Finite(spawn.position) && Finite(spawn.velocity))
        {
            context.particles.Spawn(spawn);
            ++spawned;
        }
    }
    context.stats.nonFiniteSamples += static_cast<std::uint64_t>(count - spawned);
    context.ruleStats.spawned += static_cast<std::uint64_t>(spawned);
    context.ruleStats.spawnedLastStep += static_cast<std::uint32_t>(spawned);
    context.stats.spawnedByType[typeId.index] += static_cast<std::uint64_t>(spawned);
}

} // namespace cfx::detail
