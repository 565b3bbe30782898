#include "events.h"

#include <algorithm>

namespace cfx::detail
{

EventTracker::EventTracker(const FixtureMaterials& materials, std::size_t pairs, std::uint32_t hitGroups)
    : m_materials(materials)
{
    m_scrapes.reserve(pairs);
    // A step reports at most a scrape end and an impact per body pair, or an impact and a scrape event,
    // then its particle hit groups; and the event listener may end every scrape on top (EndAll).
    m_events.reserve(std::size_t{3} * pairs + hitGroups);
}

void EventTracker::ParticleHits(std::span<const ParticleHitGroup> groups)
{
    for (const ParticleHitGroup& group : groups)
    {
        EffectEvent& event = m_events.emplace_back();
        event.type = EffectEventType::particleHits;
        event.step = m_step;
        event.point = group.centre;
        event.approachSpeed = group.meanSpeed;
        event.body = group.body;
        event.particleType = group.type;
        event.count = group.count;
    }
}

void EventTracker::ShiftOrigin(b2Vec2 newOrigin)
{
    for (ScrapeState& scrape : m_scrapes)
    {
        scrape.point -= newOrigin;
    }
}

void EventTracker::EndAll(ScrapeEnd reason, Keep keep)
{
    if (keep == Keep::none)
    {
        m_events.clear();
    }
    const auto first = static_cast<std::ptrdiff_t>(m_events.size());
    for (ScrapeState& scrape : m_scrapes)
    {
        if (scrape.id != 0)
        {
            End(scrape, reason, scrape.fixtureA, scrape.fixtureB);
        }
    }
    std::sort(m_events.begin() + first, m_events.end(),
              [](const EffectEvent& a, const EffectEvent& b) { return a.id < b.id; });
}

EventTracker::ScrapeState& EventTracker::StateOf(std::uint32_t slot)
{
    if (slot >= m_scrapes.size())
    {
        m_scrapes.resize(std::size_t{slot} + 1);
    }
    return m_scrapes[slot];
}

void EventTracker::BeginStep(std::uint64_t step, float dt, std::span<const EndedPair> ended)
{
    m_step = step;
    m_dt = dt;
    m_events.clear();
    for (const EndedPair& pair : ended)
    {
        if (pair.slot >= m_scrapes.size())
        {
            continue; // never reported: no scrape
        }
        ScrapeState& scrape = m_scrapes[pair.slot];
        if (scrape.id != 0)
        {
            // Named by the pair's last contact, with the materials its fixtures had as it left.
            EffectEvent& event = End(scrape, pair.reason, pair.fixtureA, pair.fixtureB);
            event.materialA = pair.materialA;
            event.materialB = pair.materialB;
        }
        scrape = ScrapeState{};
    }
}

bool EventTracker::Impact(const RuleDef& rule, const NewTouch& touch, float normalImpulse)
{
    if (!(touch.approachSpeed >= rule.impactThreshold))
    {
        return false;
    }
    EffectEvent event = Named(EffectEventType::impact, touch.rule, touch.fixtureA, touch.fixtureB);
    event.id = m_nextId++;
    event.point = touch.point;
    event.normal = touch.normal;
    event.approachSpeed = touch.approachSpeed;
    event.normalImpulse = normalImpulse;
    m_events.push_back(event);
    return true;
}

void EventTracker::Asleep(std::uint32_t slot)
{
    ScrapeState& scrape = StateOf(slot);
    if (scrape.id != 0)
    {
        End(scrape, ScrapeEnd::asleep, scrape.fixtureA, scrape.fixtureB);
    }
}

void EventTracker::Scrape(const RuleDef& rule, std::uint32_t slot, const PairMeasure& measure)
{
    ScrapeState& scrape = StateOf(slot);
    EffectEventType type = EffectEventType::scrapeChanged;
    if (measure.intensity > rule.threshold)
    {
        scrape.quietTime = 0.0f;
        if (scrape.id == 0)
        {
            scrape.id = m_nextId++;
            scrape.rule = measure.rule;
            type = EffectEventType::scrapeBegan;
        }
    }
    else if (scrape.id != 0)
    {
        scrape.quietTime += m_dt;
        if (scrape.quietTime >= rule.scrapeEndDelay)
        {
            End(scrape, ScrapeEnd::belowThreshold, scrape.fixtureA, scrape.fixtureB);
            return;
        }
    }
    else
    {
        return; // quiet, and no scrape going on
    }
    if (measure.loudest != nullptr)
    {
        scrape.fixtureA = measure.loudest->fixtureA;
        scrape.fixtureB = measure.loudest->fixtureB;
        scrape.point = measure.loudest->point;
        scrape.normal = measure.loudest->normal;
    }
    EffectEvent event = Named(type, scrape.rule, scrape.fixtureA, scrape.fixtureB);
    event.id = scrape.id;
    event.point = scrape.point;
    event.normal = scrape.normal;
    event.intensity = measure.intensity;
    event.tangentialSpeed = measure.loudest != nullptr ? measure.loudest->tangentialSpeed : 0.0f;
    event.normalImpulse = measure.normalImpulse;
    m_events.push_back(event);
}

EffectEvent EventTracker::Named(EffectEventType type, RuleId rule, const b2Fixture* fixtureA,
                                const b2Fixture* fixtureB) const
{
    EffectEvent event;
    event.type = type;
    event.rule = rule;
    event.fixtureA = fixtureA;
    event.fixtureB = fixtureB;
    event.materialA = m_materials.Recorded(fixtureA);
    event.materialB = m_materials.Recorded(fixtureB);
    event.step = m_step;
    return event;
}

EffectEvent& EventTracker::End(ScrapeState& scrape, ScrapeEnd reason, const b2Fixture* fixtureA,
                               const b2Fixture* fixtureB)
{
    EffectEvent event = Named(EffectEventType::scrapeEnded, scrape.rule, fixtureA, fixtureB);
    event.end = reason;
    event.id = scrape.id;
    event.point = scrape.point;
    event.normal = scrape.normal;
    scrape.id = 0;
    scrape.quietTime = 0.0f;
    return m_events.emplace_back(event);
}

} // namespace cfx::detail
