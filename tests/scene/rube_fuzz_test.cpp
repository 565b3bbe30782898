// A small deterministic fuzzer: mutated sample files must load or be rejected with diagnostics, never crash
// or reach a Box2D assert (which would abort this test binary). What loads must also step and save.
#include "scene/rube_test_util.h"

#include <cstdint>
#include <gtest/gtest.h>
#include <random>

namespace cfx
{
namespace
{

/// Loads, and when that works steps, saves and reloads. Returns whether the text loaded.
bool Exercise(const std::string& text)
{
    const std::vector<Diagnostic> diagnostics = ValidateRubeString(text, "fuzz.json");
    Scene scene;
    try
    {
        scene = LoadRubeString(text, "fuzz.json");
    }
    catch (const InputError& error)
    {
        EXPECT_FALSE(error.Diagnostics().empty());
        EXPECT_FALSE(diagnostics.empty()) << "Validate and Load disagree";
        return false;
    }
    EXPECT_TRUE(diagnostics.empty()) << test::Dump(diagnostics);
    for (int i = 0; i < 5; ++i)
    {
        scene.world->Step(1.0f / 60.0f, 8, 3);
    }
    try
    {
        const std::string saved = SaveRubeString(scene);
        LoadRubeString(saved, "resaved.json");
    }
    catch (const InputError&)
    {
        // Stepping may have driven a body to values the reader refuses (e.g. beyond the coordinate bound).
    }
    return true;
}

const std::vector<std::string>& Tokens()
{
    static const std::vector<std::string> tokens = {"0",
                                                    "-1",
                                                    "1e39",
                                                    "1e-39",
                                                    "3.4e38",
                                                    "-3.4e38",
                                                    "1e6",
                                                    "1000001",
                                                    "\"7FC00000\"",
                                                    "\"7F800000\"",
                                                    "\"FF800000\"",
                                                    "\"00000001\"",
                                                    "\"abc\"",
                                                    "null",
                                                    "true",
                                                    "false",
                                                    "[]",
                                                    "{}",
                                                    "[0]",
                                                    "{\"x\": 0}",
                                                    "2",
                                                    "65536",
                                                    "-32769",
                                                    "8",
                                                    "9",
                                                    "1e400",
                                                    "\"\"",
                                                    "0.0000001"};
    return tokens;
}

std::string MutateText(std::string text, std::mt19937& random)
{
    const int mutations = 1 + static_cast<int>(random() % 4);
    for (int m = 0; m < mutations && !text.empty(); ++m)
    {
        const std::size_t at = random() % text.size();
        switch (random() % 5)
        {
        case 0:
            text[at] = "{}[]:,\"0123456789-.eE xyntfal"[random() % 30];
            break;
        case 1:
            text.erase(at, 1 + random() % 16);
            break;
        case 2:
            text.insert(at, text.substr(at, random() % 64));
            break;
        case 3:
            text.insert(at, Tokens()[random() % Tokens().size()]);
            break;
        default:
            text.resize(at);
            break;
        }
    }
    return text;
}

/// Replaces a random leaf of the document (a number, string, boolean or vector) with a hostile value.
void MutateValue(nlohmann::json& document, std::mt19937& random)
{
    std::vector<nlohmann::json*> leaves;
    std::vector<nlohmann::json*> stack = {&document};
    while (!stack.empty())
    {
        nlohmann::json* value = stack.back();
        stack.pop_back();
        if (value->is_object() || value->is_array())
        {
            if (value->is_object() && value->contains("x") && value->contains("y"))
            {
                leaves.push_back(value);
            }
            for (auto& child : *value)
            {
                stack.push_back(&child);
            }
        }
        else
        {
            leaves.push_back(value);
        }
    }
    if (leaves.empty())
    {
        return;
    }
    nlohmann::json& leaf = *leaves[random() % leaves.size()];
    static const std::vector<nlohmann::json> values = {
        0,
        -1,
        1e-30,
        1e30,
        3e38,
        -3e38,
        999999.0,
        -999999.0,
        1e-7,
        "7FC00000",
        "7F800000",
        "00000001",
        "7F7FFFFF",
        "FF7FFFFF",
        "abc",
        nullptr,
        true,
        nlohmann::json::array(),
        nlohmann::json::object(),
        2,
        3,
        65535,
        65536,
        8,
        9,
        nlohmann::json::parse(R"({"x": 0, "y": 0})"),
        nlohmann::json::parse(R"({"x": 999999, "y": -999999})"),
        nlohmann::json::parse(R"({"x": [0, 0, 0], "y": [0, 0, 0]})"),
        nlohmann::json::parse(R"({"x": [0, 1e-3], "y": [0, 0]})"),
    };
    leaf = values[random() % values.size()];
}

class Fuzz : public ::testing::TestWithParam<std::filesystem::path>
{
};

TEST_P(Fuzz, MutatedTextNeverCrashes)
{
    const std::string text = test::ReadText(GetParam());
    std::mt19937 random(static_cast<std::uint32_t>(std::hash<std::string>{}(GetParam().filename().string())));
    for (int i = 0; i < 300; ++i)
    {
        Exercise(MutateText(text, random));
    }
}

TEST_P(Fuzz, MutatedValuesNeverCrash)
{
    const nlohmann::json original = test::ReadJson(GetParam());
    std::mt19937 random(static_cast<std::uint32_t>(std::hash<std::string>{}(GetParam().stem().string())) +
                        1u);
    for (int i = 0; i < 300; ++i)
    {
        nlohmann::json document = original;
        const int mutations = 1 + static_cast<int>(random() % 3);
        for (int m = 0; m < mutations; ++m)
        {
            MutateValue(document, random);
        }
        Exercise(document.dump());
    }
}

INSTANTIATE_TEST_SUITE_P(SharedFiles, Fuzz, ::testing::ValuesIn(test::SampleFiles()), test::SampleTestName);

/// Worlds built only from values the reader accepts, at the edges of what it accepts.
std::string ExtremeWorld(std::mt19937& random)
{
    auto pick = [&](std::initializer_list<double> values)
    {
        const double value = *(values.begin() + random() % values.size());
        return nlohmann::json(value);
    };
    auto coordinate = [&]() { return pick({0.0, 1.0, -1.0, 999999.0, -999999.0, 1e-6, 0.5}); };
    // The top of each range (docs/rube.md), or small values.
    auto upTo = [&](double max) { return pick({0.0, 1.0, 1e-30, 0.5 * max, max}); };
    auto speed = [&]() { return pick({0.0, 1.0, -1.0, 10000.0, -10000.0, 1e-6}); };
    auto vec = [&]() { return nlohmann::json{{"x", coordinate()}, {"y", coordinate()}}; };
    auto velocity = [&]() { return nlohmann::json{{"x", speed()}, {"y", speed()}}; };
    nlohmann::json world = {{"gravity", velocity()}, {"subStepping", random() % 2 == 0}};
    const int bodies = 2 + static_cast<int>(random() % 4);
    for (int b = 0; b < bodies; ++b)
    {
        nlohmann::json body = {{"type", static_cast<int>(random() % 3)},
                               {"position", vec()},
                               {"angle", coordinate()},
                               {"linearVelocity", velocity()},
                               {"angularVelocity", speed()},
                               {"awake", true},
                               {"linearDamping", upTo(1e3)},
                               {"angularDamping", upTo(1e3)},
                               {"gravityScale", pick({0.0, 1.0, -1000.0, 1000.0})},
                               {"bullet", random() % 2 == 0}};
        const int fixtures = 1 + static_cast<int>(random() % 3);
        for (int f = 0; f < fixtures; ++f)
        {
            nlohmann::json fixture = {
                {"density", upTo(1e6)}, {"friction", upTo(1e3)}, {"restitution", upTo(10.0)}};
            const double scale =
                pick({0.003, 1.0, 1000.0, 333333.0}).get<double>() * static_cast<double>(1 + random() % 3);
            switch (random() % 3)
            {
            case 0:
                fixture["circle"] = {{"radius", pick({0.001, 1.0, 999999.0})}, {"center", vec()}};
                break;
            case 1:
                fixture["polygon"] = {
                    {"vertices", {{"x", {scale, scale, -scale}}, {"y", {-scale, scale, 0.0}}}}};
                break;
            default:
                fixture["chain"] = {{"vertices", {{"x", {-scale, 0.0, scale}}, {"y", {0.0, -scale, 0.0}}}}};
                break;
            }
            body["fixture"].push_back(fixture);
        }
        world["body"].push_back(body);
    }
    static const char* kTypes[] = {"revolute", "prismatic", "distance", "rope",     "pulley",
                                   "mouse",    "wheel",     "weld",     "friction", "motor"};
    const int joints = static_cast<int>(random() % 5);
    for (int j = 0; j < joints; ++j)
    {
        const int a = static_cast<int>(random() % bodies);
        const int b = (a + 1 + static_cast<int>(random() % (bodies - 1))) % bodies;
        nlohmann::json joint = {{"type", kTypes[random() % 10]},
                                {"bodyA", a},
                                {"bodyB", b},
                                {"anchorA", vec()},
                                {"anchorB", vec()},
                                {"enableMotor", true},
                                {"motorSpeed", speed()},
                                {"maxMotorTorque", upTo(1e12)},
                                {"maxMotorForce", upTo(1e12)},
                                {"maxForce", upTo(1e12)},
                                {"maxTorque", upTo(1e12)},
                                {"frequency", upTo(1e4)},
                                {"dampingRatio", upTo(1e3)},
                                {"springFrequency", upTo(1e4)},
                                {"springDampingRatio", upTo(1e3)},
                                {"length", pick({0.0, 1.0, 999999.0})},
                                {"maxLength", pick({0.0, 5.0})},
                                {"lengthA", 1.0},
                                {"lengthB", 1.0},
                                {"ratio", pick({1e-30, 1.0, 1000.0})},
                                {"target", vec()},
                                {"enableLimit", true},
                                {"lowerLimit", -1.0},
                                {"upperLimit", 1.0},
                                {"correctionFactor", 1.0}};
        world["joint"].push_back(joint);
    }
    return world.dump();
}

TEST(FuzzEdges, ExtremeAcceptedValuesStep)
{
    std::mt19937 random(20240601u);
    int loaded = 0;
    for (int i = 0; i < 1500; ++i)
    {
        loaded += Exercise(ExtremeWorld(random)) ? 1 : 0;
    }
    EXPECT_GT(loaded, 100);
}

TEST(FuzzEdges, HostileShapesOfInput)
{
    Exercise(std::string(100000, '['));
    Exercise(std::string(100000, '[') + std::string(100000, ']'));
    Exercise("{\"body\": [" + std::string(50000, '{') + "]}");
    std::string manyErrors = "{\"body\": [";
    for (int i = 0; i < 20000; ++i)
    {
        manyErrors += std::string(i == 0 ? "" : ",") + "{\"type\": \"x\"}";
    }
    manyErrors += "]}";
    const auto diagnostics = ValidateRubeString(manyErrors, "many.json");
    EXPECT_LE(diagnostics.size(), 1000u);
    EXPECT_FALSE(Exercise("\xEF\xBB\xBF{\"body\": \"\xFF\xFE\"}"));
    EXPECT_FALSE(Exercise(std::string("{\"a\": 1}\0", 9)));
    EXPECT_TRUE(Exercise("{}"));
}

} // namespace
} // namespace cfx
