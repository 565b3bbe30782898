#include "contactfx/contact_tracker.h"

#include <algorithm>
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

void ContactTracker::Track(b2Contact* contact)
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
    m_index.Set(contact, Pack(rule, list.size()));
    list.push_back(tracked);
}

void ContactTracker::Untrack(b2Contact* contact)
{
    std::uint64_t* value = m_index.Find(contact);
    if (value == nullptr)
    {
        return;
    }
    std::vector<TrackedContact>& list = m_byRule[UnpackRule(*value).index];
    std::size_t slot = UnpackSlot(*value);
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
                Untrack(contact);
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
                Untrack(contact);
            }
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
    Untrack(contact);
    if (m_forward != nullptr)
    {
        m_forward->EndContact(contact);
    }
}

void ContactTracker::PreSolve(b2Contact* contact, const b2Manifold* oldManifold)
{
    // Box2D calls PreSolve only for touching, non-sensor contacts: a fixture that stopped being a
    // sensor while touching comes back into tracking here, since no new BeginContact will come.
    Track(contact);
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
