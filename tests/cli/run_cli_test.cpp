#include "cli/cli_support.h"

#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace cfx::test
{

namespace
{

// A failing command: exit 1, one line naming `expected` (file and field), no stats file.
void ExpectRefused(const std::string& args, const std::filesystem::path& stats,
                   const std::vector<std::string>& expected)
{
    CliResult result = RunCli(args + " --stats " + stats.string());
    EXPECT_EQ(result.exitCode, 1) << args << "\n" << result.output;
    for (const std::string& word : expected)
    {
        EXPECT_NE(result.output.find(word), std::string::npos)
            << "'" << word << "' missing in: " << result.output;
    }
    EXPECT_EQ(result.output.find("terminate"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(stats)) << "stats written by a failed run: " << args;
}

} // namespace

TEST(CliRun, DemoPrintsASummaryAndWritesStats)
{
    std::filesystem::path dir = ScratchDir("demo");
    CliResult result = RunCli("demo --seconds 3 --stats " + (dir / "stats.json").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("spawned:"), std::string::npos);
    nlohmann::json stats = nlohmann::json::parse(FileText(dir / "stats.json"));
    EXPECT_EQ(stats["steps"], 180);
    EXPECT_EQ(stats["hz"], 60.0);
    EXPECT_EQ(stats["seconds"], 3.0);
    for (const char* type : {"smoke", "sparks", "dirt"})
    {
        EXPECT_TRUE(stats["spawned"].contains(type)) << type;
    }
    for (const char* rule : {"concrete+steel", "concrete+rubber", "dirt+steel", "dirt+rubber"})
    {
        ASSERT_TRUE(stats["rules"].contains(rule)) << rule;
        EXPECT_TRUE(stats["rules"][rule].contains("contacts_max"));
        EXPECT_TRUE(stats["rules"][rule].contains("spawned"));
    }
    EXPECT_TRUE(stats.contains("live_max"));
    EXPECT_EQ(stats["spawned_inside_solid"], 0);
    EXPECT_EQ(stats["static_geometry_builds"], 1) << "the tutorial's ground never changes";
}

// Each rule's "impacts" in the stats file counts its impact events, as the events file lists them.
TEST(CliRun, StatsCountEachRulesImpactsAsTheEventsFileLists)
{
    std::filesystem::path dir = ScratchDir("impacts");
    CliResult result = RunCli("demo --seconds 8 --stats " + (dir / "stats.json").string() + " --events " +
                              (dir / "events.jsonl").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(FileText(dir / "stats.json"));
    std::map<std::string, std::uint64_t> listed;
    std::map<std::string, double> fastest, strongest;
    std::istringstream lines(FileText(dir / "events.jsonl"));
    for (std::string line; std::getline(lines, line);)
    {
        const nlohmann::json event = nlohmann::json::parse(line);
        const std::string pair = event["pair"].get<std::string>();
        if (event["type"] == "impact")
        {
            ++listed[pair];
            fastest[pair] = std::max(fastest[pair], event["approach_speed"].get<double>());
        }
        else if (event.contains("intensity") && event["intensity"].is_number()) // scrapes
        {
            strongest[pair] = std::max(strongest[pair], event["intensity"].get<double>());
        }
    }
    std::uint64_t total = 0;
    std::uint64_t rejected = 0;
    for (const auto& [rule, counts] : stats["rules"].items())
    {
        EXPECT_EQ(counts["impacts"].get<std::uint64_t>(), listed[rule]) << rule;
        total += counts["impacts"].get<std::uint64_t>();
        rejected += counts["spawn_rejected"].get<std::uint64_t>();
        // The fastest new touch is the fastest impact when there was one (the others were slower).
        if (listed[rule] > 0)
        {
            EXPECT_EQ(counts["approach_max"].get<double>(), fastest[rule]) << rule;
        }
        // A scrape reports its pair's intensity, never above the largest a step saw.
        EXPECT_GE(counts["intensity_max"].get<double>(), strongest[rule]) << rule;
    }
    EXPECT_GT(total, 0u) << "the demo's tyres land on the concrete in its first 8 s";
    EXPECT_EQ(rejected, stats["spawn_rejected"].get<std::uint64_t>()) << "the rules' rejections add up";
}

TEST(CliRun, SameCommandTwiceWritesByteIdenticalStats)
{
    std::filesystem::path dir = ScratchDir("determinism");
    const std::string args =
        "run " + Scene("physics_driven_particles.json") + " --seconds 4 --seed 9 --stats ";
    ASSERT_EQ(RunCli(args + (dir / "a.json").string()).exitCode, 0);
    ASSERT_EQ(RunCli(args + (dir / "b.json").string()).exitCode, 0);
    EXPECT_EQ(FileText(dir / "a.json"), FileText(dir / "b.json"));
    ASSERT_EQ(RunCli("demo --seconds 4 --seed 3 --stats " + (dir / "c.json").string()).exitCode, 0);
    ASSERT_EQ(RunCli("demo --seconds 4 --seed 3 --stats " + (dir / "d.json").string()).exitCode, 0);
    EXPECT_EQ(FileText(dir / "c.json"), FileText(dir / "d.json"));
}

TEST(CliRun, TutorialPresetKeepsAtMostHundredParticles)
{
    std::filesystem::path dir = ScratchDir("tutorial");
    CliResult result = RunCli("run " + Scene("physics_driven_particles.json") +
                              " --preset tutorial --seconds 2 --stats " + (dir / "s.json").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    nlohmann::json stats = nlohmann::json::parse(FileText(dir / "s.json"));
    EXPECT_LE(stats["live_max"].get<int>(), 100);
}

// The summary's "recycled" is in the stats file too (a trial found it only in the summary): the grinder's
// sparks in a pool of 64 recycle most of what they spawn.
TEST(CliRun, TheStatsFileCountsTheRecycledParticles)
{
    const std::filesystem::path dir = ScratchDir("recycled");
    nlohmann::json config = nlohmann::json::parse(RunCli("preset default").output);
    config["budget"]["capacity"] = 64;
    std::ofstream(dir / "small.effects.json") << config.dump();
    const CliResult result =
        RunCli("run --scene grinder --seconds 2 --effects " + (dir / "small.effects.json").string() +
               " --stats " + (dir / "s.json").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const nlohmann::json stats = nlohmann::json::parse(FileText(dir / "s.json"));
    ASSERT_TRUE(stats.contains("recycled")) << stats.dump();
    EXPECT_GT(stats["recycled"].get<int>(), 100);
    EXPECT_NE(result.output.find("recycled " + std::to_string(stats["recycled"].get<int>())),
              std::string::npos)
        << result.output;
}

// A trial's rule bursting smoke was summarised as "-> sparks", with the smoke in its particles.
TEST(CliRun, TheSummaryNamesARulesBurstType)
{
    const std::filesystem::path dir = ScratchDir("burst_type");
    nlohmann::json config = nlohmann::json::parse(RunCli("preset default").output);
    config["rules"][0]["burstParticleType"] = "smoke";
    std::ofstream(dir / "burst.effects.json") << config.dump();
    const CliResult result =
        RunCli("run --scene grinder --seconds 0.1 --effects " + (dir / "burst.effects.json").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("concrete+steel     -> sparks, bursts smoke at most"), std::string::npos)
        << result.output;
    // One column, as wide as its widest entry.
    const std::string smoke = "concrete+rubber    -> smoke" + std::string(20 - 5, ' ') + " at most";
    EXPECT_NE(result.output.find(smoke), std::string::npos) << result.output;
}

TEST(CliRun, RunsAnyRubeSceneWithEffectsConfig)
{
    CONTACTFX_REQUIRE_RUBE_SAMPLES();
    std::filesystem::path dir = ScratchDir("any");
    CliResult result = RunCli("run " + Sample("car.json") + " --seconds 1 --effects " +
                              Scene("default.effects.json") + " --stats " + (dir / "s.json").string());
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "s.json"));
}

TEST(CliRun, EventsFileHasOneObjectPerLineForEveryEvent)
{
    std::filesystem::path dir = ScratchDir("events");
    ASSERT_EQ(RunCli("demo --seconds 12 --events " + (dir / "a.jsonl").string()).exitCode, 0);
    ASSERT_EQ(RunCli("demo --seconds 12 --events " + (dir / "b.jsonl").string()).exitCode, 0);
    const std::string text = FileText(dir / "a.jsonl");
    EXPECT_EQ(text, FileText(dir / "b.jsonl"));
    std::istringstream lines(text);
    std::string line;
    std::map<std::string, int> types;
    std::map<std::uint32_t, std::string> lastOfScrape;
    double lastTime = 0.0;
    while (std::getline(lines, line))
    {
        const nlohmann::json event = nlohmann::json::parse(line);
        const std::string type = event["type"];
        ++types[type];
        if (type == "particle_hits") // the step's particles of one type that hit one body
        {
            for (const char* key : {"step", "time", "particle_type", "count", "point", "mean_speed"})
            {
                ASSERT_TRUE(event.contains(key)) << key << " in " << line;
            }
            EXPECT_GE(event["count"].get<int>(), 1) << line;
            EXPECT_GT(event["mean_speed"].get<double>(), 0.0) << line;
            EXPECT_GE(event["time"].get<double>(), lastTime);
            lastTime = event["time"];
            continue;
        }
        for (const char* key : {"step", "time", "id", "pair", "point"})
        {
            ASSERT_TRUE(event.contains(key)) << key << " in " << line;
        }
        EXPECT_EQ(event["point"].size(), 2u);
        EXPECT_GE(event["time"].get<double>(), lastTime);
        lastTime = event["time"];
        const std::string pair = event["pair"];
        EXPECT_LT(pair.substr(0, pair.find('+')), pair.substr(pair.find('+') + 1)) << "names sorted";
        if (type == "impact")
        {
            EXPECT_GE(event["approach_speed"].get<double>(), 2.0);
            EXPECT_GT(event["normal_impulse"].get<double>(), 0.0);
            continue;
        }
        const std::uint32_t id = event["id"];
        const std::string previous = lastOfScrape[id];
        if (type == "scrape_began")
        {
            EXPECT_EQ(previous, "");
        }
        else
        {
            EXPECT_TRUE(previous == "scrape_began" || previous == "scrape_changed") << line;
        }
        if (type != "scrape_ended")
        {
            EXPECT_TRUE(event.contains("intensity")) << line;
            EXPECT_TRUE(event.contains("tangential_speed")) << line;
            EXPECT_TRUE(event.contains("normal_impulse")) << line;
        }
        else
        {
            EXPECT_TRUE(event.contains("reason")) << line;
        }
        lastOfScrape[id] = type;
    }
    EXPECT_GT(types["scrape_began"], 5);
    EXPECT_GT(types["scrape_changed"], 100);
    EXPECT_GT(types["scrape_ended"], 5);
    EXPECT_GT(types["impact"], 2);
    EXPECT_GT(types["particle_hits"], 10) << "dirt landing on the hills, sparks on the concrete";
}

TEST(CliRun, BadInputIsRefusedWithFileAndField)
{
    std::filesystem::path dir = ScratchDir("bad");
    const std::filesystem::path stats = dir / "stats.json";
    const std::string tutorial = Scene("physics_driven_particles.json");

    ExpectRefused("run " + (dir / "missing.json").string(), stats, {"missing.json"});
    WriteTestFile(dir / "truncated.json", "{\"gravity\": {\"x\": 0, \"y\": -10}, \"body\": [");
    ExpectRefused("run " + (dir / "truncated.json").string(), stats, {"truncated.json:1:"});
    WriteTestFile(dir / "wrongtype.json", R"({"body": [{"type": 2, "position": {"x": "abc", "y": 0}}]})");
    ExpectRefused("run " + (dir / "wrongtype.json").string(), stats,
                  {"wrongtype.json", "body[0].position.x"});

    std::ifstream in(tutorial);
    std::stringstream text;
    text << in.rdbuf();
    std::string glass = text.str();
    glass.replace(glass.find("\"string\": \"steel\""), 17, "\"string\": \"glass\"");
    WriteTestFile(dir / "glass.json", glass);
    ExpectRefused("run " + (dir / "glass.json").string(), stats, {"glass.json", "customProperties", "glass"});

    ExpectRefused("run " + tutorial + " --seconds abc", stats, {"--seconds"});
    ExpectRefused("run " + tutorial + " --seconds nan", stats, {"--seconds"});
    ExpectRefused("run " + tutorial + " --seconds -2", stats, {"--seconds"});
    ExpectRefused("run " + tutorial + " --hz 0", stats, {"--hz"});
    ExpectRefused("run " + tutorial + " --hz inf", stats, {"--hz"});
    ExpectRefused("demo --seed -1", stats, {"--seed"});
    ExpectRefused("run " + tutorial + " --preset fancy", stats, {"--preset"});

    WriteTestFile(dir / "negative.effects.json",
                  R"({"materials": ["steel"], "particleTypes": [{"name": "sparks", "radius": -0.5}]})");
    ExpectRefused("run " + tutorial + " --effects " + (dir / "negative.effects.json").string(), stats,
                  {"negative.effects.json", "particleTypes[0].radius"});
    WriteTestFile(dir / "nan.effects.json", R"({"particleTypes": [{"name": "sparks", "drag": "NaN"}]})");
    ExpectRefused("run " + tutorial + " --effects " + (dir / "nan.effects.json").string(), stats,
                  {"nan.effects.json", "particleTypes[0].drag"});
    WriteTestFile(dir / "unknown.effects.json",
                  R"({"materials": ["steel"], "particleTypes": [{"name": "sparks"}],
        "rules": [{"materialA": "steel", "materialB": "wood", "particleType": "sparks"}]})");
    ExpectRefused("run " + tutorial + " --effects " + (dir / "unknown.effects.json").string(), stats,
                  {"unknown.effects.json", "rules[0].materialB", "wood"});
}

// Seeds beyond 2^64-1 are refused, not saturated; 2^64-1 itself is a seed.
TEST(CliRun, SeedsBeyondTwoToTheSixtyFourAreRefused)
{
    const std::filesystem::path dir = ScratchDir("run_seed_range");
    for (const char* seed : {"18446744073709551616", "99999999999999999999999"})
    {
        ExpectRefused(std::string("demo --seconds 0.1 --seed ") + seed, dir / "stats.json",
                      {"--seed: expected a whole number from 0 to 2^64-1, found " + std::string(seed)});
    }
    const CliResult largest = RunCli("demo --seconds 0.1 --seed 18446744073709551615");
    EXPECT_EQ(largest.exitCode, 0) << largest.output;
    EXPECT_NE(largest.output.find("seed 18446744073709551615"), std::string::npos) << largest.output;
    // Decimal: CLI11 alone read "010" as octal 8.
    const CliResult zeros = RunCli("demo --seconds 0.1 --seed 010");
    EXPECT_EQ(zeros.exitCode, 0) << zeros.output;
    EXPECT_NE(zeros.output.find("seed 10\n"), std::string::npos) << zeros.output;
}

// A rejected number is shown as given (shortest round trip), never rounded into its range, and
// nothing follows it on its line.
TEST(CliRun, RangeErrorsShowTheValueAsGiven)
{
    const std::filesystem::path stats = ScratchDir("run_range_text") / "stats.json";
    ExpectRefused("run --scene grinder --hz 0.9999999", stats,
                  {"--hz: expected a number in [1, 10000], found 0.9999999\n"});
    ExpectRefused("run --scene grinder --seconds 86400.0000001", stats,
                  {"--seconds: expected a number in (0, 86400], found 86400.0000001\n"});
    ExpectRefused("run --scene grinder --seconds -5", stats, {"found -5\n"});
    ExpectRefused("run --scene grinder --hz nan", stats, {"found nan\n"});
    // Decimal only: CLI11 alone read "0x10" as 16 s.
    ExpectRefused("run --scene grinder --seconds 0x10", stats,
                  {"--seconds: expected a number in decimal, found \"0x10\"\n"});
    ExpectRefused("render --scene grinder --fps 0X1p4 --out " + (stats.parent_path() / "f_%d.png").string(),
                  stats, {"--fps: expected a number in decimal"});
}

// round(seconds * hz) steps: a --seconds below half a step at that --hz would simulate nothing, which is
// refused, saying why; half a step or more is one step.
TEST(CliRun, SecondsThatMakeNoStepAreRefused)
{
    const std::filesystem::path dir = ScratchDir("run_no_step");
    ExpectRefused(
        "run --scene grinder --hz 1 --seconds 0.1", dir / "z.json",
        {"--seconds: 0.1 s at --hz 1 is less than half a step (0.5 s)", "give --seconds 0.5 or more"});
    ExpectRefused("demo --hz 60 --seconds 0.008", dir / "z.json", {"--seconds: 0.008 s at --hz 60"});
    const CliResult one =
        RunCli("run --scene grinder --hz 1 --seconds 0.5 --stats " + (dir / "one.json").string());
    ASSERT_EQ(one.exitCode, 0) << one.output;
    EXPECT_EQ(nlohmann::json::parse(FileText(dir / "one.json"))["steps"], 1);

    // The --seconds the refusal suggests is taken: at --hz 103 half a step, 0.5 / 103, times 103 rounds
    // to just under a half in doubles, and a trial's suggestion was itself refused.
    for (const char* hz : {"103", "107", "239"})
    {
        SCOPED_TRACE(hz);
        const CliResult refused = RunCli(std::string("run --scene grinder --seconds 1e-9 --hz ") + hz);
        ASSERT_NE(refused.exitCode, 0);
        const std::string::size_type at = refused.output.find("give --seconds ");
        ASSERT_NE(at, std::string::npos) << refused.output;
        const std::string suggested =
            refused.output.substr(at + 15, refused.output.find(' ', at + 15) - (at + 15));
        const CliResult taken = RunCli("run --scene grinder --seconds " + suggested + " --hz " + hz +
                                       " --stats " + (dir / "least.json").string());
        ASSERT_EQ(taken.exitCode, 0) << taken.output;
        EXPECT_EQ(nlohmann::json::parse(FileText(dir / "least.json"))["steps"], 1);
    }
}

// The summary names the rate the run stepped at, as given (it printed 59.94 as 60).
TEST(CliRun, TheSummaryNamesTheStepRateAsGiven)
{
    const CliResult result = RunCli("run --scene tutorial --seconds 1 --hz 59.94");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("default effects, 59.94 Hz, 1.00 s (60 steps)"), std::string::npos)
        << result.output;
}

} // namespace cfx::test
