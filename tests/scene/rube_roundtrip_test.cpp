// Save and load again: the same bodies, fixtures, joints, properties and images.
#include "scene/rube_test_util.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace cfx
{
namespace
{

constexpr float kTolerance = 1e-6f;

void ExpectNear(b2Vec2 actual, b2Vec2 expected, float tolerance = kTolerance)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
}

void ExpectRelative(float actual, float expected, float relative = 1e-5f)
{
    EXPECT_NEAR(actual, expected, relative * std::max(1.0f, std::fabs(expected)));
}

void ExpectSameShape(const b2Shape& a, const b2Shape& b)
{
    ASSERT_EQ(a.GetType(), b.GetType());
    EXPECT_EQ(a.m_radius, b.m_radius);
    switch (a.GetType())
    {
    case b2Shape::e_circle:
        EXPECT_EQ(static_cast<const b2CircleShape&>(a).m_p, static_cast<const b2CircleShape&>(b).m_p);
        break;
    case b2Shape::e_polygon:
    {
        const auto& pa = static_cast<const b2PolygonShape&>(a);
        const auto& pb = static_cast<const b2PolygonShape&>(b);
        ASSERT_EQ(pa.m_count, pb.m_count);
        for (int i = 0; i < pa.m_count; ++i)
        {
            EXPECT_EQ(pa.m_vertices[i], pb.m_vertices[i]);
        }
        break;
    }
    case b2Shape::e_edge:
    {
        const auto& ea = static_cast<const b2EdgeShape&>(a);
        const auto& eb = static_cast<const b2EdgeShape&>(b);
        EXPECT_EQ(ea.m_vertex1, eb.m_vertex1);
        EXPECT_EQ(ea.m_vertex2, eb.m_vertex2);
        EXPECT_EQ(ea.m_oneSided, eb.m_oneSided);
        if (ea.m_oneSided)
        {
            EXPECT_EQ(ea.m_vertex0, eb.m_vertex0);
            EXPECT_EQ(ea.m_vertex3, eb.m_vertex3);
        }
        break;
    }
    case b2Shape::e_chain:
    {
        const auto& ca = static_cast<const b2ChainShape&>(a);
        const auto& cb = static_cast<const b2ChainShape&>(b);
        ASSERT_EQ(ca.m_count, cb.m_count);
        for (int i = 0; i < ca.m_count; ++i)
        {
            EXPECT_EQ(ca.m_vertices[i], cb.m_vertices[i]);
        }
        EXPECT_EQ(ca.m_prevVertex, cb.m_prevVertex);
        EXPECT_EQ(ca.m_nextVertex, cb.m_nextVertex);
        break;
    }
    default:
        break;
    }
}

b2Vec2 LocalAnchorB(b2Joint* joint)
{
    return joint->GetBodyB()->GetLocalPoint(joint->GetAnchorB());
}

void ExpectSameJoint(b2Joint* a, b2Joint* b)
{
    ASSERT_EQ(a->GetType(), b->GetType());
    ExpectNear(a->GetAnchorA(), b->GetAnchorA(), 1e-5f);
    ExpectNear(a->GetAnchorB(), b->GetAnchorB(), 1e-5f);
    ExpectNear(LocalAnchorB(a), LocalAnchorB(b), 1e-5f);
    EXPECT_EQ(a->GetCollideConnected(), b->GetCollideConnected());
    switch (a->GetType())
    {
    case e_revoluteJoint:
    {
        auto* ra = static_cast<b2RevoluteJoint*>(a);
        auto* rb = static_cast<b2RevoluteJoint*>(b);
        EXPECT_EQ(ra->GetLocalAnchorA(), rb->GetLocalAnchorA());
        EXPECT_EQ(ra->GetReferenceAngle(), rb->GetReferenceAngle());
        EXPECT_EQ(ra->IsLimitEnabled(), rb->IsLimitEnabled());
        EXPECT_EQ(ra->GetLowerLimit(), rb->GetLowerLimit());
        EXPECT_EQ(ra->GetUpperLimit(), rb->GetUpperLimit());
        EXPECT_EQ(ra->GetMotorSpeed(), rb->GetMotorSpeed());
        EXPECT_EQ(ra->GetMaxMotorTorque(), rb->GetMaxMotorTorque());
        break;
    }
    case e_prismaticJoint:
    {
        auto* pa = static_cast<b2PrismaticJoint*>(a);
        auto* pb = static_cast<b2PrismaticJoint*>(b);
        EXPECT_EQ(pa->GetLocalAnchorA(), pb->GetLocalAnchorA());
        EXPECT_EQ(pa->GetLocalAxisA(), pb->GetLocalAxisA());
        EXPECT_EQ(pa->GetLowerLimit(), pb->GetLowerLimit());
        EXPECT_EQ(pa->GetMaxMotorForce(), pb->GetMaxMotorForce());
        break;
    }
    case e_distanceJoint:
    {
        auto* da = static_cast<b2DistanceJoint*>(a);
        auto* db = static_cast<b2DistanceJoint*>(b);
        EXPECT_EQ(da->GetLocalAnchorA(), db->GetLocalAnchorA());
        EXPECT_EQ(da->GetLength(), db->GetLength());
        EXPECT_EQ(da->GetMinLength(), db->GetMinLength());
        EXPECT_EQ(da->GetMaxLength(), db->GetMaxLength());
        ExpectRelative(da->GetStiffness(), db->GetStiffness());
        ExpectRelative(da->GetDamping(), db->GetDamping());
        break;
    }
    case e_wheelJoint:
    {
        auto* wa = static_cast<b2WheelJoint*>(a);
        auto* wb = static_cast<b2WheelJoint*>(b);
        EXPECT_EQ(wa->GetLocalAnchorA(), wb->GetLocalAnchorA());
        EXPECT_EQ(wa->GetLocalAxisA(), wb->GetLocalAxisA());
        EXPECT_EQ(wa->GetMotorSpeed(), wb->GetMotorSpeed());
        EXPECT_EQ(wa->GetMaxMotorTorque(), wb->GetMaxMotorTorque());
        ExpectRelative(wa->GetStiffness(), wb->GetStiffness());
        ExpectRelative(wa->GetDamping(), wb->GetDamping());
        break;
    }
    case e_weldJoint:
    {
        auto* wa = static_cast<b2WeldJoint*>(a);
        auto* wb = static_cast<b2WeldJoint*>(b);
        EXPECT_EQ(wa->GetReferenceAngle(), wb->GetReferenceAngle());
        ExpectRelative(wa->GetStiffness(), wb->GetStiffness());
        ExpectRelative(wa->GetDamping(), wb->GetDamping());
        break;
    }
    case e_pulleyJoint:
    {
        auto* pa = static_cast<b2PulleyJoint*>(a);
        auto* pb = static_cast<b2PulleyJoint*>(b);
        EXPECT_EQ(pa->GetGroundAnchorA(), pb->GetGroundAnchorA());
        EXPECT_EQ(pa->GetLengthA(), pb->GetLengthA());
        EXPECT_EQ(pa->GetRatio(), pb->GetRatio());
        break;
    }
    case e_mouseJoint:
    {
        auto* ma = static_cast<b2MouseJoint*>(a);
        auto* mb = static_cast<b2MouseJoint*>(b);
        EXPECT_EQ(ma->GetTarget(), mb->GetTarget());
        EXPECT_EQ(ma->GetMaxForce(), mb->GetMaxForce());
        ExpectRelative(ma->GetStiffness(), mb->GetStiffness());
        break;
    }
    case e_gearJoint:
        EXPECT_EQ(static_cast<b2GearJoint*>(a)->GetRatio(), static_cast<b2GearJoint*>(b)->GetRatio());
        break;
    case e_frictionJoint:
        EXPECT_EQ(static_cast<b2FrictionJoint*>(a)->GetMaxForce(),
                  static_cast<b2FrictionJoint*>(b)->GetMaxForce());
        EXPECT_EQ(static_cast<b2FrictionJoint*>(a)->GetMaxTorque(),
                  static_cast<b2FrictionJoint*>(b)->GetMaxTorque());
        break;
    case e_motorJoint:
    {
        auto* ma = static_cast<b2MotorJoint*>(a);
        auto* mb = static_cast<b2MotorJoint*>(b);
        EXPECT_EQ(ma->GetLinearOffset(), mb->GetLinearOffset());
        EXPECT_EQ(ma->GetAngularOffset(), mb->GetAngularOffset());
        EXPECT_EQ(ma->GetCorrectionFactor(), mb->GetCorrectionFactor());
        break;
    }
    default:
        break;
    }
}

void ExpectSameProperties(const CustomProperties& a, const CustomProperties& b)
{
    ASSERT_EQ(a.items.size(), b.items.size());
    for (std::size_t i = 0; i < a.items.size(); ++i)
    {
        EXPECT_EQ(a.items[i].name, b.items[i].name);
        EXPECT_EQ(a.items[i].value.index(), b.items[i].value.index());
        if (a.items[i].value.index() == b.items[i].value.index())
        {
            EXPECT_TRUE(a.items[i].value == b.items[i].value) << a.items[i].name;
        }
    }
}

/// The scenes hold the same world, in the same order.
void ExpectSameScene(const Scene& a, const Scene& b)
{
    ASSERT_EQ(a.bodies.size(), b.bodies.size());
    for (std::size_t i = 0; i < a.bodies.size(); ++i)
    {
        SCOPED_TRACE("body " + std::to_string(i));
        const b2Body* ba = a.bodies[i].body;
        const b2Body* bb = b.bodies[i].body;
        EXPECT_EQ(a.bodies[i].name, b.bodies[i].name);
        EXPECT_EQ(ba->GetType(), bb->GetType());
        EXPECT_EQ(ba->GetPosition(), bb->GetPosition());
        EXPECT_EQ(ba->GetAngle(), bb->GetAngle());
        ExpectNear(ba->GetLinearVelocity(), bb->GetLinearVelocity());
        EXPECT_NEAR(ba->GetAngularVelocity(), bb->GetAngularVelocity(), kTolerance);
        EXPECT_EQ(ba->GetLinearDamping(), bb->GetLinearDamping());
        EXPECT_EQ(ba->GetGravityScale(), bb->GetGravityScale());
        EXPECT_EQ(ba->IsAwake(), bb->IsAwake());
        EXPECT_EQ(ba->IsEnabled(), bb->IsEnabled());
        EXPECT_EQ(ba->IsBullet(), bb->IsBullet());
        EXPECT_EQ(ba->IsFixedRotation(), bb->IsFixedRotation());
        ExpectRelative(ba->GetMass(), bb->GetMass());
        ExpectRelative(ba->GetInertia(), bb->GetInertia());
        ExpectNear(ba->GetLocalCenter(), bb->GetLocalCenter(), 1e-5f);
        ExpectSameProperties(a.bodies[i].properties, b.bodies[i].properties);
    }
    ASSERT_EQ(a.fixtures.size(), b.fixtures.size());
    for (std::size_t i = 0; i < a.fixtures.size(); ++i)
    {
        SCOPED_TRACE("fixture " + std::to_string(i));
        const b2Fixture* fa = a.fixtures[i].fixture;
        const b2Fixture* fb = b.fixtures[i].fixture;
        EXPECT_EQ(a.fixtures[i].name, b.fixtures[i].name);
        EXPECT_EQ(a.fixtures[i].bodyIndex, b.fixtures[i].bodyIndex);
        EXPECT_EQ(fa->GetFriction(), fb->GetFriction());
        EXPECT_EQ(fa->GetRestitution(), fb->GetRestitution());
        EXPECT_EQ(fa->GetDensity(), fb->GetDensity());
        EXPECT_EQ(fa->IsSensor(), fb->IsSensor());
        EXPECT_EQ(fa->GetFilterData().categoryBits, fb->GetFilterData().categoryBits);
        EXPECT_EQ(fa->GetFilterData().maskBits, fb->GetFilterData().maskBits);
        EXPECT_EQ(fa->GetFilterData().groupIndex, fb->GetFilterData().groupIndex);
        ExpectSameShape(*fa->GetShape(), *fb->GetShape());
        ExpectSameProperties(a.fixtures[i].properties, b.fixtures[i].properties);
    }
    ASSERT_EQ(a.joints.size(), b.joints.size());
    for (std::size_t i = 0; i < a.joints.size(); ++i)
    {
        SCOPED_TRACE("joint " + std::to_string(i));
        // Gear joints move to the end of the file; match joints by name.
        const SceneJoint* other = b.FindJoint(a.joints[i].name);
        ASSERT_NE(other, nullptr);
        EXPECT_EQ(a.joints[i].type, other->type);
        ExpectSameJoint(a.joints[i].joint, other->joint);
        ExpectSameProperties(a.joints[i].properties, other->properties);
    }
    ASSERT_EQ(a.images.size(), b.images.size());
    for (std::size_t i = 0; i < a.images.size(); ++i)
    {
        const SceneImage& ia = a.images[i];
        const SceneImage& ib = b.images[i];
        EXPECT_EQ(ia.name, ib.name);
        EXPECT_EQ(ia.file, ib.file);
        EXPECT_EQ(ia.bodyIndex, ib.bodyIndex);
        EXPECT_EQ(ia.center, ib.center);
        EXPECT_EQ(ia.scale, ib.scale);
        EXPECT_EQ(ia.opacity, ib.opacity);
        EXPECT_EQ(ia.renderOrder, ib.renderOrder);
        EXPECT_EQ(ia.flip, ib.flip);
        for (int c = 0; c < 4; ++c)
        {
            EXPECT_EQ(ia.colorTint[c], ib.colorTint[c]);
        }
        ASSERT_EQ(ia.corners.size(), ib.corners.size());
        for (std::size_t c = 0; c < ia.corners.size(); ++c)
        {
            EXPECT_EQ(ia.corners[c], ib.corners[c]);
        }
        ASSERT_EQ(ia.uvCoords.size(), ib.uvCoords.size());
        EXPECT_EQ(ia.glDrawElements, ib.glDrawElements);
        ExpectSameProperties(ia.properties, ib.properties);
    }
    ExpectSameProperties(a.properties, b.properties);
    EXPECT_EQ(a.world->GetGravity(), b.world->GetGravity());
    EXPECT_EQ(a.world->GetAllowSleeping(), b.world->GetAllowSleeping());
    EXPECT_EQ(a.world->GetWarmStarting(), b.world->GetWarmStarting());
    EXPECT_EQ(a.world->GetContinuousPhysics(), b.world->GetContinuousPhysics());
    EXPECT_EQ(a.world->GetSubStepping(), b.world->GetSubStepping());
    EXPECT_EQ(a.world->GetAutoClearForces(), b.world->GetAutoClearForces());
    EXPECT_EQ(a.settings.stepsPerSecond, b.settings.stepsPerSecond);
    EXPECT_EQ(a.settings.velocityIterations, b.settings.velocityIterations);
    EXPECT_EQ(a.settings.positionIterations, b.settings.positionIterations);
}

class RoundTrip : public ::testing::TestWithParam<std::filesystem::path>
{
};

TEST_P(RoundTrip, SavedSampleLoadsAsTheSameWorld)
{
    Scene original = LoadRubeFile(GetParam());
    const std::string saved = SaveRubeString(original);
    Scene reloaded = LoadRubeString(saved, "saved.json");
    ExpectSameScene(original, reloaded);
    // A second round changes nothing that matters either.
    Scene again = LoadRubeString(SaveRubeString(reloaded), "saved2.json");
    ExpectSameScene(reloaded, again);
}

TEST_P(RoundTrip, SavedAfterSteppingHoldsTheCurrentState)
{
    Scene original = LoadRubeFile(GetParam());
    for (int i = 0; i < 30; ++i)
    {
        original.world->Step(1.0f / 60.0f, 8, 3);
    }
    Scene reloaded = LoadRubeString(SaveRubeString(original), "stepped.json");
    ExpectSameScene(original, reloaded);
}

INSTANTIATE_TEST_SUITE_P(SharedFiles, RoundTrip, ::testing::ValuesIn(test::SampleFiles()),
                         test::SampleTestName);

TEST(RoundTrip, EveryShapeJointPropertyAndImage)
{
    const std::string properties =
        R"("customProperties": [{"name": "i", "int": 3}, {"name": "f", "float": 0.1},
        {"name": "s", "string": "x\"y"}, {"name": "b", "bool": false}, {"name": "v", "vec2": {"x": 1, "y": -1}},
        {"name": "c", "color": [1, 2, 3, 4]}])";
    const std::string json = R"({"gravity": {"x": 0, "y": -9.8}, "stepsPerSecond": 30, )" + properties + R"(,
      "body": [
        {"name": "ground", "type": 0, "fixture": [
          {"name": "edge", "edge": {"vertex1": {"x": -5, "y": 0}, "vertex2": {"x": 5, "y": 0}}},
          {"name": "oneSided", "edge": {"vertex1": {"x": -5, "y": 1}, "vertex2": {"x": 5, "y": 1},
            "hasVertex0": true, "hasVertex3": true, "vertex0": {"x": -6, "y": 1.5}, "vertex3": {"x": 6, "y": 1.5}}},
          {"name": "chain", "chain": {"vertices": {"x": [-5, 0, 5], "y": [-1, -2, -1]}}},
          {"name": "loop", "loop": {"vertices": {"x": [10, 12, 12, 10], "y": [0, 0, 2, 2]}}},
          {"name": "twoPoint", "polygon": {"vertices": {"x": [20, 21], "y": [0, 0]}}}]},
        {"name": "a", "type": 2, "awake": true, "position": {"x": 0, "y": 3}, "angle": 0.3,
         "linearVelocity": {"x": 1, "y": 2}, "angularVelocity": 0.5, "linearDamping": 0.1, "angularDamping": 0.2,
         "gravityScale": 0.5, "bullet": true, )" +
                             properties + R"(, "fixture": [
          {"name": "box", "density": 2, "friction": 0.4, "restitution": 0.3, "sensor": false,
           "filter-categoryBits": 2, "filter-maskBits": 5, "filter-groupIndex": -1, )" +
                             properties + R"(,
           "polygon": {"vertices": {"x": [0.5, 0.5, -0.5, -0.5], "y": [-0.5, 0.5, 0.5, -0.5]}}},
          {"name": "ball", "density": 1, "circle": {"radius": 0.25, "center": {"x": 0.5, "y": 0.5}}}]},
        {"name": "b", "type": 2, "awake": true, "position": {"x": 3, "y": 3}, "fixture": [
          {"density": 1, "circle": {"radius": 0.5}}]},
        {"name": "k", "type": 1, "awake": true, "position": {"x": 6, "y": 3}, "linearVelocity": {"x": -1, "y": 0},
         "fixture": [{"circle": {"radius": 0.5}}]},
        {"name": "sleeper", "type": 2, "awake": false, "fixedRotation": true, "active": false,
         "allowSleep": false, "position": {"x": 9, "y": 3}, "fixture": [{"density": 1, "circle": {"radius": 0.5}}]}],
      "joint": [
        {"name": "gear", "type": "gear", "bodyA": 1, "bodyB": 2, "joint1": 1, "joint2": 2, "ratio": 2},
        {"name": "rev", "type": "revolute", "bodyA": 0, "bodyB": 1, "anchorA": {"x": 0, "y": 3}, "enableLimit": true,
         "lowerLimit": -1, "upperLimit": 1, "enableMotor": true, "motorSpeed": 1, "maxMotorTorque": 5, )" +
                             properties + R"(},
        {"name": "pri", "type": "prismatic", "bodyA": 0, "bodyB": 2, "anchorA": {"x": 3, "y": 3},
         "localAxisA": {"x": 0, "y": 1}, "enableLimit": true, "lowerLimit": -1, "upperLimit": 1},
        {"name": "dist", "type": "distance", "bodyA": 1, "bodyB": 2, "length": 3, "frequency": 2,
         "dampingRatio": 0.3},
        {"name": "rigid", "type": "distance", "bodyA": 1, "bodyB": 2, "length": 3},
        {"name": "rope", "type": "rope", "bodyA": 1, "bodyB": 2, "maxLength": 5},
        {"name": "pulley", "type": "pulley", "bodyA": 1, "bodyB": 2, "groundAnchorA": {"x": 0, "y": 6},
         "groundAnchorB": {"x": 3, "y": 6}, "anchorA": {"x": 0.1, "y": 0.2}, "lengthA": 3, "lengthB": 3,
         "ratio": 1.5},
        {"name": "mouse", "type": "mouse", "bodyA": 0, "bodyB": 1, "target": {"x": 1, "y": 4},
         "anchorB": {"x": 0.2, "y": 3.1}, "maxForce": 50, "frequency": 4, "dampingRatio": 0.6},
        {"name": "wheel", "type": "wheel", "bodyA": 1, "bodyB": 2, "localAxisA": {"x": 0, "y": 1},
         "enableMotor": true, "motorSpeed": 3, "maxMotorTorque": 4, "springFrequency": 3, "springDampingRatio": 0.5},
        {"name": "weld", "type": "weld", "bodyA": 1, "bodyB": 2, "refAngle": 0.1, "frequency": 1,
         "dampingRatio": 0.2},
        {"name": "friction", "type": "friction", "bodyA": 1, "bodyB": 2, "maxForce": 2, "maxTorque": 3},
        {"name": "motor", "type": "motor", "bodyA": 1, "bodyB": 2, "linearOffset": {"x": 1, "y": 0},
         "refAngle": 0.2, "maxForce": 6, "maxTorque": 7, "correctionFactor": 0.5}],
      "image": [{"name": "img", "file": "a.png", "body": 1, "center": {"x": 0.5, "y": 0}, "scale": 1.5,
                 "opacity": 0.5, "renderOrder": 2, "flip": true, "colorTint": [255, 128, 0, 255],
                 "corners": {"x": [-1, 1, 1, -1], "y": [-1, -1, 1, 1]},
                 "glTexCoordPointer": [0, 0, 1, 0, 1, 1, 0, 1], "glDrawElements": [0, 1, 2, 2, 3, 0], )" +
                             properties + R"(}]})";
    Scene original = LoadRubeString(json, "all.json");
    const std::string saved = SaveRubeString(original);
    Scene reloaded = LoadRubeString(saved, "saved.json");
    ExpectSameScene(original, reloaded);
    EXPECT_EQ(reloaded.FindJoint("rope")->type, "rope");
    EXPECT_EQ(reloaded.FindJoint("gear")->joint->GetType(), e_gearJoint);
    EXPECT_EQ(reloaded.FindFixture("twoPoint")->fixture->GetType(), b2Shape::e_edge);
    EXPECT_FALSE(reloaded.FindBody("sleeper")->body->IsAwake());

    // The text is plain JSON numbers, not hex.
    const nlohmann::json document = nlohmann::json::parse(saved);
    EXPECT_TRUE(document["body"][1]["position"]["y"].is_number());
    EXPECT_EQ(document["body"][1]["fixture"][0]["friction"].dump(), "0.4");
}

TEST(RoundTrip, ObjectsAddedOrRemovedAfterLoading)
{
    Scene scene = LoadRubeString(test::World(test::Box(0.0f) + "," + test::Box(3.0f)), "s.json");
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(7.0f, 1.0f);
    b2Body* added = scene.world->CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = 0.5f;
    added->CreateFixture(&circle, 1.0f);
    scene.world->DestroyBody(scene.bodies[0].body);

    Scene reloaded = LoadRubeString(SaveRubeString(scene), "s2.json");
    ASSERT_EQ(reloaded.bodies.size(), 2u);
    EXPECT_EQ(reloaded.bodies[0].body->GetPosition(), b2Vec2(3.0f, 0.0f));
    EXPECT_EQ(reloaded.bodies[1].body->GetPosition(), b2Vec2(7.0f, 1.0f));
    EXPECT_EQ(reloaded.bodies[1].body->GetFixtureList()->GetType(), b2Shape::e_circle);
}

// The stiffness and damping of a joint's spring (wheel, distance, mouse or weld).
std::pair<float, float> SpringOf(b2Joint* joint)
{
    switch (joint->GetType())
    {
    case e_wheelJoint:
        return {static_cast<b2WheelJoint*>(joint)->GetStiffness(),
                static_cast<b2WheelJoint*>(joint)->GetDamping()};
    case e_distanceJoint:
        return {static_cast<b2DistanceJoint*>(joint)->GetStiffness(),
                static_cast<b2DistanceJoint*>(joint)->GetDamping()};
    case e_mouseJoint:
        return {static_cast<b2MouseJoint*>(joint)->GetStiffness(),
                static_cast<b2MouseJoint*>(joint)->GetDamping()};
    default:
        return {static_cast<b2WeldJoint*>(joint)->GetStiffness(),
                static_cast<b2WeldJoint*>(joint)->GetDamping()};
    }
}

// A scene of a static ground and a dynamic body of `mass` and `inertia` (about its origin, at its centre of
// mass) joined by four springs of `frequency` and `ratio`: wheel, distance, mouse, weld.
std::string SpringScene(const std::string& mass, const std::string& inertia, const std::string& frequency,
                        const std::string& ratio)
{
    const std::string spring = R"("frequency": )" + frequency + R"(, "dampingRatio": )" + ratio;
    return R"({"gravity": {"x": 0, "y": -10}, "body": [
        {"name": "ground", "type": 0, "fixture": [{"polygon": {"vertices": {"x": [-9, 9, 9, -9], "y": [-1, -1, 0, 0]}}}]},
        {"name": "car", "type": 2, "position": {"x": 0.3, "y": 1.1}, "massData-mass": )" +
           mass + R"(, "massData-I": )" + inertia +
           R"(, "fixture": [{"density": 1, "circle": {"radius": 0.4}}]}],
      "joint": [
        {"name": "wheel", "type": "wheel", "bodyA": 0, "bodyB": 1, "localAxisA": {"x": 0, "y": 1},
         "springFrequency": )" +
           frequency + R"(, "springDampingRatio": )" + ratio + R"(},
        {"name": "distance", "type": "distance", "bodyA": 0, "bodyB": 1, "length": 1.3, )" +
           spring + R"(},
        {"name": "mouse", "type": "mouse", "bodyA": 0, "bodyB": 1, "target": {"x": 1, "y": 4}, "maxForce": 50, )" +
           spring + R"(},
        {"name": "weld", "type": "weld", "bodyA": 0, "bodyB": 1, )" +
           spring + "}]}";
}

// Frequency and damping ratio become Box2D 2.4's stiffness and damping on loading and go back on saving; the
// computed inverse can be a float away, and a trial saw a damping ratio of 0.7 creep by an ulp at each save
// and load (0.699999988, 0.70000005, 0.7000001, ...); a re-check found the largest ratio saved as
// 1000.00006, which the reader then refused. The writer saves floats within the reader's ranges that load
// as the springs were: the joints are the same bits, and saving again writes the same text. Random masses,
// inertias, frequencies and ratios (a seeded generator of the test's own), the re-check's cases and the
// ranges' ends.
TEST(RoundTrip, SavedSpringsLoadAsTheyWereAndSaveTheSameText)
{
    std::vector<std::array<std::string, 4>> cases = {
        {"0.301413425", "0.0534484167", "2.0872067", "0.581718489"},
        {"1", "1", "3", "1000"},
        {"17", "2.5", "10000", "0.7"},
        {"0.1", "0.01", "10000", "1000"}};
    std::uint64_t state = 12345;
    const auto uniform = [&](double low, double high)
    {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return low + (high - low) * static_cast<double>(state >> 11) / 9007199254740992.0;
    };
    const auto text = [](double value)
    {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.9g", value);
        return std::string(buffer);
    };
    for (int i = 0; i < 500; ++i)
    {
        const double mass = std::pow(10.0, uniform(-1.0, 2.0));
        cases.push_back({text(mass), text(mass * uniform(0.05, 1.0)),
                         text(std::pow(10.0, uniform(-1.0, 1.5))), text(std::pow(10.0, uniform(-2.0, 0.5)))});
    }
    int springs = 0;
    for (const auto& [mass, inertia, frequency, ratio] : cases)
    {
        SCOPED_TRACE("mass " + mass + ", inertia " + inertia + ", frequency " + frequency + ", ratio " +
                     ratio);
        Scene original = LoadRubeString(SpringScene(mass, inertia, frequency, ratio), "springs.json");
        const std::string saved = SaveRubeString(original);
        Scene reloaded = LoadRubeString(saved, "saved.json");
        ASSERT_EQ(reloaded.joints.size(), original.joints.size());
        for (std::size_t j = 0; j < original.joints.size(); ++j)
        {
            const auto before = SpringOf(original.joints[j].joint);
            const auto after = SpringOf(reloaded.joints[j].joint);
            EXPECT_GT(before.second, 0.0f) << original.joints[j].name;
            EXPECT_EQ(after.first, before.first) << original.joints[j].name << ": stiffness";
            EXPECT_EQ(after.second, before.second) << original.joints[j].name << ": damping";
            ++springs;
        }
        EXPECT_EQ(SaveRubeString(reloaded), saved);
    }
    EXPECT_EQ(springs, 4 * 504);
}

} // namespace
} // namespace cfx
