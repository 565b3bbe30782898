// Every joint type RUBE saves becomes the right Box2D 2.4.1 joint with its values.
#include "scene/rube_test_util.h"

#include <gtest/gtest.h>

namespace cfx
{
namespace
{

/// Two dynamic unit boxes (bodies 0 and 1), a static ground box (body 2), and the given joints.
Scene LoadJoints(const std::string& joints)
{
    return LoadRubeString(
        test::World(test::Box(0.0f) + "," + test::Box(3.0f) + "," + test::Box(0.0f, 0), joints),
        "joints.json");
}

template <class T> T* Joint(const Scene& scene, std::size_t index)
{
    return static_cast<T*>(scene.joints.at(index).joint);
}

TEST(RubeJoints, Revolute)
{
    Scene scene =
        LoadJoints(R"({"type": "revolute", "name": "r", "bodyA": 0, "bodyB": 1, "collideConnected": true,
        "anchorA": {"x": 1, "y": 0}, "anchorB": {"x": -2, "y": 0}, "refAngle": 0.1, "enableLimit": true,
        "lowerLimit": -0.5, "upperLimit": 0.5, "enableMotor": true, "motorSpeed": 2, "maxMotorTorque": 10})");
    ASSERT_EQ(scene.joints.at(0).joint->GetType(), e_revoluteJoint);
    auto* joint = Joint<b2RevoluteJoint>(scene, 0);
    EXPECT_EQ(scene.joints[0].name, "r");
    EXPECT_EQ(scene.joints[0].type, "revolute");
    EXPECT_TRUE(joint->GetCollideConnected());
    EXPECT_EQ(joint->GetBodyA(), scene.bodies[0].body);
    EXPECT_EQ(joint->GetBodyB(), scene.bodies[1].body);
    EXPECT_EQ(joint->GetLocalAnchorA(), b2Vec2(1.0f, 0.0f));
    EXPECT_EQ(joint->GetLocalAnchorB(), b2Vec2(-2.0f, 0.0f));
    EXPECT_EQ(joint->GetReferenceAngle(), 0.1f);
    EXPECT_TRUE(joint->IsLimitEnabled());
    EXPECT_EQ(joint->GetLowerLimit(), -0.5f);
    EXPECT_EQ(joint->GetUpperLimit(), 0.5f);
    EXPECT_TRUE(joint->IsMotorEnabled());
    EXPECT_EQ(joint->GetMotorSpeed(), 2.0f);
    EXPECT_EQ(joint->GetMaxMotorTorque(), 10.0f);
}

TEST(RubeJoints, PrismaticWithNewAndOldAxisNames)
{
    Scene scene = LoadJoints(R"({"type": "prismatic", "bodyA": 2, "bodyB": 0, "localAxisA": {"x": 0, "y": 1},
        "refAngle": 0.2, "enableLimit": true, "lowerLimit": -1, "upperLimit": 2, "enableMotor": true,
        "motorSpeed": 3, "maxMotorForce": 50},
        {"type": "prismatic", "bodyA": 2, "bodyB": 1, "localAxis1": {"x": 1, "y": 0}})");
    ASSERT_EQ(scene.joints.at(0).joint->GetType(), e_prismaticJoint);
    auto* joint = Joint<b2PrismaticJoint>(scene, 0);
    EXPECT_EQ(joint->GetLocalAxisA(), b2Vec2(0.0f, 1.0f));
    EXPECT_EQ(joint->GetReferenceAngle(), 0.2f);
    EXPECT_EQ(joint->GetLowerLimit(), -1.0f);
    EXPECT_EQ(joint->GetUpperLimit(), 2.0f);
    EXPECT_EQ(joint->GetMaxMotorForce(), 50.0f);
    EXPECT_EQ(joint->GetMotorSpeed(), 3.0f);
    EXPECT_EQ(Joint<b2PrismaticJoint>(scene, 1)->GetLocalAxisA(), b2Vec2(1.0f, 0.0f));
}

TEST(RubeJoints, DistanceRigidAndSoft)
{
    Scene scene = LoadJoints(R"({"type": "distance", "bodyA": 0, "bodyB": 1, "length": 3},
        {"type": "distance", "bodyA": 0, "bodyB": 1, "length": 2.5, "frequency": 4, "dampingRatio": 0.5})");
    auto* rigid = Joint<b2DistanceJoint>(scene, 0);
    ASSERT_EQ(rigid->GetType(), e_distanceJoint);
    EXPECT_EQ(rigid->GetLength(), 3.0f);
    EXPECT_EQ(rigid->GetMinLength(), 3.0f);
    EXPECT_EQ(rigid->GetMaxLength(), 3.0f);
    EXPECT_EQ(rigid->GetStiffness(), 0.0f);

    auto* soft = Joint<b2DistanceJoint>(scene, 1);
    float stiffness = 0.0f;
    float damping = 0.0f;
    b2LinearStiffness(stiffness, damping, 4.0f, 0.5f, scene.bodies[0].body, scene.bodies[1].body);
    EXPECT_GT(stiffness, 0.0f);
    EXPECT_EQ(soft->GetStiffness(), stiffness);
    EXPECT_EQ(soft->GetDamping(), damping);
    EXPECT_EQ(soft->GetLength(), 2.5f);
    EXPECT_LT(soft->GetMinLength(), 2.5f);
    EXPECT_GT(soft->GetMaxLength(), 1e30f);
}

TEST(RubeJoints, RopeBecomesADistanceJointWithMaxLength)
{
    Scene scene = LoadJoints(R"({"type": "rope", "name": "rope", "bodyA": 0, "bodyB": 1,
        "anchorA": {"x": 0.5, "y": 0}, "maxLength": 4})");
    ASSERT_EQ(scene.joints.at(0).joint->GetType(), e_distanceJoint);
    EXPECT_EQ(scene.joints[0].type, "rope");
    auto* rope = Joint<b2DistanceJoint>(scene, 0);
    EXPECT_EQ(rope->GetMaxLength(), 4.0f);
    EXPECT_EQ(rope->GetMinLength(), b2_linearSlop); // 0, clamped by Box2D
    EXPECT_EQ(rope->GetStiffness(), 0.0f);
    EXPECT_EQ(rope->GetLocalAnchorA(), b2Vec2(0.5f, 0.0f));
}

TEST(RubeJoints, Pulley)
{
    Scene scene = LoadJoints(R"({"type": "pulley", "bodyA": 0, "bodyB": 1, "groundAnchorA": {"x": 0, "y": 5},
        "groundAnchorB": {"x": 3, "y": 5}, "lengthA": 5, "lengthB": 4, "ratio": 2})");
    auto* pulley = Joint<b2PulleyJoint>(scene, 0);
    ASSERT_EQ(pulley->GetType(), e_pulleyJoint);
    EXPECT_EQ(pulley->GetGroundAnchorA(), b2Vec2(0.0f, 5.0f));
    EXPECT_EQ(pulley->GetGroundAnchorB(), b2Vec2(3.0f, 5.0f));
    EXPECT_EQ(pulley->GetLengthA(), 5.0f);
    EXPECT_EQ(pulley->GetLengthB(), 4.0f);
    EXPECT_EQ(pulley->GetRatio(), 2.0f);
}

TEST(RubeJoints, Mouse)
{
    Scene scene = LoadJoints(R"({"type": "mouse", "bodyA": 2, "bodyB": 0, "target": {"x": 1, "y": 2},
        "anchorB": {"x": 0.25, "y": 0}, "maxForce": 100, "frequency": 5, "dampingRatio": 0.7})");
    auto* mouse = Joint<b2MouseJoint>(scene, 0);
    ASSERT_EQ(mouse->GetType(), e_mouseJoint);
    EXPECT_EQ(mouse->GetTarget(), b2Vec2(1.0f, 2.0f));
    EXPECT_EQ(mouse->GetAnchorB(), b2Vec2(0.25f, 0.0f)); // the grabbed point on body B, in world coordinates
    EXPECT_EQ(mouse->GetMaxForce(), 100.0f);
    float stiffness = 0.0f;
    float damping = 0.0f;
    b2LinearStiffness(stiffness, damping, 5.0f, 0.7f, scene.bodies[2].body, scene.bodies[0].body);
    EXPECT_EQ(mouse->GetStiffness(), stiffness);
    EXPECT_EQ(mouse->GetDamping(), damping);
}

TEST(RubeJoints, GearIsCreatedAfterTheJointsItRefersTo)
{
    Scene scene = LoadJoints(R"({"type": "gear", "name": "gear", "bodyA": 0, "bodyB": 1, "joint1": 1,
        "joint2": 2, "ratio": -2},
        {"type": "revolute", "bodyA": 2, "bodyB": 0},
        {"type": "prismatic", "bodyA": 2, "bodyB": 1, "localAxisA": {"x": 1, "y": 0}})");
    ASSERT_EQ(scene.joints.size(), 3u);
    auto* gear = Joint<b2GearJoint>(scene, 0);
    ASSERT_EQ(gear->GetType(), e_gearJoint);
    EXPECT_EQ(scene.joints[0].name, "gear");
    EXPECT_EQ(gear->GetJoint1(), scene.joints[1].joint);
    EXPECT_EQ(gear->GetJoint2(), scene.joints[2].joint);
    EXPECT_EQ(gear->GetRatio(), -2.0f);

    Scene derived = LoadJoints(R"({"type": "revolute", "bodyA": 2, "bodyB": 0},
        {"type": "revolute", "bodyA": 2, "bodyB": 1}, {"type": "gear", "joint1": 0, "joint2": 1})");
    EXPECT_EQ(derived.joints.at(2).joint->GetType(), e_gearJoint);
}

TEST(RubeJoints, WheelSpringAndMotor)
{
    Scene scene = LoadJoints(R"({"type": "wheel", "bodyA": 0, "bodyB": 1, "localAxisA": {"x": 0, "y": 1},
        "enableMotor": true, "motorSpeed": -4, "maxMotorTorque": 20, "springFrequency": 3.8,
        "springDampingRatio": 0.7})");
    auto* wheel = Joint<b2WheelJoint>(scene, 0);
    ASSERT_EQ(wheel->GetType(), e_wheelJoint);
    EXPECT_EQ(wheel->GetLocalAxisA(), b2Vec2(0.0f, 1.0f));
    EXPECT_TRUE(wheel->IsMotorEnabled());
    EXPECT_EQ(wheel->GetMotorSpeed(), -4.0f);
    EXPECT_EQ(wheel->GetMaxMotorTorque(), 20.0f);
    float stiffness = 0.0f;
    float damping = 0.0f;
    b2LinearStiffness(stiffness, damping, 3.8f, 0.7f, scene.bodies[0].body, scene.bodies[1].body);
    EXPECT_EQ(wheel->GetStiffness(), stiffness);
    EXPECT_EQ(wheel->GetDamping(), damping);
}

TEST(RubeJoints, WeldUsesAngularStiffness)
{
    Scene scene = LoadJoints(R"({"type": "weld", "bodyA": 0, "bodyB": 1, "refAngle": 0.3, "frequency": 2,
        "dampingRatio": 0.1})");
    auto* weld = Joint<b2WeldJoint>(scene, 0);
    ASSERT_EQ(weld->GetType(), e_weldJoint);
    EXPECT_EQ(weld->GetReferenceAngle(), 0.3f);
    float stiffness = 0.0f;
    float damping = 0.0f;
    b2AngularStiffness(stiffness, damping, 2.0f, 0.1f, scene.bodies[0].body, scene.bodies[1].body);
    EXPECT_EQ(weld->GetStiffness(), stiffness);
    EXPECT_EQ(weld->GetDamping(), damping);
}

TEST(RubeJoints, FrictionAndMotor)
{
    Scene scene = LoadJoints(R"({"type": "friction", "bodyA": 0, "bodyB": 1, "maxForce": 5, "maxTorque": 6},
        {"type": "motor", "bodyA": 0, "bodyB": 1, "linearOffset": {"x": 1, "y": 2}, "refAngle": 0.5,
         "maxForce": 7, "maxTorque": 8, "correctionFactor": 0.4},
        {"type": "motor", "bodyA": 0, "bodyB": 1, "anchorA": {"x": 3, "y": 4}})");
    auto* friction = Joint<b2FrictionJoint>(scene, 0);
    ASSERT_EQ(friction->GetType(), e_frictionJoint);
    EXPECT_EQ(friction->GetMaxForce(), 5.0f);
    EXPECT_EQ(friction->GetMaxTorque(), 6.0f);
    auto* motor = Joint<b2MotorJoint>(scene, 1);
    ASSERT_EQ(motor->GetType(), e_motorJoint);
    EXPECT_EQ(motor->GetLinearOffset(), b2Vec2(1.0f, 2.0f));
    EXPECT_EQ(motor->GetAngularOffset(), 0.5f);
    EXPECT_EQ(motor->GetMaxForce(), 7.0f);
    EXPECT_EQ(motor->GetMaxTorque(), 8.0f);
    EXPECT_EQ(motor->GetCorrectionFactor(), 0.4f);
    EXPECT_EQ(Joint<b2MotorJoint>(scene, 2)->GetLinearOffset(), b2Vec2(3.0f, 4.0f)); // pre-1.7 RUBE files
}

TEST(RubeJoints, AllTypesStepTogether)
{
    Scene scene = LoadJoints(R"({"type": "revolute", "bodyA": 2, "bodyB": 0},
        {"type": "prismatic", "bodyA": 2, "bodyB": 1},
        {"type": "distance", "bodyA": 0, "bodyB": 1, "length": 3},
        {"type": "rope", "bodyA": 0, "bodyB": 1, "maxLength": 4},
        {"type": "pulley", "bodyA": 0, "bodyB": 1, "ratio": 1, "lengthA": 1, "lengthB": 1},
        {"type": "mouse", "bodyA": 2, "bodyB": 0, "maxForce": 10, "frequency": 5, "dampingRatio": 0.7},
        {"type": "gear", "bodyA": 0, "bodyB": 1, "joint1": 0, "joint2": 1, "ratio": 1},
        {"type": "wheel", "bodyA": 0, "bodyB": 1, "springFrequency": 4, "springDampingRatio": 0.7},
        {"type": "weld", "bodyA": 0, "bodyB": 1},
        {"type": "friction", "bodyA": 0, "bodyB": 1, "maxForce": 1, "maxTorque": 1},
        {"type": "motor", "bodyA": 0, "bodyB": 1})");
    EXPECT_EQ(scene.world->GetJointCount(), 11);
    for (int i = 0; i < 120; ++i)
    {
        scene.world->Step(1.0f / 60.0f, 8, 3);
    }
    EXPECT_TRUE(scene.bodies[0].body->GetPosition().IsValid());
}

} // namespace
} // namespace cfx
