// Format details: hex floats, the zero vector, defaults for missing values, shapes, custom properties,
// images, lookups.
#include "scene/rube_test_util.h"

#include <gtest/gtest.h>

namespace cfx
{
namespace
{

using test::World;

const b2Shape* OnlyShape(const Scene& scene)
{
    EXPECT_EQ(scene.fixtures.size(), 1u);
    return scene.fixtures.at(0).fixture->GetShape();
}

Scene LoadOneFixture(const std::string& fixture)
{
    return LoadRubeString(World(R"({"type": 0, "fixture": [)" + fixture + "]}"), "shape.json");
}

TEST(RubeFormat, HexFloatsEverywhere)
{
    Scene scene = LoadRubeString(World(R"({"type": 2, "position": {"x": "3F800000", "y": "c0000000"},
        "angle": "3F000000", "linearVelocity": {"x": "40400000", "y": 0}, "awake": true,
        "fixture": [{"density": "3F800000", "friction": "3E99999A",
                     "circle": {"radius": "3F000000", "center": {"x": "3F800000", "y": 0}}}]})",
                                       "", R"("stepsPerSecond": "42700000")"),
                                 "hex.json");
    b2Body* body = scene.bodies.at(0).body;
    EXPECT_EQ(body->GetPosition(), b2Vec2(1.0f, -2.0f));
    EXPECT_EQ(body->GetAngle(), 0.5f);
    EXPECT_EQ(body->GetLinearVelocity(), b2Vec2(3.0f, 0.0f));
    const b2Fixture* fixture = scene.fixtures.at(0).fixture;
    EXPECT_EQ(fixture->GetDensity(), 1.0f);
    EXPECT_EQ(fixture->GetFriction(), std::bit_cast<float>(0x3E99999Au));
    const auto* circle = static_cast<const b2CircleShape*>(fixture->GetShape());
    EXPECT_EQ(circle->m_radius, 0.5f);
    EXPECT_EQ(circle->m_p, b2Vec2(1.0f, 0.0f));
    EXPECT_EQ(scene.settings.stepsPerSecond, 60.0f);
}

TEST(RubeFormat, ZeroVectorShorthand)
{
    Scene scene = LoadRubeString(R"({"gravity": 0, "body": [{"type": 2, "position": 0, "linearVelocity": 0,
        "awake": true, "fixture": [{"density": 1, "circle": {"radius": 1, "center": 0}}]}]})",
                                 "zero.json");
    EXPECT_EQ(scene.bodies.at(0).body->GetPosition(), b2Vec2(0.0f, 0.0f));
    EXPECT_EQ(scene.world->GetGravity(), b2Vec2(0.0f, 0.0f));
    EXPECT_EQ(static_cast<const b2CircleShape*>(OnlyShape(scene))->m_p, b2Vec2(0.0f, 0.0f));
}

TEST(RubeFormat, DefaultsForMissingValues)
{
    Scene scene = LoadRubeString(R"({"body": [{"fixture": [{"circle": {"radius": 1}}]}]})", "defaults.json");
    b2Body* body = scene.bodies.at(0).body;
    EXPECT_EQ(body->GetType(), b2_staticBody);
    EXPECT_EQ(body->GetGravityScale(), 1.0f);
    EXPECT_TRUE(body->IsSleepingAllowed());
    EXPECT_TRUE(body->IsEnabled());
    EXPECT_FALSE(body->IsBullet());
    EXPECT_FALSE(body->IsFixedRotation());
    EXPECT_EQ(body->GetLinearDamping(), 0.0f);
    EXPECT_EQ(body->GetAngularDamping(), 0.0f);
    const b2Fixture* fixture = scene.fixtures.at(0).fixture;
    EXPECT_EQ(fixture->GetDensity(), 0.0f); // RUBE's default, not Box2D's
    EXPECT_EQ(fixture->GetFriction(), 0.0f);
    EXPECT_EQ(fixture->GetRestitution(), 0.0f);
    EXPECT_FALSE(fixture->IsSensor());
    EXPECT_EQ(fixture->GetFilterData().categoryBits, 1);
    EXPECT_EQ(fixture->GetFilterData().maskBits, 65535);
    EXPECT_EQ(fixture->GetFilterData().groupIndex, 0);
    EXPECT_EQ(static_cast<const b2CircleShape*>(fixture->GetShape())->m_p, b2Vec2(0.0f, 0.0f));

    EXPECT_EQ(scene.world->GetGravity(), b2Vec2(0.0f, 0.0f)); // b2dJson reads a missing gravity as zero
    EXPECT_TRUE(scene.world->GetAllowSleeping());
    EXPECT_TRUE(scene.world->GetAutoClearForces());
    EXPECT_TRUE(scene.world->GetWarmStarting());
    EXPECT_TRUE(scene.world->GetContinuousPhysics());
    EXPECT_FALSE(scene.world->GetSubStepping());
    EXPECT_EQ(scene.settings.stepsPerSecond, 60.0f);
    EXPECT_EQ(scene.settings.velocityIterations, 8);
    EXPECT_EQ(scene.settings.positionIterations, 3);
}

TEST(RubeFormat, BodyAndFixtureFields)
{
    Scene scene =
        LoadRubeString(World(R"({"name": "b", "type": 1, "position": {"x": 1, "y": 2}, "angle": 0.25,
        "linearVelocity": {"x": 3, "y": 4}, "angularVelocity": 5, "linearDamping": 0.5, "angularDamping": 0.75,
        "gravityScale": -2, "bullet": true, "allowSleep": false, "awake": true, "active": false,
        "fixedRotation": true,
        "fixture": [{"name": "f", "friction": 0.3, "restitution": 0.6, "density": 2, "sensor": true,
                     "filter-categoryBits": 4, "filter-maskBits": 9, "filter-groupIndex": -3,
                     "circle": {"radius": 0.5}}]})"),
                       "fields.json");
    b2Body* body = scene.bodies.at(0).body;
    EXPECT_EQ(body->GetType(), b2_kinematicBody);
    EXPECT_EQ(body->GetPosition(), b2Vec2(1.0f, 2.0f));
    EXPECT_EQ(body->GetAngle(), 0.25f);
    EXPECT_EQ(body->GetLinearVelocity(), b2Vec2(3.0f, 4.0f));
    EXPECT_EQ(body->GetAngularVelocity(), 5.0f);
    EXPECT_EQ(body->GetLinearDamping(), 0.5f);
    EXPECT_EQ(body->GetAngularDamping(), 0.75f);
    EXPECT_EQ(body->GetGravityScale(), -2.0f);
    EXPECT_TRUE(body->IsBullet());
    EXPECT_FALSE(body->IsSleepingAllowed());
    EXPECT_TRUE(body->IsAwake());
    EXPECT_FALSE(body->IsEnabled());
    EXPECT_TRUE(body->IsFixedRotation());
    const b2Fixture* fixture = scene.fixtures.at(0).fixture;
    EXPECT_EQ(fixture->GetFriction(), 0.3f);
    EXPECT_EQ(fixture->GetRestitution(), 0.6f);
    EXPECT_EQ(fixture->GetDensity(), 2.0f);
    EXPECT_TRUE(fixture->IsSensor());
    EXPECT_EQ(fixture->GetFilterData().categoryBits, 4);
    EXPECT_EQ(fixture->GetFilterData().maskBits, 9);
    EXPECT_EQ(fixture->GetFilterData().groupIndex, -3);
}

TEST(RubeFormat, WorldSettings)
{
    Scene scene =
        LoadRubeString(R"({"gravity": {"x": 1, "y": -5}, "allowSleep": false, "autoClearForces": false,
        "warmStarting": false, "continuousPhysics": false, "subStepping": true, "stepsPerSecond": 120,
        "velocityIterations": 10, "positionIterations": 6})",
                       "world.json");
    EXPECT_EQ(scene.world->GetGravity(), b2Vec2(1.0f, -5.0f));
    EXPECT_FALSE(scene.world->GetAllowSleeping());
    EXPECT_FALSE(scene.world->GetAutoClearForces());
    EXPECT_FALSE(scene.world->GetWarmStarting());
    EXPECT_FALSE(scene.world->GetContinuousPhysics());
    EXPECT_TRUE(scene.world->GetSubStepping());
    EXPECT_FALSE(scene.settings.allowSleep);
    EXPECT_TRUE(scene.settings.subStepping);
    EXPECT_EQ(scene.settings.stepsPerSecond, 120.0f);
    EXPECT_EQ(scene.settings.velocityIterations, 10);
    EXPECT_EQ(scene.settings.positionIterations, 6);
}

TEST(RubeFormat, MassDataIsAppliedAfterTheFixtures)
{
    Scene scene = LoadRubeString(World(test::Box(0.0f, 2, R"("massData-mass": 7, "massData-center": {"x": 0.1,
        "y": 0}, "massData-I": 3)")),
                                 "mass.json");
    b2Body* body = scene.bodies.at(0).body;
    EXPECT_EQ(body->GetMass(), 7.0f);
    EXPECT_EQ(body->GetLocalCenter(), b2Vec2(0.1f, 0.0f));
    EXPECT_FLOAT_EQ(body->GetInertia(), 3.0f);

    Scene computed = LoadRubeString(World(test::Box(0.0f)), "mass.json");
    EXPECT_FLOAT_EQ(computed.bodies.at(0).body->GetMass(), 1.0f); // unit box, density 1
}

// RUBE scenes are Box2D 2.3 scenes, where a dynamic body without mass gets 1 kg and falls; Box2D 2.4.1 leaves
// it at 0 kg, floating (a trial's ball whose fixture had no density, and an anchor body without fixtures).
TEST(RubeFormat, ADynamicBodyWithoutMassWeighsOneKilogramAndFalls)
{
    Scene scene =
        LoadRubeString(World(R"({"name": "ball", "type": 2, "awake": true, "position": {"x": 0, "y": 10},
        "fixture": [{"circle": {"radius": 0.5, "center": {"x": 0.3, "y": 0}}}]},
        {"name": "anchor", "type": 2, "awake": true, "position": {"x": 5, "y": 10}})"),
                       "massless.json");
    for (const SceneBody& body : scene.bodies)
    {
        EXPECT_EQ(body.body->GetMass(), 1.0f) << body.name;
        EXPECT_EQ(body.body->GetLocalCenter(), b2Vec2(0.0f, 0.0f)) << body.name;
        EXPECT_EQ(body.body->GetInertia(), 0.0f) << body.name;
    }
    for (int i = 0; i < 60; ++i)
    {
        scene.world->Step(1.0f / 60.0f, 8, 3);
    }
    for (const SceneBody& body : scene.bodies)
    {
        EXPECT_LT(body.body->GetPosition().y, 6.0f) << body.name << ": fell for 1 s";
    }
}

TEST(RubeFormat, VelocityIsTheVelocityOfTheCentreOfMass)
{
    // The fixture is off the body origin: Box2D would move the velocity with the centre of mass.
    Scene scene = LoadRubeString(World(R"({"type": 2, "awake": true, "angularVelocity": 2,
        "linearVelocity": {"x": 1, "y": 0},
        "fixture": [{"density": 1, "circle": {"radius": 1, "center": {"x": 3, "y": 0}}}]})"),
                                 "velocity.json");
    EXPECT_EQ(scene.bodies.at(0).body->GetLinearVelocity(), b2Vec2(1.0f, 0.0f));
    EXPECT_EQ(scene.bodies.at(0).body->GetAngularVelocity(), 2.0f);
}

TEST(RubeFormat, TwoVertexPolygonIsAnEdge)
{
    Scene scene = LoadOneFixture(R"({"polygon": {"vertices": {"x": [0, 2], "y": [1, 1]}}})");
    ASSERT_EQ(OnlyShape(scene)->GetType(), b2Shape::e_edge);
    const auto* edge = static_cast<const b2EdgeShape*>(OnlyShape(scene));
    EXPECT_EQ(edge->m_vertex1, b2Vec2(0.0f, 1.0f));
    EXPECT_EQ(edge->m_vertex2, b2Vec2(2.0f, 1.0f));
    EXPECT_FALSE(edge->m_oneSided);
}

TEST(RubeFormat, PolygonKeepsItsVertices)
{
    Scene scene = LoadOneFixture(R"({"polygon": {"vertices": {"x": [1, 1, -1, -1], "y": [-1, 1, 1, -1]}}})");
    ASSERT_EQ(OnlyShape(scene)->GetType(), b2Shape::e_polygon);
    const auto* polygon = static_cast<const b2PolygonShape*>(OnlyShape(scene));
    ASSERT_EQ(polygon->m_count, 4);
    EXPECT_EQ(polygon->m_vertices[0], b2Vec2(1.0f, -1.0f));
    EXPECT_EQ(polygon->m_vertices[2], b2Vec2(-1.0f, 1.0f));
}

TEST(RubeFormat, EdgeShapes)
{
    Scene twoSided =
        LoadOneFixture(R"({"edge": {"vertex1": {"x": 0, "y": 0}, "vertex2": {"x": 1, "y": 0}}})");
    const auto* plain = static_cast<const b2EdgeShape*>(OnlyShape(twoSided));
    EXPECT_FALSE(plain->m_oneSided);
    EXPECT_EQ(plain->m_vertex2, b2Vec2(1.0f, 0.0f));

    Scene oneSided = LoadOneFixture(R"({"edge": {"vertex1": {"x": 0, "y": 0}, "vertex2": {"x": 1, "y": 0},
        "hasVertex0": true, "hasVertex3": true, "vertex0": {"x": -1, "y": 0.5}, "vertex3": {"x": 2, "y": -0.5}}})");
    const auto* edge = static_cast<const b2EdgeShape*>(OnlyShape(oneSided));
    EXPECT_TRUE(edge->m_oneSided);
    EXPECT_EQ(edge->m_vertex0, b2Vec2(-1.0f, 0.5f));
    EXPECT_EQ(edge->m_vertex3, b2Vec2(2.0f, -0.5f));

    Scene half = LoadOneFixture(R"({"edge": {"vertex1": {"x": 0, "y": 0}, "vertex2": {"x": 1, "y": 0},
        "hasVertex0": true, "vertex0": {"x": -1, "y": 0.5}}})");
    const auto* halfEdge = static_cast<const b2EdgeShape*>(OnlyShape(half));
    EXPECT_TRUE(halfEdge->m_oneSided);
    EXPECT_EQ(halfEdge->m_vertex3, b2Vec2(2.0f, 0.0f)); // continues the edge
}

TEST(RubeFormat, ChainGhostVertices)
{
    Scene explicitGhosts = LoadOneFixture(R"({"chain": {"vertices": {"x": [0, 1, 2], "y": [0, 0, 1]},
        "hasPrevVertex": true, "hasNextVertex": true, "prevVertex": {"x": -1, "y": 1}, "nextVertex": {"x": 3,
        "y": 3}}})");
    const auto* chain = static_cast<const b2ChainShape*>(OnlyShape(explicitGhosts));
    ASSERT_EQ(chain->m_count, 3);
    EXPECT_EQ(chain->m_prevVertex, b2Vec2(-1.0f, 1.0f));
    EXPECT_EQ(chain->m_nextVertex, b2Vec2(3.0f, 3.0f));

    Scene noGhosts = LoadOneFixture(R"({"chain": {"vertices": {"x": [0, 1, 2], "y": [0, 0, 1]}}})");
    const auto* open = static_cast<const b2ChainShape*>(OnlyShape(noGhosts));
    EXPECT_EQ(open->m_prevVertex, b2Vec2(-1.0f, 0.0f)); // the first segment continued
    EXPECT_EQ(open->m_nextVertex, b2Vec2(3.0f, 2.0f));
}

TEST(RubeFormat, ClosedChainsAndLegacyLoopsBecomeLoops)
{
    Scene closed = LoadOneFixture(R"({"chain": {"vertices": {"x": [0, 1, 1, 0, 0], "y": [0, 0, 1, 1, 0]}}})");
    const auto* loop = static_cast<const b2ChainShape*>(OnlyShape(closed));
    ASSERT_EQ(loop->m_count, 5);
    EXPECT_EQ(loop->m_prevVertex, b2Vec2(0.0f, 1.0f)); // CreateLoop links the ends
    EXPECT_EQ(loop->m_nextVertex, b2Vec2(1.0f, 0.0f));

    Scene legacy = LoadOneFixture(R"({"loop": {"vertices": {"x": [0, 1, 1, 0], "y": [0, 0, 1, 1]}}})");
    const auto* legacyLoop = static_cast<const b2ChainShape*>(OnlyShape(legacy));
    ASSERT_EQ(legacyLoop->m_count, 5);
    EXPECT_EQ(legacyLoop->m_vertices[4], b2Vec2(0.0f, 0.0f));
}

// Three vertices whose last repeats the first cannot be a loop (it would have 2 distinct vertices): they
// load as the open chain they spell, there and back, with a warning saying so.
TEST(RubeFormat, AClosedChainOfTwoDistinctVerticesLoadsOpenWithAWarning)
{
    const std::string json =
        World(R"({"type": 0, "fixture": [{"chain": {"vertices": {"x": [0, 1, 0], "y": [0, 0, 0]}}}]})");
    std::vector<Diagnostic> warnings;
    EXPECT_TRUE(ValidateRubeString(json, "shape.json", nullptr, &warnings).empty());
    ASSERT_EQ(warnings.size(), 1u) << test::Dump(warnings);
    EXPECT_EQ(warnings[0].path, "body[0].fixture[0].chain.vertices");
    EXPECT_NE(warnings[0].message.find("closed chain needs 3 distinct vertices: loaded as an open chain"),
              std::string::npos)
        << warnings[0].message;
    const Scene scene = LoadRubeString(json, "shape.json");
    const auto* chain = static_cast<const b2ChainShape*>(OnlyShape(scene));
    EXPECT_EQ(chain->m_count, 3);

    std::vector<Diagnostic> none; // four vertices closing a triangle: a loop, nothing to warn about
    ValidateRubeString(World(R"({"type": 0, "fixture": [{"chain": {"vertices": {"x": [0, 1, 1, 0], "y":
        [0, 0, 1, 0]}}}]})"),
                       "shape.json", nullptr, &none);
    EXPECT_TRUE(none.empty()) << test::Dump(none);
    // With ghost vertices the chain says it is open: nothing to warn about either.
    ValidateRubeString(World(R"({"type": 0, "fixture": [{"chain": {"vertices": {"x": [0, 1, 0], "y": [0, 0,
        0]}, "hasPrevVertex": true, "prevVertex": {"x": -1, "y": 0}}}]})"),
                       "shape.json", nullptr, &none);
    EXPECT_TRUE(none.empty()) << test::Dump(none);
}

TEST(RubeFormat, CustomPropertiesOfEveryTypeOnEveryObject)
{
    const std::string properties = R"("customProperties": [
        {"name": "i", "int": -7}, {"name": "f", "float": "3FC00000"}, {"name": "s", "string": "text"},
        {"name": "b", "bool": true}, {"name": "v", "vec2": {"x": 1, "y": 2}}, {"name": "z", "vec2": 0},
        {"name": "c", "color": [10, 20, 30, 255]}])";
    const std::string json = R"({"gravity": 0, )" + properties + R"(,
        "body": [{"name": "body0", "type": 2, )" +
                             properties + R"(, "fixture": [{"name": "fixture0", "density": 1,
            "circle": {"radius": 1}, )" +
                             properties + R"(}]},
                 {"name": "body1", "type": 2, "position": {"x": 3, "y": 0},
                  "fixture": [{"density": 1, "circle": {"radius": 1}}]}],
        "joint": [{"name": "joint0", "type": "weld", "bodyA": 0, "bodyB": 1, )" +
                             properties + R"(}],
        "image": [{"name": "image0", "file": "a.png", "body": 1, )" +
                             properties + R"(}]})";
    Scene scene = LoadRubeString(json, "properties.json");
    const CustomProperties* all[] = {
        &scene.properties, &scene.FindBody("body0")->properties, &scene.FindFixture("fixture0")->properties,
        &scene.FindJoint("joint0")->properties, &scene.FindImage("image0")->properties};
    for (const CustomProperties* owner : all)
    {
        ASSERT_EQ(owner->items.size(), 7u);
        EXPECT_EQ(std::get<int>(owner->Find("i")->value), -7);
        EXPECT_EQ(std::get<float>(owner->Find("f")->value), 1.5f);
        EXPECT_EQ(*owner->FindString("s"), "text");
        EXPECT_EQ(std::get<bool>(owner->Find("b")->value), true);
        EXPECT_EQ(std::get<b2Vec2>(owner->Find("v")->value), b2Vec2(1.0f, 2.0f));
        EXPECT_EQ(std::get<b2Vec2>(owner->Find("z")->value), b2Vec2(0.0f, 0.0f));
        EXPECT_EQ(std::get<Rgba8>(owner->Find("c")->value), (Rgba8{10, 20, 30, 255}));
        EXPECT_EQ(owner->Find("missing"), nullptr);
        EXPECT_EQ(owner->FindString("i"), nullptr); // not a string
        EXPECT_EQ(owner->items[0].name, "i");       // file order
    }
}

TEST(RubeFormat, ImagesAreKeptAsData)
{
    Scene scene = LoadRubeString(World(test::Box(0.0f), "", R"("image": [{"name": "img", "file": "a.png",
        "body": 0, "center": {"x": 1, "y": 2}, "angle": 0.5, "scale": 2, "aspectScale": 0.5, "flip": true,
        "opacity": 0.25, "filter": 0, "renderOrder": 3, "colorTint": [255, 0, 51, 255],
        "corners": {"x": [-1, 1, 1, -1], "y": [-1, -1, 1, 1]}, "glTexCoordPointer": [0, 0, 1, 0, 1, 1, 0, 1],
        "glVertexPointer": [-1, -1, 1, -1, 1, 1, -1, 1], "glDrawElements": [0, 1, 2, 2, 3, 0]},
        {"file": "b.png", "body": -1}])"),
                                 "images.json");
    ASSERT_EQ(scene.images.size(), 2u);
    const SceneImage& image = scene.images[0];
    EXPECT_EQ(image.name, "img");
    EXPECT_EQ(image.file, "a.png");
    EXPECT_EQ(image.bodyIndex, 0);
    EXPECT_EQ(image.center, b2Vec2(1.0f, 2.0f));
    EXPECT_EQ(image.angle, 0.5f);
    EXPECT_EQ(image.scale, 2.0f);
    EXPECT_EQ(image.aspectScale, 0.5f);
    EXPECT_TRUE(image.flip);
    EXPECT_EQ(image.opacity, 0.25f);
    EXPECT_EQ(image.filter, 0);
    EXPECT_EQ(image.renderOrder, 3.0f);
    EXPECT_EQ(image.colorTint[0], 1.0f);
    EXPECT_EQ(image.colorTint[1], 0.0f);
    EXPECT_FLOAT_EQ(image.colorTint[2], 0.2f);
    ASSERT_EQ(image.corners.size(), 4u);
    EXPECT_EQ(image.corners[1], b2Vec2(1.0f, -1.0f));
    ASSERT_EQ(image.uvCoords.size(), 4u);
    EXPECT_EQ(image.uvCoords[1], b2Vec2(1.0f, 0.0f));
    EXPECT_EQ(image.glDrawElements.size(), 6u);
    EXPECT_EQ(scene.images[1].bodyIndex, -1);
    EXPECT_EQ(scene.images[1].scale, 1.0f);
}

TEST(RubeFormat, LookupsByNameAndObject)
{
    Scene scene = LoadRubeString(World(R"({"name": "a", "type": 2, "fixture": [{"name": "fa", "density": 1,
        "circle": {"radius": 1}}, {"name": "same", "density": 1, "circle": {"radius": 0.5}}]},
        {"name": "b", "type": 2, "position": {"x": 5, "y": 0}, "fixture": [{"name": "same", "density": 1,
        "circle": {"radius": 1}}]})",
                                       R"({"name": "j", "type": "revolute", "bodyA": 0, "bodyB": 1})"),
                                 "lookups.json");
    ASSERT_NE(scene.FindBody("b"), nullptr);
    EXPECT_EQ(scene.FindBody("b")->body, scene.bodies[1].body);
    EXPECT_EQ(scene.FindBody("nope"), nullptr);
    ASSERT_NE(scene.FindFixture("same"), nullptr);
    EXPECT_EQ(scene.FindFixture("same"), &scene.fixtures[1]); // the first with that name
    EXPECT_EQ(scene.FindFixture("same")->bodyIndex, 0);
    EXPECT_EQ(scene.FindFixture(scene.fixtures[2].fixture), &scene.fixtures[2]);
    EXPECT_EQ(scene.FindFixture(static_cast<const b2Fixture*>(nullptr)), nullptr);
    EXPECT_EQ(scene.FindBody(scene.bodies[0].body), &scene.bodies[0]);
    ASSERT_NE(scene.FindJoint("j"), nullptr);
    EXPECT_EQ(scene.FindJoint(scene.FindJoint("j")->joint), scene.FindJoint("j"));
    EXPECT_EQ(scene.FindJoint("k"), nullptr);
}

} // namespace
} // namespace cfx
