#include "contact_tracker.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_fixture.h>

namespace cfx
{

namespace
{

std::uint64_t Pack(RuleId rule, std::size_t slot)
{
    return (static_cast<std::uint64_t>(rule.index) << 32) | static_cast<std::uint64_t>(slot);
}

RuleId UnpackRule(std::uint64_t value)
{
    return RuleId{static_cast<std::uint16_t>(value >> 32)};
}

std::size_t UnpackSlot(std::uint64_t value)
{
    return static_cast<std::size_t>(value & 0xFFFFFFFFu);
}

bool IsSolid(const b2Contact* contact)
{
    return !contact->GetFixtureA()->IsSensor() && !contact->GetFixtureB()->IsSensor();
}

} // namespace

ContactTracker::ContactTracker(const RuleTable& rules, const FixtureMaterials& materials)
    : m_rules(rules), m_materials(materials), m_byRule(static_cast<std::size_t>(rules.RuleCount()))
{
}

void ContactTracker::Track(b2Contact* contact, bool firstTouch)
{
    if (IsTracked(contact) || !IsSolid(contact))
    {
        return;
    }
    MaterialId materialA = m_materials.Get(contact->GetFixtureA());
    MaterialId materialB = m_materials.Get(contact->GetFixtureB());
    RuleId rule = m_rules.Find(materialA, materialB);
    if (!rule.IsValid())
    {
        return;
    }
    std::vector<TrackedContact>& list = m_byRule[rule.index];
    TrackedContact tracked;
    tracked.contact = contact;
    tracked.rule = rule;
    tracked.swapped = m_rules.FirstMaterial(rule) != materialA;
    tracked.id = m_nextId++;
    tracked.beganStep = m_step;
    if (firstTouch)
    {
        RecordApproach(contact, tracked);
    }
    m_index.Set(contact, Pack(rule, list.size()));
    list.push_back(tracked);
}

void ContactTracker::Untrack(b2Contact* contact, ScrapeEnd reason)
{
    std::uint64_t* value = m_index.Find(contact);
    if (value == nullptr)
    {
        return;
    }
    std::vector<TrackedContact>& list = m_byRule[UnpackRule(*value).index];
    std::size_t slot = UnpackSlot(*value);
    if (list[slot].scrapeId != 0)
    {
        m_endedScrapes.push_back(EndScrape(list[slot], reason));
    }
    m_index.Erase(contact);
    if (slot + 1 != list.size())
    {
        list[slot] = list.back();
        m_index.Set(list[slot].contact, Pack(list[slot].rule, slot));
    }
    list.pop_back();
}

void ContactTracker::Prune()
{
    for (std::vector<TrackedContact>& list : m_byRule)
    {
        for (std::size_t i = list.size(); i-- > 0;)
        {
            b2Contact* contact = list[i].contact;
            if (!IsSolid(contact) || !contact->IsTouching())
            {
                Untrack(contact, ScrapeEnd::contactEnded);
            }
        }
    }
}

void ContactTracker::EndStep()
{
    for (std::vector<TrackedContact>& list : m_byRule)
    {
        for (TrackedContact& tracked : list)
        {
            tracked.normalImpulse[0] = 0.0f;
            tracked.normalImpulse[1] = 0.0f;
        }
    }
    ++m_step;
}

void ContactTracker::ForgetFixture(const b2Fixture* fixture)
{
    for (std::vector<TrackedContact>& list : m_byRule)
    {
        for (std::size_t i = list.size(); i-- > 0;)
        {
            b2Contact* contact = list[i].contact;
            if (contact->GetFixtureA() == fixture || contact->GetFixtureB() == fixture)
            {
                Untrack(contact, ScrapeEnd::destroyed);
            }
        }
    }
}

void ContactTracker::MarkDestroyed(const b2Fixture* fixture)
{
    for (EffectEvent& ended : m_endedScrapes)
    {
        if (ended.fixtureA == fixture || ended.fixtureB == fixture)
        {
            ended.end = ScrapeEnd::destroyed;
        }
    }
}

const b2Fixture* ContactTracker::RuleFixtureA(const TrackedContact& tracked) const
{
    return tracked.swapped ? tracked.contact->GetFixtureB() : tracked.contact->GetFixtureA();
}

const b2Fixture* ContactTracker::RuleFixtureB(const TrackedContact& tracked) const
{
    return tracked.swapped ? tracked.contact->GetFixtureA() : tracked.contact->GetFixtureB();
}

EffectEvent ContactTracker::EndScrape(TrackedContact& tracked, ScrapeEnd reason) const
{
    EffectEvent event;
    event.type = EffectEventType::scrapeEnded;
    event.end = reason;
    event.rule = tracked.rule;
    event.fixtureA = RuleFixtureA(tracked);
    event.fixtureB = RuleFixtureB(tracked);
    event.materialA = m_materials.Get(event.fixtureA);
    event.materialB = m_materials.Get(event.fixtureB);
    event.id = tracked.scrapeId;
    event.step = m_step;
    event.point = tracked.scrapePoint;
    event.normal = tracked.scrapeNormal;
    tracked.scrapeId = 0;
    tracked.quietTime = 0.0f;
    return event;
}

void ContactTracker::RecordApproach(b2Contact* contact, TrackedContact& tracked)
{
    const b2Manifold* manifold = contact->GetManifold();
    if (manifold->pointCount < 1)
    {
        return;
    }
    b2WorldManifold world;
    contact->GetWorldManifold(&world);
    const b2Body* bodyA = contact->GetFixtureA()->GetBody();
    const b2Body* bodyB = contact->GetFixtureB()->GetBody();
    tracked.impactPending = true;
    tracked.approachNormal = world.normal;
    tracked.approachSpeed = -1.0f;
    for (int i = 0; i < manifold->pointCount; ++i)
    {
        const b2Vec2 relative = bodyA->GetLinearVelocityFromWorldPoint(world.points[i]) -
                                bodyB->GetLinearVelocityFromWorldPoint(world.points[i]);
        const float approach = b2Dot(relative, world.normal); // > 0: A moves toward B
        if (approach > tracked.approachSpeed)
        {
            tracked.approachSpeed = approach;
            tracked.approachPoint = world.points[i];
        }
    }
    tracked.approachSpeed = std::max(tracked.approachSpeed, 0.0f);
}

void ContactTracker::BeginContact(b2Contact* contact)
{
    Track(contact, true);
    if (m_forward != nullptr)
    {
        m_forward->BeginContact(contact);
    }
}

void ContactTracker::EndContact(b2Contact* contact)
{
    Untrack(contact, ScrapeEnd::contactEnded);
    if (m_forward != nullptr)
    {
        m_forward->EndContact(contact);
    }
}

void ContactTracker::PreSolve(b2Contact* contact, const b2Manifold* oldManifold)
{
    // Box2D calls PreSolve only for touching, non-sensor contacts: a fixture that stopped being a
    // sensor while touching comes back into tracking here, since no new BeginContact will come.
    Track(contact, false);
    if (m_forward != nullptr)
    {
        m_forward->PreSolve(contact, oldManifold);
    }
}

void ContactTracker::PostSolve(b2Contact* contact, const b2ContactImpulse* impulse)
{
    if (std::uint64_t* value = m_index.Find(contact))
    {
        TrackedContact& tracked = m_byRule[UnpackRule(*value).index][UnpackSlot(*value)];
        // Continuous collision may report a contact more than once per step: keep the largest.
        for (int i = 0; i < impulse->count && i < 2; ++i)
        {
            tracked.normalImpulse[i] = std::max(tracked.normalImpulse[i], impulse->normalImpulses[i]);
        }
    }
    if (m_forward != nullptr)
    {
        m_forward->PostSolve(contact, impulse);
    }
}

} // namespace cfx
