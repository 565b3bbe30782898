// Every real RUBE file the project has loads, and what was built matches its JSON (read here with nlohmann,
// independently of the library).
#include "scene/rube_test_util.h"

#include <cctype>
#include <gtest/gtest.h>
#include <map>
#include <optional>

namespace cfx
{
namespace
{

using test::JsonFloat;
using test::JsonVec;

class RubeSample : public ::testing::TestWithParam<std::filesystem::path>
{
};

b2Shape::Type ExpectedShapeType(const nlohmann::json& fixture)
{
    if (fixture.contains("circle"))
    {
        return b2Shape::e_circle;
    }
    if (fixture.contains("polygon"))
    {
        return fixture["polygon"]["vertices"]["x"].size() == 2 ? b2Shape::e_edge : b2Shape::e_polygon;
    }
    if (fixture.contains("edge"))
    {
        return b2Shape::e_edge;
    }
    return b2Shape::e_chain;
}

b2JointType ExpectedJointType(const std::string& type)
{
    static const std::map<std::string, b2JointType> kTypes = {
        {"revolute", e_revoluteJoint}, {"prismatic", e_prismaticJoint}, {"distance", e_distanceJoint},
        {"rope", e_distanceJoint},     {"pulley", e_pulleyJoint},       {"mouse", e_mouseJoint},
        {"gear", e_gearJoint},         {"wheel", e_wheelJoint},         {"weld", e_weldJoint},
        {"friction", e_frictionJoint}, {"motor", e_motorJoint},
    };
    return kTypes.at(type);
}

/// Local anchor A of the joint types that keep one.
std::optional<b2Vec2> LocalAnchorA(b2Joint* joint)
{
    switch (joint->GetType())
    {
    case e_revoluteJoint:
        return static_cast<b2RevoluteJoint*>(joint)->GetLocalAnchorA();
    case e_prismaticJoint:
        return static_cast<b2PrismaticJoint*>(joint)->GetLocalAnchorA();
    case e_distanceJoint:
        return static_cast<b2DistanceJoint*>(joint)->GetLocalAnchorA();
    case e_wheelJoint:
        return static_cast<b2WheelJoint*>(joint)->GetLocalAnchorA();
    case e_weldJoint:
        return static_cast<b2WeldJoint*>(joint)->GetLocalAnchorA();
    default:
        return std::nullopt;
    }
}

TEST_P(RubeSample, LoadsAndMatchesItsJson)
{
    const std::filesystem::path path = GetParam();
    const nlohmann::json json = test::ReadJson(path);
    Scene scene = LoadRubeFile(path);
    ASSERT_TRUE(scene.world);

    const auto& bodiesJson = json.value("body", nlohmann::json::array());
    ASSERT_EQ(scene.bodies.size(), bodiesJson.size());
    ASSERT_EQ(scene.world->GetBodyCount(), static_cast<int32>(bodiesJson.size()));
    std::size_t fixtureIndex = 0;
    for (std::size_t b = 0; b < bodiesJson.size(); ++b)
    {
        SCOPED_TRACE("body " + std::to_string(b));
        const auto& bodyJson = bodiesJson[b];
        const SceneBody& entry = scene.bodies[b];
        b2Body* body = entry.body;
        EXPECT_EQ(entry.name, bodyJson.value("name", ""));
        EXPECT_EQ(static_cast<int>(body->GetType()), bodyJson.value("type", 0));
        EXPECT_EQ(body->GetPosition(), JsonVec(bodyJson, "position"));
        EXPECT_EQ(body->GetAngle(), JsonFloat(bodyJson, "angle", 0.0f));
        if (body->GetType() != b2_staticBody && body->IsAwake())
        {
            EXPECT_EQ(body->GetLinearVelocity(), JsonVec(bodyJson, "linearVelocity"));
            EXPECT_EQ(body->GetAngularVelocity(), JsonFloat(bodyJson, "angularVelocity", 0.0f));
        }
        EXPECT_EQ(body->IsFixedRotation(), bodyJson.value("fixedRotation", false));
        if (body->GetType() == b2_dynamicBody && bodyJson.contains("massData-mass"))
        {
            EXPECT_EQ(body->GetMass(), JsonFloat(bodyJson["massData-mass"]));
        }

        const auto& fixturesJson = bodyJson.value("fixture", nlohmann::json::array());
        // Each of the file's fixtures, and the back side of each one-sided one (SceneFixture::backSide).
        int fixturesOnBody = 0;
        for (b2Fixture* f = body->GetFixtureList(); f != nullptr; f = f->GetNext())
        {
            const SceneFixture* owner = scene.FindFixture(f);
            ASSERT_NE(owner, nullptr);
            fixturesOnBody += owner->backSide == f ? 0 : 1;
            const b2Shape::Type type = owner->fixture->GetShape()->GetType();
            const bool oneSided = type == b2Shape::e_chain ||
                                  (type == b2Shape::e_edge &&
                                   static_cast<const b2EdgeShape*>(owner->fixture->GetShape())->m_oneSided);
            EXPECT_EQ(owner->backSide != nullptr, oneSided);
        }
        ASSERT_EQ(fixturesOnBody, static_cast<int>(fixturesJson.size()));
        for (std::size_t f = 0; f < fixturesJson.size(); ++f, ++fixtureIndex)
        {
            SCOPED_TRACE("fixture " + std::to_string(f));
            const auto& fixtureJson = fixturesJson[f];
            ASSERT_LT(fixtureIndex, scene.fixtures.size());
            const SceneFixture& fixtureEntry = scene.fixtures[fixtureIndex];
            EXPECT_EQ(fixtureEntry.bodyIndex, static_cast<int>(b));
            EXPECT_EQ(fixtureEntry.name, fixtureJson.value("name", ""));
            b2Fixture* fixture = fixtureEntry.fixture;
            EXPECT_EQ(fixture->GetBody(), body);
            EXPECT_EQ(fixture->GetFriction(), JsonFloat(fixtureJson, "friction", 0.0f));
            EXPECT_EQ(fixture->GetRestitution(), JsonFloat(fixtureJson, "restitution", 0.0f));
            EXPECT_EQ(fixture->GetDensity(), JsonFloat(fixtureJson, "density", 0.0f));
            EXPECT_EQ(fixture->GetFilterData().categoryBits, fixtureJson.value("filter-categoryBits", 1));
            EXPECT_EQ(fixture->GetFilterData().maskBits, fixtureJson.value("filter-maskBits", 0xFFFF));
            EXPECT_EQ(fixture->GetType(), ExpectedShapeType(fixtureJson));
            if (fixtureJson.contains("circle"))
            {
                const auto* circle = static_cast<const b2CircleShape*>(fixture->GetShape());
                EXPECT_EQ(circle->m_radius, JsonFloat(fixtureJson["circle"]["radius"]));
                EXPECT_EQ(circle->m_p, JsonVec(fixtureJson["circle"], "center"));
            }
            if (fixtureJson.contains("chain"))
            {
                const auto* chain = static_cast<const b2ChainShape*>(fixture->GetShape());
                const auto& xs = fixtureJson["chain"]["vertices"]["x"];
                const auto& ys = fixtureJson["chain"]["vertices"]["y"];
                ASSERT_EQ(chain->m_count, static_cast<int32>(xs.size()));
                for (std::size_t v = 0; v < xs.size(); ++v)
                {
                    EXPECT_EQ(chain->m_vertices[v], b2Vec2(JsonFloat(xs[v]), JsonFloat(ys[v])));
                }
            }
            if (fixtureJson.contains("customProperties"))
            {
                for (const auto& property : fixtureJson["customProperties"])
                {
                    if (property.contains("string"))
                    {
                        const std::string* value =
                            fixtureEntry.properties.FindString(property["name"].get<std::string>());
                        ASSERT_NE(value, nullptr);
                        EXPECT_EQ(*value, property["string"].get<std::string>());
                    }
                }
            }
        }
    }
    EXPECT_EQ(fixtureIndex, scene.fixtures.size());

    const auto& jointsJson = json.value("joint", nlohmann::json::array());
    ASSERT_EQ(scene.joints.size(), jointsJson.size());
    ASSERT_EQ(scene.world->GetJointCount(), static_cast<int32>(jointsJson.size()));
    for (std::size_t j = 0; j < jointsJson.size(); ++j)
    {
        SCOPED_TRACE("joint " + std::to_string(j));
        const auto& jointJson = jointsJson[j];
        const SceneJoint& entry = scene.joints[j];
        EXPECT_EQ(entry.type, jointJson["type"].get<std::string>());
        EXPECT_EQ(entry.name, jointJson.value("name", ""));
        EXPECT_EQ(entry.joint->GetType(), ExpectedJointType(entry.type));
        EXPECT_EQ(entry.joint->GetBodyA(), scene.bodies[jointJson["bodyA"].get<std::size_t>()].body);
        EXPECT_EQ(entry.joint->GetBodyB(), scene.bodies[jointJson["bodyB"].get<std::size_t>()].body);
        if (auto anchor = LocalAnchorA(entry.joint))
        {
            EXPECT_EQ(*anchor, JsonVec(jointJson, "anchorA"));
        }
    }

    const auto& imagesJson = json.value("image", nlohmann::json::array());
    ASSERT_EQ(scene.images.size(), imagesJson.size());
    for (std::size_t i = 0; i < imagesJson.size(); ++i)
    {
        EXPECT_EQ(scene.images[i].file, imagesJson[i]["file"].get<std::string>());
        EXPECT_EQ(scene.images[i].bodyIndex, imagesJson[i].value("body", -1));
        EXPECT_EQ(scene.images[i].opacity, JsonFloat(imagesJson[i], "opacity", 1.0f));
    }

    for (const auto& property : json.value("customProperties", nlohmann::json::array()))
    {
        if (property.contains("string"))
        {
            const std::string* value = scene.properties.FindString(property["name"].get<std::string>());
            ASSERT_NE(value, nullptr);
            EXPECT_EQ(*value, property["string"].get<std::string>());
        }
    }

    EXPECT_EQ(scene.world->GetGravity(), JsonVec(json, "gravity"));
    EXPECT_EQ(scene.settings.stepsPerSecond, JsonFloat(json, "stepsPerSecond", 60.0f));
    EXPECT_EQ(scene.settings.velocityIterations, json.value("velocityIterations", 8));
    EXPECT_EQ(scene.settings.positionIterations, json.value("positionIterations", 3));
    EXPECT_EQ(scene.world->GetAllowSleeping(), json.value("allowSleep", true));
    EXPECT_EQ(scene.world->GetSubStepping(), json.value("subStepping", false));

    // The world steps without trouble.
    for (int i = 0; i < 60; ++i)
    {
        scene.world->Step(1.0f / 60.0f, 8, 3);
    }
}

TEST_P(RubeSample, ValidatesWithoutProblemsAndCounts)
{
    const std::filesystem::path path = GetParam();
    const nlohmann::json json = test::ReadJson(path);
    SceneCounts counts;
    const std::vector<Diagnostic> diagnostics = ValidateRubeFile(path, &counts);
    EXPECT_TRUE(diagnostics.empty()) << test::Dump(diagnostics);
    int fixtures = 0;
    for (const auto& body : json.value("body", nlohmann::json::array()))
    {
        fixtures += static_cast<int>(body.value("fixture", nlohmann::json::array()).size());
    }
    EXPECT_EQ(counts.bodies, static_cast<int>(json.value("body", nlohmann::json::array()).size()));
    EXPECT_EQ(counts.fixtures, fixtures);
    EXPECT_EQ(counts.joints, static_cast<int>(json.value("joint", nlohmann::json::array()).size()));
    EXPECT_EQ(counts.images, static_cast<int>(json.value("image", nlohmann::json::array()).size()));
}

INSTANTIATE_TEST_SUITE_P(SharedFiles, RubeSample, ::testing::ValuesIn(test::SampleFiles()),
                         test::SampleTestName);

TEST(RubeSamples, SharedFolder)
{
    CONTACTFX_REQUIRE_RUBE_SAMPLES();
    // The samples that are there took part in the parameterised tests above.
    const std::vector<std::filesystem::path> files = test::SampleFiles();
    EXPECT_TRUE(std::any_of(files.begin(), files.end(),
                            [](const std::filesystem::path& file)
                            { return file.parent_path() == test::RubeSamplesDir(); }));
}

TEST(RubeSamples, ProjectScenesSpecificValues)
{
    // Facts read off the file by eye, as a second check of the generic comparison above.
    Scene main = LoadRubeFile(test::ProjectScene("physics_driven_particles.json"));
    const SceneFixture* dirt = main.FindFixture("ground_dirt_0");
    ASSERT_NE(dirt, nullptr);
    ASSERT_NE(dirt->properties.FindString("material"), nullptr);
    EXPECT_EQ(*dirt->properties.FindString("material"), "dirt");
    EXPECT_EQ(dirt->fixture->GetFriction(), 0.25f);
    const SceneJoint* suspension = main.FindJoint("suspension_front");
    ASSERT_NE(suspension, nullptr);
    EXPECT_EQ(suspension->joint->GetType(), e_wheelJoint);
}

TEST(RubeSamples, CarSampleSpecificValues)
{
    CONTACTFX_REQUIRE_RUBE_SAMPLES();
    Scene car = LoadRubeFile(test::RubeSamplesDir() / "car.json");
    const SceneJoint* spring = car.FindJoint("antennaspring2");
    ASSERT_NE(spring, nullptr);
    EXPECT_EQ(spring->joint->GetType(), e_distanceJoint);
    ASSERT_EQ(car.images.size(), 3u);
    EXPECT_EQ(car.images[2].file, "images/carbody.png");
    EXPECT_EQ(car.images[2].renderOrder, 1.0f);
    EXPECT_EQ(car.images[2].opacity, 0.5f);
    ASSERT_EQ(car.images[2].corners.size(), 4u);
    ASSERT_EQ(car.images[2].uvCoords.size(), 4u);
    EXPECT_EQ(car.images[2].uvCoords[2], b2Vec2(1.0f, 1.0f));
    EXPECT_EQ(car.images[2].glDrawElements, (std::vector<int>{0, 1, 2, 2, 3, 0}));
}

} // namespace
} // namespace cfx
