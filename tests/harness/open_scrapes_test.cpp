// A run's events end every scrape they begin: Simulation::EndScrapes (Effects::EndScrapes) closes the
// scrapes still open when the run stops, as the CLI's events file does.
#include "harness/simulation.h"
#include "scenes_dir.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

namespace cfx
{
namespace
{

// The grinder scene file as `contactfx run scenes/grinder.json` runs it: default preset, seed 1, 60 Hz.
SimulationDef GrinderFile()
{
    SimulationDef def;
    def.scene = kScenesDir / "grinder.json";
    return def;
}

// Every event of `steps` steps, then the closing ones.
std::vector<EffectEvent> RunAndClose(Simulation& simulation, int steps)
{
    std::vector<EffectEvent> events;
    for (int i = 0; i < steps; ++i)
    {
        simulation.Step();
        const std::span<const EffectEvent> step = simulation.GetEffects().Events();
        events.insert(events.end(), step.begin(), step.end());
    }
    const std::span<const EffectEvent> closing = simulation.EndScrapes();
    events.insert(events.end(), closing.begin(), closing.end());
    return events;
}

TEST(OpenScrapes, EveryScrapeThatBeganEndsOnceAfterItsLastChange)
{
    Simulation simulation(GrinderFile());
    const std::vector<EffectEvent> events = RunAndClose(simulation, 120); // 2 s
    std::map<std::uint32_t, int> ends;                                    // id -> scrapeEnded events
    std::size_t began = 0;
    for (const EffectEvent& event : events)
    {
        if (event.type == EffectEventType::scrapeBegan)
        {
            EXPECT_TRUE(ends.emplace(event.id, 0).second) << "id " << event.id << " began twice";
            ++began;
        }
        else if (event.type == EffectEventType::scrapeChanged)
        {
            ASSERT_TRUE(ends.contains(event.id)) << "id " << event.id;
            EXPECT_EQ(ends[event.id], 0) << "id " << event.id << " changed after it ended";
        }
        else if (event.type == EffectEventType::scrapeEnded)
        {
            ASSERT_TRUE(ends.contains(event.id)) << "id " << event.id;
            ++ends[event.id];
        }
    }
    EXPECT_GT(began, 0u);
    for (const auto& [id, count] : ends)
    {
        EXPECT_EQ(count, 1) << "id " << id;
    }
}

TEST(OpenScrapes, TheGrinderStillScrapesAfterTwoSecondsAndItsScrapesEndAtTheRunsEnd)
{
    Simulation simulation(GrinderFile());
    for (int i = 0; i < 120; ++i)
    {
        simulation.Step();
    }
    const std::span<const EffectEvent> ended = simulation.EndScrapes();
    const std::vector<EffectEvent> closing(ended.begin(), ended.end());
    ASSERT_FALSE(closing.empty()); // what the fix is for: the wheel still grinds when the run stops
    for (std::size_t i = 0; i < closing.size(); ++i)
    {
        const EffectEvent& event = closing[i];
        EXPECT_EQ(event.type, EffectEventType::scrapeEnded);
        EXPECT_EQ(event.end, ScrapeEnd::stopped);
        EXPECT_NE(event.id, 0u);
        EXPECT_TRUE(i == 0 || closing[i - 1].id < event.id) << "in id order";
        const nlohmann::json line =
            nlohmann::json::parse(EventJsonLine(event, simulation.GetEffects().Config(), 60.0));
        EXPECT_EQ(line["type"], "scrape_ended");
        EXPECT_EQ(line["reason"], "run_ended");
        EXPECT_EQ(line["step"], simulation.Steps() - 1);
        EXPECT_DOUBLE_EQ(line["time"].get<double>(), static_cast<double>(simulation.Steps()) / 60.0);
    }
    // Ended: asking again ends nothing; stepping on, the wheel's scrape begins again with a new id.
    EXPECT_TRUE(simulation.EndScrapes().empty());
    simulation.Step();
    std::uint32_t highest = 0;
    for (const EffectEvent& event : closing)
    {
        highest = std::max(highest, event.id);
    }
    bool began = false;
    for (const EffectEvent& event : simulation.GetEffects().Events())
    {
        EXPECT_FALSE(event.type == EffectEventType::scrapeChanged ||
                     event.type == EffectEventType::scrapeEnded)
            << "id " << event.id << " goes on after it ended";
        if (event.type == EffectEventType::scrapeBegan)
        {
            EXPECT_GT(event.id, highest);
            began = true;
        }
    }
    EXPECT_TRUE(began);
}

TEST(OpenScrapes, NoneBeforeTheFirstStepNorRightAfterReplacingTheEffects)
{
    Simulation simulation(GrinderFile());
    EXPECT_TRUE(simulation.EndScrapes().empty());
    for (int i = 0; i < 120; ++i)
    {
        simulation.Step();
    }
    simulation.ReplaceEffects(simulation.GetEffects().Config());
    EXPECT_TRUE(simulation.EndScrapes().empty()); // the old effects' scrapes went with them
}

} // namespace
} // namespace cfx
