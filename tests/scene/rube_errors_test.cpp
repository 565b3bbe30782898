// Bad input: every problem is reported with file, JSON path, what was expected and what was found, and
// nothing reaches a Box2D assert.
#include "scene/rube_test_util.h"

#include <gtest/gtest.h>
#include <unistd.h>

namespace cfx
{
namespace
{

using test::Box;
using test::HasDiagnostic;
using test::LoadErrors;
using test::World;

std::string OneFixture(const std::string& fixture, int type = 2)
{
    return World(R"({"type": )" + std::to_string(type) + R"(, "fixture": [)" + fixture + "]}");
}

std::string Polygon(const std::string& xs, const std::string& ys)
{
    return OneFixture(R"({"density": 1, "polygon": {"vertices": {"x": [)" + xs + R"(], "y": [)" + ys +
                      "]}}}");
}

TEST(RubeErrors, TruncatedJsonHasLineAndColumn)
{
    const std::string text = test::ReadText(test::ProjectScene("grinder.json"));
    const std::string truncated = text.substr(0, text.size() / 2);
    auto diagnostics = LoadErrors(truncated);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].file, "test.json");
    EXPECT_GT(diagnostics[0].line, 1);
    EXPECT_GT(diagnostics[0].column, 0);
    EXPECT_NE(diagnostics[0].message.find("malformed JSON"), std::string::npos);
    EXPECT_NE(diagnostics[0].ToString().find("test.json:" + std::to_string(diagnostics[0].line) + ":"),
              std::string::npos);
}

TEST(RubeErrors, MalformedJsonInTheMiddle)
{
    auto diagnostics = LoadErrors("{\n  \"body\": [\n    {\"type\": 2,, }\n  ]\n}");
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].line, 3);
    EXPECT_EQ(diagnostics[0].column, 16);
}

TEST(RubeErrors, EmptyTextAndWrongTopLevel)
{
    EXPECT_EQ(LoadErrors("").at(0).line, 1);
    auto diagnostics = LoadErrors("[1, 2]");
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].message, "expected a JSON object at the top level, found an array");
}

TEST(RubeErrors, WrongTypesNameThePathAndWhatWasFound)
{
    auto diagnostics = LoadErrors(OneFixture(R"({"friction": "abc", "circle": {"radius": 1}})"));
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].file, "test.json");
    EXPECT_EQ(diagnostics[0].path, "body[0].fixture[0].friction");
    EXPECT_EQ(diagnostics[0].message, "expected a number, found string \"abc\"");
    EXPECT_EQ(diagnostics[0].ToString(),
              "test.json: body[0].fixture[0].friction: expected a number, found string \"abc\"");

    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"type": "dynamic"})")), "body[0].type",
                              "expected an integer, found string \"dynamic\""));
    EXPECT_TRUE(
        HasDiagnostic(LoadErrors(World(R"({"position": [1, 2]})")), "body[0].position", "expected a vector"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"bullet": 1})")), "body[0].bullet",
                              "expected true or false, found number 1"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"body": {}})"), "body", "expected an array, found an object"));
    EXPECT_TRUE(
        HasDiagnostic(LoadErrors(R"({"body": [3]})"), "body[0]", "expected an object, found number 3"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"name": 5})")), "body[0].name", "expected a string"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"fixture": [{"density": 1}]})")), "body[0].fixture[0]",
                              "expected a shape"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"circle": 1})")), "body[0].fixture[0].circle",
                              "expected an object"));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(OneFixture(R"({"circle": {"radius": 1}, "polygon": {"vertices": {"x": [], "y": []}}})")),
        "body[0].fixture[0]", "expected one shape"));
    EXPECT_TRUE(
        HasDiagnostic(LoadErrors(OneFixture(R"({"polygon": {"vertices": {"x": [0, 1, 1], "y": [0, 0]}}})")),
                      "body[0].fixture[0].polygon.vertices", "as many y as x"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"customProperties": [{"name": "a", "int": 1.5}]})"),
                              "customProperties[0].int", "expected an integer, found number 1.5"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"customProperties": [{"name": "a"}]})"), "customProperties[0]",
                              "expected a value"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"customProperties": [{"name": "a", "color": [1, 2, 3]}]})"),
                              "customProperties[0].color", "expected a color"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"customProperties": [{"name": "a", "color": [1, 2, 3, 300]}]})"),
                              "customProperties[0].color[3]", "between 0 and 255"));
}

TEST(RubeErrors, NanAndInfinities)
{
    for (const char* value : {R"("7FC00000")", R"("7F800000")", R"("FF800000")", R"("ffc00001")"})
    {
        SCOPED_TRACE(value);
        auto diagnostics = LoadErrors(World(std::string(R"({"angle": )") + value + "}"));
        ASSERT_EQ(diagnostics.size(), 1u);
        EXPECT_EQ(diagnostics[0].path, "body[0].angle");
        EXPECT_NE(diagnostics[0].message.find("expected a finite number"), std::string::npos);
    }
    // Plain JSON has no NaN: nlohmann rejects the literals, and numbers beyond the float range are reported.
    EXPECT_GT(LoadErrors(World(R"({"angle": NaN})")).at(0).line, 0);
    EXPECT_GT(LoadErrors(World(R"({"angle": Infinity})")).at(0).line, 0);
    EXPECT_GT(LoadErrors(World(R"({"angle": 1e400})")).at(0).line, 0);
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"position": {"x": 1e39, "y": 0}})")), "body[0].position.x",
                              "float range"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"position": {"x": 1e30, "y": 0}})")), "body[0].position.x",
                              "between -1e+06 and 1e+06"));
}

TEST(RubeErrors, NumbersOutOfRange)
{
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"density": -1, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].density", "expected a number >= 0, found -1"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"circle": {"radius": 0}})")),
                              "body[0].fixture[0].circle.radius", "found 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"circle": {"radius": -2}})")),
                              "body[0].fixture[0].circle.radius", "> 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"circle": {}})")), "body[0].fixture[0].circle.radius",
                              "missing"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"friction": -0.1, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].friction", ">= 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"restitution": -1, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].restitution", ">= 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"type": 3})")), "body[0].type",
                              "expected an integer between 0 and 2, found number 3"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"type": -1})")), "body[0].type"));
    EXPECT_TRUE(
        HasDiagnostic(LoadErrors(OneFixture(R"({"filter-categoryBits": 65536, "circle": {"radius": 1}})")),
                      "body[0].fixture[0].filter-categoryBits", "between 0 and 65535"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"filter-maskBits": -1, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].filter-maskBits", "between 0 and 65535"));
    EXPECT_TRUE(
        HasDiagnostic(LoadErrors(OneFixture(R"({"filter-groupIndex": 40000, "circle": {"radius": 1}})")),
                      "body[0].fixture[0].filter-groupIndex"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"linearDamping": -1})")), "body[0].linearDamping"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"massData-mass": -1})")), "body[0].massData-mass"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"stepsPerSecond": 0})"), "stepsPerSecond", "> 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"velocityIterations": -1})"), "velocityIterations"));
}

TEST(RubeErrors, BadPolygons)
{
    EXPECT_TRUE(
        HasDiagnostic(LoadErrors(Polygon("0", "0")), "body[0].fixture[0].polygon.vertices", "found 1"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("", "")), "body[0].fixture[0].polygon.vertices", "found 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("1, 0.77, 0, -0.77, -1, -0.77, 0, 0.77, 0.9",
                                                 "0, 0.77, 1, 0.77, 0, -0.77, -1, -0.77, -0.3")),
                              "body[0].fixture[0].polygon.vertices", "found 9"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("0, 1, 2", "0, 0, 0")),
                              "body[0].fixture[0].polygon.vertices", "collinear"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("0, 1, 1, 1.0001", "0, 0, 1, 1")),
                              "body[0].fixture[0].polygon.vertices", "closer"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("0, 2, 0, 0.5", "0, 1, 2, 1")),
                              "body[0].fixture[0].polygon.vertices", "not convex"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("0, 1, 0.5", "0, 0, 0.000001")),
                              "body[0].fixture[0].polygon.vertices", "collinear"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("0, 0.001", "0, 0")), "body[0].fixture[0].polygon.vertices",
                              "degenerate edge"));
}

TEST(RubeErrors, BadEdgesAndChains)
{
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(OneFixture(R"({"edge": {"vertex1": {"x": 1, "y": 1}, "vertex2": {"x": 1, "y": 1}}})")),
        "body[0].fixture[0].edge", "degenerate edge"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"edge": {"vertex1": 0}})")),
                              "body[0].fixture[0].edge.vertex2", "missing"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"chain": {"vertices": {"x": [1], "y": [1]}}})")),
                              "body[0].fixture[0].chain.vertices", "at least 2"));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(OneFixture(R"({"chain": {"vertices": {"x": [0, 1, 1, 2], "y": [0, 0, 0, 0]}}})")),
        "body[0].fixture[0].chain.vertices", "vertices 1 and 2"));
    EXPECT_TRUE(
        HasDiagnostic(LoadErrors(OneFixture(
                          R"({"chain": {"vertices": {"x": [0, 1], "y": [0, 0]}, "hasPrevVertex": true}})")),
                      "body[0].fixture[0].chain.prevVertex", "missing"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"loop": {"vertices": {"x": [0, 1], "y": [0, 0]}}})")),
                              "body[0].fixture[0].loop.vertices", "at least 3"));
}

TEST(RubeErrors, BadJointReferences)
{
    const std::string bodies = Box(0.0f) + "," + Box(3.0f) + "," + Box(0.0f, 0);
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, R"({"type": "revolute", "bodyA": 0, "bodyB": 7})")),
                              "joint[0].bodyB", "between 0 and 2, found number 7"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, R"({"type": "revolute", "bodyA": -1, "bodyB": 1})")),
                              "joint[0].bodyA"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, R"({"type": "revolute", "bodyA": 1, "bodyB": 1})")),
                              "joint[0].bodyB", "other than bodyA"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, R"({"type": "revolute", "bodyA": 1})")),
                              "joint[0].bodyB", "missing"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World("", R"({"type": "revolute", "bodyA": 0, "bodyB": 1})")),
                              "joint[0].bodyA", "the file has none"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, R"({"type": "spring", "bodyA": 0, "bodyB": 1})")),
                              "joint[0].type", "found string \"spring\""));
    EXPECT_TRUE(
        HasDiagnostic(LoadErrors(World(bodies, R"({"bodyA": 0, "bodyB": 1})")), "joint[0].type", "missing"));

    const std::string revolutes = R"({"type": "revolute", "bodyA": 2, "bodyB": 0},
        {"type": "revolute", "bodyA": 2, "bodyB": 1}, {"type": "distance", "bodyA": 0, "bodyB": 1},
        {"type": "revolute", "bodyA": 0, "bodyB": 2})";
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(bodies, revolutes + R"(, {"type": "gear", "bodyA": 0, "bodyB": 1, "joint1": 0,
            "joint2": 9})")),
        "joint[4].joint2", "between 0 and 4"));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(bodies, revolutes + R"(, {"type": "gear", "bodyA": 0, "bodyB": 1, "joint1": 0,
            "joint2": 2})")),
        "joint[4].joint2", "expected a revolute or prismatic joint, found joint[2] of type \"distance\""));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(bodies, revolutes + R"(, {"type": "gear", "bodyA": 0, "bodyB": 1, "joint1": 0,
            "joint2": 4})")),
        "joint[4].joint2", "the gear joint itself"));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(bodies, revolutes + R"(, {"type": "gear", "bodyA": 0, "bodyB": 1, "joint1": 0,
            "joint2": 3})")),
        "joint[4].joint2", "static bodyB"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, R"({"type": "gear", "bodyA": 0, "bodyB": 1})")),
                              "joint[0].joint1", "missing"));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(bodies, R"({"type": "prismatic", "bodyA": 0, "bodyB": 1, "localAxisA": 0})")),
        "joint[0].localAxisA", "non-zero axis"));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(bodies, R"({"type": "revolute", "bodyA": 0, "bodyB": 1, "lowerLimit": 1,
            "upperLimit": -1})")),
        "joint[0].upperLimit", ">= lowerLimit"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, R"({"type": "pulley", "bodyA": 0, "bodyB": 1,
        "ratio": 0})")),
                              "joint[0].ratio", "> 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, R"({"type": "mouse", "bodyA": 2, "bodyB": 0,
        "maxForce": -1})")),
                              "joint[0].maxForce", ">= 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, R"({"type": "motor", "bodyA": 0, "bodyB": 1,
        "correctionFactor": 2})")),
                              "joint[0].correctionFactor", "between 0 and 1"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(bodies, "", R"("image": [{"body": 3}])")), "image[0].body"));
}

TEST(RubeErrors, SeveralErrorsAreAllReported)
{
    const std::string json = World(R"({"type": 5, "fixture": [{"friction": "abc", "circle": {"radius": -1}},
        {"density": -1, "polygon": {"vertices": {"x": [0], "y": [0]}}}]}, {"angle": "7FC00000"})",
                                   R"({"type": "weld", "bodyA": 0, "bodyB": 9})");
    auto diagnostics = LoadErrors(json);
    EXPECT_GE(diagnostics.size(), 7u) << test::Dump(diagnostics);
    EXPECT_TRUE(HasDiagnostic(diagnostics, "body[0].type"));
    EXPECT_TRUE(HasDiagnostic(diagnostics, "body[0].fixture[0].friction"));
    EXPECT_TRUE(HasDiagnostic(diagnostics, "body[0].fixture[0].circle.radius"));
    EXPECT_TRUE(HasDiagnostic(diagnostics, "body[0].fixture[1].density"));
    EXPECT_TRUE(HasDiagnostic(diagnostics, "body[0].fixture[1].polygon.vertices"));
    EXPECT_TRUE(HasDiagnostic(diagnostics, "body[1].angle"));
    EXPECT_TRUE(HasDiagnostic(diagnostics, "joint[0].bodyB"));
    for (const Diagnostic& diagnostic : diagnostics)
    {
        EXPECT_EQ(diagnostic.file, "test.json");
    }

    try
    {
        LoadRubeString(json, "several.json");
        FAIL();
    }
    catch (const InputError& error)
    {
        EXPECT_EQ(std::string(error.what()), error.Diagnostics().front().ToString());
        EXPECT_NE(std::string(error.what()).find("several.json"), std::string::npos);
    }
}

TEST(RubeErrors, ValidateReportsWithoutThrowing)
{
    SceneCounts counts;
    auto diagnostics = ValidateRubeString(
        World(Box(0.0f) + R"(, {"type": 7, "fixture": [{"circle": {"radius": 1}}, {"circle": 3}]})"),
        "v.json", &counts);
    EXPECT_EQ(diagnostics.size(), 2u) << test::Dump(diagnostics);
    EXPECT_EQ(counts.bodies, 2);
    EXPECT_EQ(counts.fixtures, 3);
    EXPECT_TRUE(ValidateRubeString(World(Box(0.0f)), "ok.json").empty());
}

TEST(RubeErrors, MissingFileNamesThePath)
{
    const std::filesystem::path missing =
        std::filesystem::temp_directory_path() / "contactfx_no_such_file.json";
    try
    {
        LoadRubeFile(missing);
        FAIL();
    }
    catch (const InputError& error)
    {
        EXPECT_EQ(error.Diagnostics().at(0).file, missing.string());
        EXPECT_NE(error.Diagnostics().at(0).message.find("cannot open"), std::string::npos);
    }
    auto diagnostics = ValidateRubeFile(missing);
    ASSERT_EQ(diagnostics.size(), 1u);
    EXPECT_EQ(diagnostics[0].file, missing.string());
}

TEST(RubeErrors, MassFarFromTheBodyOriginIsReportedNotAsserted)
{
    // A tiny dense circle far from its body's origin: Box2D's inertia about the centre of mass cancels out.
    auto diagnostics = LoadErrors(World(R"({"type": 2, "fixture": [{"density": 1,
        "circle": {"radius": 0.001, "center": {"x": 900000, "y": 0}}}]})"));
    EXPECT_TRUE(HasDiagnostic(diagnostics, "body[0].fixture", "rotational inertia"))
        << test::Dump(diagnostics);

    auto saved = LoadErrors(World(R"({"type": 2, "massData-mass": 10, "massData-center": {"x": 5, "y": 0},
        "massData-I": 1, "fixture": [{"density": 1, "circle": {"radius": 1}}]})"));
    EXPECT_TRUE(HasDiagnostic(saved, "body[0].massData-I", "rotational inertia")) << test::Dump(saved);

    // With fixed rotation there is nothing to subtract.
    EXPECT_NO_THROW(LoadRubeString(World(R"({"type": 2, "fixedRotation": true, "massData-mass": 10,
        "massData-center": {"x": 5, "y": 0}, "massData-I": 1, "fixture": [{"density": 1,
        "circle": {"radius": 1}}]})"),
                                   "fixed.json"));
}

TEST(RubeErrors, SpringsTooStiffAreReported)
{
    const std::string heavy = R"({"type": 2, "awake": true, "fixture": [{"density": 1e30,
        "polygon": {"vertices": {"x": [0.5, 0.5, -0.5, -0.5], "y": [-0.5, 0.5, 0.5, -0.5]}}}]})";
    auto diagnostics = LoadErrors(World(heavy + "," + heavy, R"({"type": "distance", "bodyA": 0, "bodyB": 1,
        "length": 1, "frequency": 1e6, "dampingRatio": 1})"));
    EXPECT_TRUE(HasDiagnostic(diagnostics, "joint[0].frequency", "too stiff")) << test::Dump(diagnostics);
}

class SaveFailure : public ::testing::Test
{
protected:
    void SetUp() override
    {
        m_dir = std::filesystem::temp_directory_path() /
                ("contactfx_save_test_" + std::to_string(::getpid()) + "_" +
                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(m_dir);
        std::filesystem::create_directories(m_dir);
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }

    std::size_t EntriesIn(const std::filesystem::path& dir) const
    {
        return static_cast<std::size_t>(
            std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()));
    }

    std::filesystem::path m_dir;
};

TEST_F(SaveFailure, MissingDirectoryThrowsNamingThePath)
{
    Scene scene = LoadRubeString(World(Box(0.0f)), "s.json");
    const std::filesystem::path target = m_dir / "missing" / "out.json";
    try
    {
        SaveRubeFile(scene, target);
        FAIL();
    }
    catch (const InputError& error)
    {
        EXPECT_EQ(error.Diagnostics().at(0).file, target.string());
    }
    EXPECT_FALSE(std::filesystem::exists(m_dir / "missing"));
    EXPECT_EQ(EntriesIn(m_dir), 0u);
}

TEST_F(SaveFailure, TargetThatIsADirectoryLeavesNothingBehind)
{
    Scene scene = LoadRubeString(World(Box(0.0f)), "s.json");
    const std::filesystem::path target = m_dir / "taken";
    std::filesystem::create_directory(target);
    EXPECT_THROW(SaveRubeFile(scene, target), InputError);
    EXPECT_EQ(EntriesIn(m_dir), 1u); // only the directory; no temporary file
    EXPECT_TRUE(std::filesystem::is_directory(target));
}

TEST_F(SaveFailure, ParentThatIsAFileThrows)
{
    Scene scene = LoadRubeString(World(Box(0.0f)), "s.json");
    const std::filesystem::path file = m_dir / "plain";
    {
        std::ofstream(file) << "x";
    }
    EXPECT_THROW(SaveRubeFile(scene, file / "out.json"), InputError);
    EXPECT_EQ(EntriesIn(m_dir), 1u);
    EXPECT_EQ(test::ReadText(file), "x");
}

TEST_F(SaveFailure, SuccessfulSaveReplacesTheFileWholly)
{
    Scene scene = LoadRubeString(World(Box(0.0f)), "s.json");
    const std::filesystem::path target = m_dir / "out.json";
    {
        std::ofstream(target) << "old";
    }
    SaveRubeFile(scene, target);
    EXPECT_EQ(EntriesIn(m_dir), 1u);
    EXPECT_EQ(test::ReadText(target), SaveRubeString(scene));
    EXPECT_EQ(LoadRubeFile(target).bodies.size(), 1u);
}

TEST(RubeErrors, SavingNonFiniteValuesThrows)
{
    Scene scene = LoadRubeString(World(Box(0.0f)), "s.json");
    scene.bodies[0].body->SetLinearVelocity(b2Vec2(std::numeric_limits<float>::quiet_NaN(), 0.0f));
    try
    {
        SaveRubeString(scene);
        FAIL();
    }
    catch (const InputError& error)
    {
        EXPECT_TRUE(HasDiagnostic(error.Diagnostics(), "body[0].linearVelocity.x", "finite"));
    }
}

} // namespace
} // namespace cfx
