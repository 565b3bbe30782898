#include "contactfx/effects.h"

#include "contact_tracker.h"
#include "effects_access.h"
#include "emitter.h"
#include "fixture_materials.h"

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

namespace cfx
{

namespace
{

const EffectsConfig& Checked(const EffectsConfig& config)
{
    std::vector<Diagnostic> problems = Validate(config);
    if (!problems.empty())
    {
        throw InputError(std::move(problems));
    }
    return config;
}

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

// Forgets fixtures destroyed with their body, then forwards to the application's listener.
class Destruction final : public b2DestructionListener
{
public:
    Destruction(FixtureMaterials& materials, ContactTracker& tracker, b2DestructionListener* application)
        : m_materials(materials), m_tracker(tracker), forward(application)
    {
    }

    void SayGoodbye(b2Joint* joint) override
    {
        if (forward != nullptr)
        {
            forward->SayGoodbye(joint);
        }
    }

    void SayGoodbye(b2Fixture* fixture) override
    {
        // Box2D ended the fixture's contacts just before: their scrapes ended by destruction.
        m_tracker.MarkDestroyed(fixture);
        m_materials.Erase(fixture);
        if (forward != nullptr)
        {
            forward->SayGoodbye(fixture);
        }
    }

private:
    FixtureMaterials& m_materials;
    ContactTracker& m_tracker;

public:
    b2DestructionListener* forward;
};

} // namespace

// What Effects keeps out of its public header. Members are declared in the order they depend on each
// other: the tracker reads the materials, the destruction listener edits both.
struct Effects::Internals
{
    Internals(const RuleTable& rules, const EffectsConfig& config, const EffectsDef& def)
        : tracker(rules, materials), destruction(materials, tracker, def.destructionListener),
          emitter(config, def.seed)
    {
        tracker.SetForward(def.contactListener);
        tracker.Reserve(config.budget.contacts);
    }

    FixtureMaterials materials;
    ContactTracker tracker;
    Destruction destruction;
    detail::Emitter emitter;
};

Effects::Effects(b2World& world, const EffectsDef& def)
    : m_world(world), m_config(Checked(def.config)), m_rules(BuildRuleTable(m_config)),
      m_particles(world, m_config.particleTypes, m_config.budget, def.particles),
      m_internals(std::make_unique<Internals>(m_rules, m_config, def)), m_eventListener(def.eventListener)
{
    m_stats.spawnedByType.assign(m_config.particleTypes.size(), 0);
    m_stats.rules.assign(m_config.rules.size(), RuleStats{});
    // A step reports at most a scrape end and an impact per body pair (budget.contacts of them).
    m_events.reserve(std::size_t{2} * m_config.budget.contacts);
    m_world.SetContactListener(&m_internals->tracker);
    m_world.SetDestructionListener(&m_internals->destruction);
}

Effects::~Effects()
{
    m_world.SetContactListener(m_internals->tracker.Forward());
    m_world.SetDestructionListener(m_internals->destruction.forward);
}

void Effects::SetMaterial(b2Fixture* fixture, MaterialId material)
{
    m_internals->materials.Set(fixture, material);
}

MaterialId Effects::Material(const b2Fixture* fixture) const
{
    return m_internals->materials.Get(fixture);
}

void Effects::SetContactListener(b2ContactListener* listener)
{
    m_internals->tracker.SetForward(listener);
}

void Effects::SetMaterial(b2Body* body, MaterialId material)
{
    for (b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        m_internals->materials.Set(fixture, material);
    }
}

void Effects::ForgetFixture(b2Fixture* fixture)
{
    m_internals->tracker.ForgetFixture(fixture);
    m_internals->materials.Erase(fixture);
}

void Effects::SetDestructionListener(b2DestructionListener* listener)
{
    m_internals->destruction.forward = listener;
}

void Effects::Step(float dt)
{
    ContactTracker& tracker = m_internals->tracker;
    tracker.Prune();
    m_events.assign(tracker.EndedScrapes().begin(), tracker.EndedScrapes().end());
    tracker.ClearEndedScrapes();
    m_internals->emitter.Emit(m_world, m_config, tracker, m_particles, m_stats, m_events, dt);
    m_particles.Step(dt, m_world.GetGravity());
    tracker.EndStep();
    m_stats.steps += 1;
    m_stats.time += static_cast<double>(dt);
    m_stats.live = m_particles.Count();
    m_stats.liveMax = std::max(m_stats.liveMax, m_stats.live);
    m_stats.recycled = m_particles.Recycled();
    m_stats.crushed = m_particles.Counters().crushed;
    m_stats.particleStepsInside = m_particles.Counters().stepsInside;
    m_stats.crossings = m_particles.Counters().crossings;
    if (m_eventListener != nullptr)
    {
        for (const EffectEvent& event : m_events)
        {
            m_eventListener->OnEffectEvent(event);
        }
    }
}

namespace detail
{

const ContactTracker& EffectsAccess::Tracker(const Effects& effects)
{
    return effects.m_internals->tracker;
}

} // namespace detail

} // namespace cfx
