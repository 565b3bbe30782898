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
                              "body[0].fixture[0].density",
                              "expected a number between 0 and 1e+06, found -1"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"circle": {"radius": 0}})")),
                              "body[0].fixture[0].circle.radius", "found 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"circle": {"radius": -2}})")),
                              "body[0].fixture[0].circle.radius", "> 0"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"circle": {}})")), "body[0].fixture[0].circle.radius",
                              "missing"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"friction": -0.1, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].friction", "between 0 and 1000"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"restitution": -1, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].restitution", "between 0 and 10"));
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

TEST(RubeErrors, TheDocumentedLimitsThemselvesLoad)
{
    // docs/rube.md: massData-I 0 .. 1e24, massData-mass 0 .. 1e12 (1e24 as a float is above 1e24).
    EXPECT_NO_THROW(LoadRubeString(World(R"({"type": 2, "massData-mass": 1e12, "massData-I": 1e24,
        "fixture": [{"density": 1e6, "friction": 1000, "restitution": 10, "circle": {"radius": 1}}]})"),
                                   "test.json"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"type": 2, "massData-mass": 1, "massData-I": 1.01e24})")),
                              "body[0].massData-I", "between 0 and 1e+24, found 1.01e+24"));
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
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("0, 1, 1.001", "0, 0, 0.001")),
                              "body[0].fixture[0].polygon.vertices", "only 2 vertices are left"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("0, 0.01, 0.005", "0, 0, 0.000001")),
                              "body[0].fixture[0].polygon.vertices", "area"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(Polygon("0, 0.001", "0, 0")), "body[0].fixture[0].polygon.vertices",
                              "degenerate edge"));
}

// What Box2D accepts loads, and the vertices it drops are warnings under the polygon's path.
TEST(RubeErrors, PolygonsBox2DRepairsLoadWithWarnings)
{
    std::vector<Diagnostic> warnings;
    const std::string welded = Polygon("0, 1, 1, 1.0001", "0, 0, 1, 1");
    EXPECT_TRUE(ValidateRubeString(welded, "test.json", nullptr, &warnings).empty());
    ASSERT_EQ(warnings.size(), 1U) << test::Dump(warnings);
    EXPECT_EQ(warnings[0].path, "body[0].fixture[0].polygon.vertices");
    EXPECT_TRUE(warnings[0].warning);
    EXPECT_NE(warnings[0].message.find("vertex 3 is closer than b2_linearSlop/2 (0.0025) to vertex 2"),
              std::string::npos);
    EXPECT_NE(
        warnings[0].ToString().find("test.json: body[0].fixture[0].polygon.vertices: warning: vertex 3"),
        std::string::npos)
        << warnings[0].ToString();

    const Scene arrow = LoadRubeString(Polygon("0, 2, 0, 0.5", "0, 1, 2, 1"), "test.json");
    ASSERT_EQ(arrow.warnings.size(), 1U);
    EXPECT_NE(arrow.warnings[0].message.find("vertex 3 is not a corner"), std::string::npos);
    const auto* polygon = static_cast<const b2PolygonShape*>(arrow.fixtures[0].fixture->GetShape());
    EXPECT_EQ(polygon->m_count, 3);

    EXPECT_TRUE(
        ValidateRubeString(Polygon("0, 1, 0.5", "0, 0, 0.000001"), "test.json", nullptr, &warnings).empty());
    EXPECT_TRUE(warnings.empty());
}

// Every number of a scene has a range that keeps Box2D and the effects finite; out of range is an error
// with the JSON path (docs/rube.md lists the ranges).
TEST(RubeErrors, HugeNumbersAreOutOfRange)
{
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"restitution": 1e30, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].restitution",
                              "expected a number between 0 and 10, found 1e+30"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"restitution": 3.4e38, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].restitution", "between 0 and 10"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"friction": 1e4, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].friction", "between 0 and 1000"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"density": 1e7, "circle": {"radius": 1}})")),
                              "body[0].fixture[0].density", "between 0 and 1e+06"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(OneFixture(R"({"circle": {"radius": 3e9}})")),
                              "body[0].fixture[0].circle.radius", "> 0 and <= 1e+06"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"gravityScale": 3.4e38})")), "body[0].gravityScale",
                              "between -1000 and 1000"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"linearVelocity": {"x": 1e5, "y": 0}})")),
                              "body[0].linearVelocity.x", "between -10000 and 10000"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"angularVelocity": -1e5})")), "body[0].angularVelocity"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"angularDamping": 1e4})")), "body[0].angularDamping"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"massData-mass": 1e13})")), "body[0].massData-mass"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(R"({"massData-I": 1e25})")), "body[0].massData-I"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"gravity": {"x": 0, "y": -1e5}})"), "gravity.y"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"stepsPerSecond": 1e5})"), "stepsPerSecond", "<= 10000"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(R"({"positionIterations": 5000})"), "positionIterations"));
    const std::string two = Box(0.0f) + "," + Box(3.0f);
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(two, R"({"type": "revolute", "bodyA": 0, "bodyB": 1, "maxMotorTorque": 1e13})")),
        "joint[0].maxMotorTorque", "between 0 and 1e+12"));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(two, R"({"type": "revolute", "bodyA": 0, "bodyB": 1, "motorSpeed": 1e5})")),
        "joint[0].motorSpeed"));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(two, R"({"type": "distance", "bodyA": 0, "bodyB": 1, "frequency": 1e5})")),
        "joint[0].frequency"));
    EXPECT_TRUE(HasDiagnostic(
        LoadErrors(World(two, R"({"type": "weld", "bodyA": 0, "bodyB": 1, "dampingRatio": 1e4})")),
        "joint[0].dampingRatio"));
    EXPECT_TRUE(HasDiagnostic(LoadErrors(World(Box(0.0f), "", R"("image": [{"opacity": 2}])")),
                              "image[0].opacity", "between 0 and 1"));
    EXPECT_TRUE(
        HasDiagnostic(LoadErrors(World(Box(0.0f), "", R"("image": [{"scale": 1e30}])")), "image[0].scale"));
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
                              "joint[0].maxForce", "between 0 and 1e+12"));
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
        // what() lists every problem, one per line: a game that logs only what() saw 1 of 5 (a trial).
        std::string lines;
        for (const Diagnostic& diagnostic : error.Diagnostics())
        {
            lines += (lines.empty() ? "" : "\n") + diagnostic.ToString();
        }
        EXPECT_EQ(std::string(error.what()), lines);
        EXPECT_NE(std::string(error.what()).find("several.json"), std::string::npos);
        EXPECT_NE(std::string(error.what()).find("joint[0].bodyB"), std::string::npos);
    }
}

// RUBE never writes a key twice; a hand-edited scene that does is told where, not loaded with the last one.
TEST(RubeErrors, DuplicateKeysAreErrors)
{
    auto diagnostics = LoadErrors(World(Box(0.0f) + ", " + Box(2.0f, 2, R"("angle": 0, "angle": 1)")));
    ASSERT_EQ(diagnostics.size(), 1u) << test::Dump(diagnostics);
    EXPECT_EQ(diagnostics[0].path, "body[1].angle");
    EXPECT_EQ(diagnostics[0].message, "duplicate key \"angle\": each key may appear once in an object");
    EXPECT_EQ(diagnostics[0].file, "test.json");
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

    // Far but not that far: Box2D computes a positive inertia for these in every rounding, and loads them (a
    // trial's 10 cm pebble 50 m from its body's origin and 1 m crate 1 km from it were refused by a check
    // that asked for a margin of 8 float epsilons).
    for (const char* body :
         {R"({"type": 2, "fixture": [{"density": 1, "polygon": {"vertices": {"x": [50, 50.1,
                                 50.1, 50], "y": [0, 0, 0.1, 0.1]}}}]})",
          R"({"type": 2, "fixture": [{"density": 1, "polygon": {"vertices": {"x": [1000, 1001,
                                 1001, 1000], "y": [0, 0, 1, 1]}}}]})"})
    {
        const Scene scene = LoadRubeString(World(body), "far.json");
        EXPECT_GT(scene.bodies[0].body->GetInertia(), 0.0f) << body;
    }

    // With fixed rotation there is nothing to subtract.
    EXPECT_NO_THROW(LoadRubeString(World(R"({"type": 2, "fixedRotation": true, "massData-mass": 10,
        "massData-center": {"x": 5, "y": 0}, "massData-I": 1, "fixture": [{"density": 1,
        "circle": {"radius": 1}}]})"),
                                   "fixed.json"));
}

TEST(RubeErrors, SpringsTooStiffAreReported)
{
    // The ranges of density and frequency keep the stiffness (mass * (2 pi f)^2) far from float overflow;
    // out of range they are errors before any stiffness is computed.
    const std::string heavy = R"({"type": 2, "awake": true, "fixture": [{"density": 1e30,
        "polygon": {"vertices": {"x": [0.5, 0.5, -0.5, -0.5], "y": [-0.5, 0.5, 0.5, -0.5]}}}]})";
    auto diagnostics = LoadErrors(World(heavy + "," + heavy, R"({"type": "distance", "bodyA": 0, "bodyB": 1,
        "length": 1, "frequency": 1e6, "dampingRatio": 1})"));
    EXPECT_TRUE(HasDiagnostic(diagnostics, "joint[0].frequency", "between 0 and 10000"))
        << test::Dump(diagnostics);
    EXPECT_TRUE(HasDiagnostic(diagnostics, "body[0].fixture[0].density", "between 0 and 1e+06"));
    // At the top of both ranges the spring loads.
    const std::string heaviest = R"({"type": 2, "awake": true, "fixture": [{"density": 1e6,
        "polygon": {"vertices": {"x": [500, 500, -500, -500], "y": [-500, 500, 500, -500]}}}]})";
    EXPECT_NO_THROW(LoadRubeString(World(heaviest + "," + heaviest, R"({"type": "distance", "bodyA": 0,
        "bodyB": 1, "length": 1, "frequency": 1e4, "dampingRatio": 1000})"),
                                   "stiff.json"));
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
