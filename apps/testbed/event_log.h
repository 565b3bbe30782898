// contactfx-testbed: the effect events of the last moments, for the events panel and the markers.
//
// The session records every step's events (scrapes, impacts and particle hits, events.h) with the simulated
// time they happened; the panel lists them newest first and the view marks where the recent ones happened.
// Bounded: the oldest entries go once there are kCapacity.
#pragma once

#include "contactfx/effects.h"

#include <deque>
#include <string>

namespace cfx::testbed
{

struct LoggedEvent
{
    EffectEvent event;
    float time = 0.0f; ///< s, simulated time of the step that reported it
    std::string text;  ///< one line for the panel
};

class EventLog
{
public:
    static constexpr std::size_t kCapacity = 200;

    /// Appends the events of the step that just ran (Effects::Events()) at simulated time `time`.
    void Record(const Effects& effects, float time);
    void Clear() { m_entries.clear(); }
    /// Oldest first.
    const std::deque<LoggedEvent>& Entries() const { return m_entries; }

private:
    std::deque<LoggedEvent> m_entries;
};

/// "1.23 impact #12 steel+concrete 4.1 m/s" (approach speed), "... scrape #3 ... I 2.5" (intensity),
/// "... ended #3 ... asleep" (reason).
std::string DescribeEvent(const EffectEvent& event, const EffectsConfig& config, float time);

} // namespace cfx::testbed
