#include "contactfx/effects.h"

#include "emitter.h"

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

} // namespace

// Forgets fixtures destroyed with their body, then forwards to the application's listener.
class Effects::Destruction final : public b2DestructionListener
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

Effects::Effects(b2World& world, const EffectsDef& def)
    : m_world(world), m_config(Checked(def.config)), m_rules(BuildRuleTable(m_config)),
      m_tracker(m_rules, m_materials), m_particles(world, m_config.particleTypes, m_config.budget),
      m_destruction(std::make_unique<Destruction>(m_materials, m_tracker, def.destructionListener)),
      m_emitter(std::make_unique<detail::Emitter>(m_config, def.seed)), m_eventListener(def.eventListener)
{
    m_stats.spawnedByType.assign(m_config.particleTypes.size(), 0);
    m_stats.rules.assign(m_config.rules.size(), RuleStats{});
    m_tracker.SetForward(def.contactListener);
    m_world.SetContactListener(&m_tracker);
    m_world.SetDestructionListener(m_destruction.get());
}

Effects::~Effects()
{
    m_world.SetContactListener(m_tracker.Forward());
    m_world.SetDestructionListener(m_destruction->forward);
}

void Effects::SetMaterial(b2Fixture* fixture, MaterialId material)
{
    m_materials.Set(fixture, material);
}

void Effects::SetMaterial(b2Body* body, MaterialId material)
{
    for (b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        m_materials.Set(fixture, material);
    }
}

void Effects::ForgetFixture(b2Fixture* fixture)
{
    m_tracker.ForgetFixture(fixture);
    m_materials.Erase(fixture);
}

void Effects::SetDestructionListener(b2DestructionListener* listener)
{
    m_destruction->forward = listener;
}

void Effects::Step(float dt)
{
    m_tracker.Prune();
    m_events.assign(m_tracker.EndedScrapes().begin(), m_tracker.EndedScrapes().end());
    m_tracker.ClearEndedScrapes();
    m_emitter->Emit(m_world, m_config, m_tracker, m_particles, m_stats, m_events, dt);
    m_particles.Step(dt, m_world.GetGravity());
    m_tracker.EndStep();
    m_stats.steps += 1;
    m_stats.time += static_cast<double>(dt);
    m_stats.live = m_particles.Count();
    m_stats.liveMax = std::max(m_stats.liveMax, m_stats.live);
    m_stats.recycled = m_particles.Recycled();
    if (m_eventListener != nullptr)
    {
        for (const EffectEvent& event : m_events)
        {
            m_eventListener->OnEffectEvent(event);
        }
    }
}

} // namespace cfx
