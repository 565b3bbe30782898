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

// m/s: a manifold point approaching no faster than this is at rest, not touching anew.
constexpr float kRestingApproach = 1.0e-3f;

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

RuleTable BuildRuleTable(const EffectsConfig& config)
{
    RuleTable table(static_cast<int>(config.materials.size()));
    for (std::size_t i = 0; i < config.rules.size(); ++i)
    {
        table.Set(config.FindMaterial(config.rules[i].materialA),
                  config.FindMaterial(config.rules[i].materialB), RuleId{static_cast<std::uint16_t>(i)});
    }
    return table;
}

ContactTracker::ContactTracker(const RuleTable& rules, const FixtureMaterials& materials)
    : m_rules(rules), m_materials(materials), m_byRule(static_cast<std::size_t>(rules.RuleCount()))
{
}

void ContactTracker::Reserve(std::uint32_t perRule, std::size_t total)
{
    for (std::vector<TrackedContact>& list : m_byRule)
    {
        list.reserve(perRule);
    }
    m_index.Reserve(total);
    m_pairs.reserve(total);
    m_freePairs.reserve(total);
    m_endedPairs.reserve(total);
    m_endingPairs.reserve(total);
}

TrackedContact* ContactTracker::Tracked(const b2Contact* contact)
{
    const std::uint64_t* value = m_index.Find(contact);
    return value != nullptr ? &m_byRule[UnpackRule(*value).index][UnpackSlot(*value)] : nullptr;
}

TrackedContact* ContactTracker::Track(b2Contact* contact)
{
    if (TrackedContact* tracked = Tracked(contact))
    {
        return tracked;
    }
    if (!IsSolid(contact))
    {
        return nullptr;
    }
    MaterialId materialA = m_materials.Get(contact->GetFixtureA());
    MaterialId materialB = m_materials.Get(contact->GetFixtureB());
    RuleId rule = m_rules.Find(materialA, materialB);
    if (!rule.IsValid())
    {
        return nullptr;
    }
    std::vector<TrackedContact>& list = m_byRule[rule.index];
    TrackedContact tracked;
    tracked.contact = contact;
    tracked.rule = rule;
    tracked.swapped = m_rules.FirstMaterial(rule) != materialA;
    tracked.pair = FindOrAddPair(contact, rule);
    m_pairs[tracked.pair].contacts += 1;
    m_index.Set(contact, Pack(rule, list.size()));
    list.push_back(tracked);
    return &list.back();
}

std::uint32_t ContactTracker::FindOrAddPair(b2Contact* contact, RuleId rule)
{
    // Another tracked contact of the same rule between the same two bodies holds the pair. Every contact
    // of a body is in its contact list: walking both lists in step, the shorter one ends first, and by
    // then it has been searched completely.
    b2Body* bodyA = contact->GetFixtureA()->GetBody();
    b2Body* bodyB = contact->GetFixtureB()->GetBody();
    const b2ContactEdge* edgeA = bodyA->GetContactList();
    const b2ContactEdge* edgeB = bodyB->GetContactList();
    auto pairOf = [&](const b2ContactEdge* edge, const b2Body* other) -> const TrackedContact*
    {
        if (edge->other != other || edge->contact == contact)
        {
            return nullptr;
        }
        const std::uint64_t* value = m_index.Find(edge->contact);
        if (value == nullptr || UnpackRule(*value) != rule)
        {
            return nullptr;
        }
        return &m_byRule[rule.index][UnpackSlot(*value)];
    };
    while (edgeA != nullptr && edgeB != nullptr)
    {
        if (const TrackedContact* found = pairOf(edgeA, bodyB))
        {
            return found->pair;
        }
        if (const TrackedContact* found = pairOf(edgeB, bodyA))
        {
            return found->pair;
        }
        edgeA = edgeA->next;
        edgeB = edgeB->next;
    }
    // The same two bodies' pair of this rule, waiting to end since its last contact left: it goes on.
    for (auto ending = m_endingPairs.begin(); ending != m_endingPairs.end(); ++ending)
    {
        if (ending->ended.reason == ScrapeEnd::contactEnded && m_pairs[ending->ended.slot].rule == rule &&
            ((ending->bodyA == bodyA && ending->bodyB == bodyB) ||
             (ending->bodyA == bodyB && ending->bodyB == bodyA)))
        {
            const std::uint32_t slot = ending->ended.slot;
            m_endingPairs.erase(ending); // keeps the others' order; no allocation
            return slot;
        }
    }
    std::uint32_t slot = 0;
    if (!m_freePairs.empty())
    {
        slot = m_freePairs.back();
        m_freePairs.pop_back();
    }
    else
    {
        slot = static_cast<std::uint32_t>(m_pairs.size());
        m_pairs.emplace_back();
        // Room for every slot to be free, and for every slot's pair to end in one step (a slot is listed
        // once at most): freeing a pair inside a callback never allocates.
        m_freePairs.reserve(m_pairs.capacity());
        m_endedPairs.reserve(m_pairs.capacity());
        m_endingPairs.reserve(m_pairs.capacity());
    }
    m_pairs[slot] = TrackedPair{};
    m_pairs[slot].rule = rule;
    m_pairs[slot].beganStep = m_step;
    return slot;
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
    TrackedPair& pair = m_pairs[list[slot].pair];
    pair.contacts -= 1;
    if (pair.contacts == 0)
    {
        // The pair's last contact, named so that a destroyed fixture is recognised by MarkDestroyed. A
        // pair that began after the last EndStep was never seen by a step: nobody keeps state for it.
        if (pair.beganStep < m_step)
        {
            EndedPair ended;
            ended.slot = list[slot].pair;
            ended.reason = reason;
            ended.fixtureA = RuleFixtureA(list[slot]);
            ended.fixtureB = RuleFixtureB(list[slot]);
            ended.materialA = m_materials.Recorded(ended.fixtureA);
            ended.materialB = m_materials.Recorded(ended.fixtureB);
            if (reason == ScrapeEnd::contactEnded)
            {
                m_endingPairs.push_back(
                    EndingPair{ended, contact->GetFixtureA()->GetBody(), contact->GetFixtureB()->GetBody()});
            }
            else
            {
                m_endedPairs.push_back(ended);
                m_freePairs.push_back(ended.slot);
            }
        }
        else
        {
            m_freePairs.push_back(list[slot].pair);
        }
    }
    m_index.Erase(contact);
    if (slot + 1 != list.size())
    {
        list[slot] = list.back();
        m_index.Set(list[slot].contact, Pack(list[slot].rule, slot));
    }
    list.pop_back();
}

bool ContactTracker::AnyAwake() const
{
    const auto moving = [](const b2Body* body)
    { return body->IsAwake() && body->GetType() != b2_staticBody; };
    for (const std::vector<TrackedContact>& list : m_byRule)
    {
        for (const TrackedContact& tracked : list)
        {
            if (moving(tracked.contact->GetFixtureA()->GetBody()) ||
                moving(tracked.contact->GetFixtureB()->GetBody()))
            {
                return true;
            }
        }
    }
    return false;
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
    for (const EndingPair& ending : m_endingPairs)
    {
        m_endedPairs.push_back(ending.ended);
        m_freePairs.push_back(ending.ended.slot);
    }
    m_endingPairs.clear();
}

void ContactTracker::ShiftOrigin(b2Vec2 newOrigin)
{
    for (std::vector<TrackedContact>& contacts : m_byRule)
    {
        for (TrackedContact& tracked : contacts)
        {
            tracked.approachPoint -= newOrigin;
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
            tracked.newTouch = false;
        }
    }
    m_endedPairs.clear();
    m_solved = false;
    ++m_step;
}

void ContactTracker::EndContactsOf(const b2Fixture* fixture, ScrapeEnd reason)
{
    for (std::vector<TrackedContact>& list : m_byRule)
    {
        for (std::size_t i = list.size(); i-- > 0;)
        {
            b2Contact* contact = list[i].contact;
            if (contact->GetFixtureA() == fixture || contact->GetFixtureB() == fixture)
            {
                Untrack(contact, reason);
            }
        }
    }
}

void ContactTracker::MarkDestroyed(const b2Fixture* fixture)
{
    const auto mark = [fixture](EndedPair& ended)
    {
        if (ended.fixtureA == fixture || ended.fixtureB == fixture)
        {
            ended.reason = ScrapeEnd::destroyed;
        }
    };
    for (EndedPair& ended : m_endedPairs)
    {
        mark(ended);
    }
    for (EndingPair& ending : m_endingPairs)
    {
        mark(ending.ended);
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

void ContactTracker::NoteTouches(b2Contact* contact, const b2Manifold& oldManifold, TrackedContact& tracked)
{
    if (!contact->IsEnabled())
    {
        // Disabled by the application: it did not touch, nor did an earlier piece of the step (continuous
        // collision calls PreSolve again) that this one undoes.
        tracked.disabled = true;
        tracked.newTouch = false;
        return;
    }
    const b2Manifold* manifold = contact->GetManifold();
    b2PointState before[b2_maxManifoldPoints];
    b2PointState now[b2_maxManifoldPoints];
    b2GetPointStates(before, now, &oldManifold, manifold);
    const bool allNew = tracked.disabled;
    tracked.disabled = false;
    b2WorldManifold world;
    bool measured = false;
    const b2Body* bodyA = contact->GetFixtureA()->GetBody();
    const b2Body* bodyB = contact->GetFixtureB()->GetBody();
    for (int i = 0; i < manifold->pointCount; ++i)
    {
        if (!allNew && now[i] != b2_addState)
        {
            continue;
        }
        if (!measured)
        {
            contact->GetWorldManifold(&world);
            measured = true;
        }
        const b2Vec2 relative = bodyA->GetLinearVelocityFromWorldPoint(world.points[i]) -
                                bodyB->GetLinearVelocityFromWorldPoint(world.points[i]);
        const float approach = std::max(b2Dot(relative, world.normal), 0.0f); // > 0: A moves toward B
        // A point that does not approach is not a touch, whatever the impact threshold: a box settling on a
        // chain has its points renamed, and its contacts with the next segments begin at rest, approaching
        // at 1e-7 m/s of rounding (with impactThreshold 0 they came as impacts, one a step).
        if (!(approach > kRestingApproach))
        {
            continue;
        }
        if (!tracked.newTouch || approach > tracked.approachSpeed)
        {
            tracked.newTouch = true;
            tracked.approachSpeed = approach;
            tracked.approachPoint = world.points[i];
            tracked.approachNormal = world.normal;
        }
    }
}

void ContactTracker::BeginContact(b2Contact* contact)
{
    Track(contact);
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
    m_solved = true;
    TrackedContact* tracked = Track(contact);
    if (m_forward != nullptr)
    {
        m_forward->PreSolve(contact, oldManifold);
        // It may have changed what is tracked (SetMaterial ends contacts): look again.
        tracked = Tracked(contact);
    }
    // After the application's PreSolve, which may disable the contact.
    if (tracked != nullptr)
    {
        NoteTouches(contact, *oldManifold, *tracked);
    }
}

void ContactTracker::PostSolve(b2Contact* contact, const b2ContactImpulse* impulse)
{
    if (TrackedContact* tracked = Tracked(contact))
    {
        // Continuous collision may report a contact more than once per step: keep the largest.
        for (int i = 0; i < impulse->count && i < 2; ++i)
        {
            tracked->normalImpulse[i] = std::max(tracked->normalImpulse[i], impulse->normalImpulses[i]);
        }
    }
    if (m_forward != nullptr)
    {
        m_forward->PostSolve(contact, impulse);
    }
}

} // namespace cfx
