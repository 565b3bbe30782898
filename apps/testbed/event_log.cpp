#include "event_log.h"

#include "harness/simulation.h"

#include <cstdio>

namespace cfx::testbed
{

std::string DescribeEvent(const EffectEvent& event, const EffectsConfig& config, float time)
{
    static constexpr const char* kTypes[] = {"began", "scrape", "ended", "impact", "hits"};
    static constexpr const char* kEnds[] = {
        "", "contact ended", "asleep", "below threshold", "destroyed", "stopped", "material changed"};
    static_assert(std::size(kEnds) == static_cast<std::size_t>(ScrapeEnd::materialChanged) + 1);
    char line[160];
    if (event.type == EffectEventType::particleHits)
    {
        std::snprintf(line, sizeof line, "%5.2f %-6s %u %s, %.1f m/s", static_cast<double>(time),
                      kTypes[static_cast<int>(event.type)], event.count,
                      config.particleTypes[event.particleType.index].name.c_str(),
                      static_cast<double>(event.approachSpeed));
        return line;
    }
    const RuleDef& rule = config.rules[event.rule.index];
    const int prefix = std::snprintf(line, sizeof line, "%5.2f %-6s #%-3u %s ", static_cast<double>(time),
                                     kTypes[static_cast<int>(event.type)], event.id, PairName(rule).c_str());
    const std::size_t at = prefix > 0 ? static_cast<std::size_t>(prefix) : 0;
    if (at < sizeof line)
    {
        if (event.type == EffectEventType::impact)
        {
            std::snprintf(line + at, sizeof line - at, "%.1f m/s", static_cast<double>(event.approachSpeed));
        }
        else if (event.type == EffectEventType::scrapeEnded)
        {
            std::snprintf(line + at, sizeof line - at, "%s", kEnds[static_cast<int>(event.end)]);
        }
        else
        {
            std::snprintf(line + at, sizeof line - at, "I %.1f", static_cast<double>(event.intensity));
        }
    }
    return line;
}

void EventLog::Record(const Effects& effects, float time)
{
    for (const EffectEvent& event : effects.Events())
    {
        m_entries.push_back(LoggedEvent{event, time, DescribeEvent(event, effects.Config(), time)});
        if (m_entries.size() > kCapacity)
        {
            m_entries.pop_front();
        }
    }
}

} // namespace cfx::testbed
