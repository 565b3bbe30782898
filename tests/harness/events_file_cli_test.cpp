// The CLI's events file ends every scrape it begins: the scrapes still open when the run stops end at the
// run's end time with the reason "run_ended" (docs/events.md), from Simulation::OpenScrapesEnded.
#include "cli/cli_support.h"
#include "scenes_dir.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace cfx::test
{

TEST(EventsFile, EveryScrapeThatBeganEndsAndThoseOpenAtTheEndEndAtTheRunsEnd)
{
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "contactfx_test_events_file";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::filesystem::path events = dir / "g.jsonl";
    const CliResult result =
        RunCli("run " + (kScenesDir / "grinder.json").string() + " --seconds 2 --events " + events.string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::ifstream in(events);
    std::map<std::uint64_t, int> ends; // scrape id -> scrape_ended lines
    int endedByTheRun = 0;
    std::string text;
    while (std::getline(in, text))
    {
        const nlohmann::json line = nlohmann::json::parse(text);
        const std::string type = line["type"];
        if (type == "scrape_began")
        {
            EXPECT_TRUE(ends.emplace(line["id"].get<std::uint64_t>(), 0).second) << text;
        }
        else if (type == "scrape_ended")
        {
            ASSERT_TRUE(ends.contains(line["id"].get<std::uint64_t>())) << text;
            ++ends[line["id"].get<std::uint64_t>()];
            if (line["reason"] == "run_ended")
            {
                ++endedByTheRun;
                EXPECT_DOUBLE_EQ(line["time"].get<double>(), 2.0) << text;
                EXPECT_EQ(line["step"], 119) << text;
            }
        }
        else if (endedByTheRun > 0)
        {
            ADD_FAILURE() << "after the run's end: " << text;
        }
    }
    EXPECT_GT(endedByTheRun, 0); // the grinder's wheel still grinds at 2 s
    for (const auto& [id, count] : ends)
    {
        EXPECT_EQ(count, 1) << "scrape " << id;
    }
    std::filesystem::remove_all(dir);
}

} // namespace cfx::test
