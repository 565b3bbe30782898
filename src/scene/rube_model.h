// A RUBE document as read and checked, before any Box2D object exists.
//
// The reader (rube_reader.cpp) fills these from JSON and reports every problem; the builder
// (scene_builder.cpp) only ever sees documents without problems, so that no Box2D assert can fire.
#pragma once

#include "contactfx/scene/rube.h"

#include <box2d/box2d.h>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cfx::scene_detail
{

struct ShapeModel
{
    enum class Kind
    {
        circle,
        polygon,
        edge,
        chain,
    };
    Kind kind = Kind::circle;

    // circle
    float radius = 0.0f;
    b2Vec2 center{0.0f, 0.0f};

    // polygon (file order) and chain; a loop has no repeated closing vertex
    std::vector<b2Vec2> vertices;
    bool loop = false;
    b2Vec2 prevVertex{0.0f, 0.0f}; ///< open chain ghost vertices (extrapolated when the file has none)
    b2Vec2 nextVertex{0.0f, 0.0f};

    // edge
    b2Vec2 vertex0{0.0f, 0.0f}, vertex1{0.0f, 0.0f}, vertex2{0.0f, 0.0f}, vertex3{0.0f, 0.0f};
    bool oneSided = false;
};

struct FixtureModel
{
    std::string name;
    float friction = 0.0f;
    float restitution = 0.0f;
    float density = 0.0f;
    bool sensor = false;
    std::uint16_t categoryBits = 0x0001;
    std::uint16_t maskBits = 0xFFFF;
    std::int16_t groupIndex = 0;
    ShapeModel shape;
    CustomProperties properties;
};

struct BodyModel
{
    std::string path; ///< "body[3]", for problems found while building
    std::string name;
    b2BodyType type = b2_staticBody;
    b2Vec2 position{0.0f, 0.0f};
    float angle = 0.0f;
    b2Vec2 linearVelocity{0.0f, 0.0f};
    float angularVelocity = 0.0f;
    float linearDamping = 0.0f;
    float angularDamping = 0.0f;
    float gravityScale = 1.0f;
    bool bullet = false;
    bool allowSleep = true;
    bool awake = false;
    bool enabled = true;
    bool fixedRotation = false;
    std::optional<b2MassData> massData; ///< present when the file has any massData-* field
    std::vector<FixtureModel> fixtures;
    CustomProperties properties;
};

enum class JointKind
{
    revolute,
    prismatic,
    distance,
    rope,
    pulley,
    mouse,
    gear,
    wheel,
    weld,
    friction,
    motor,
};

/// Every field any joint type has; each type reads its own (defaults follow Box2D's b2*JointDef).
struct JointModel
{
    std::string path; ///< "joint[2]"
    std::string name;
    std::string type; ///< as in the file
    JointKind kind = JointKind::revolute;
    int bodyA = -1;
    int bodyB = -1;
    bool collideConnected = false;
    b2Vec2 anchorA{0.0f, 0.0f};
    b2Vec2 anchorB{0.0f, 0.0f};

    float referenceAngle = 0.0f;
    bool enableLimit = false;
    float lowerLimit = 0.0f;
    float upperLimit = 0.0f;
    bool enableMotor = false;
    float motorSpeed = 0.0f;
    float maxMotorTorque = 0.0f;
    float maxMotorForce = 0.0f;
    b2Vec2 localAxisA{1.0f, 0.0f};

    float length = 1.0f; ///< distance; rope: maxLength
    std::optional<float> minLength;
    std::optional<float> maxLength;
    float frequency = 0.0f; ///< Hz, converted to stiffness when building
    float dampingRatio = 0.0f;

    b2Vec2 groundAnchorA{-1.0f, 1.0f};
    b2Vec2 groundAnchorB{1.0f, 1.0f};
    float lengthA = 0.0f;
    float lengthB = 0.0f;
    float ratio = 1.0f; ///< pulley, gear

    b2Vec2 target{0.0f, 0.0f};
    std::optional<b2Vec2> mouseAnchor; ///< world point of the mouse joint on body B, when saved
    float maxForce = 0.0f;
    float maxTorque = 0.0f;

    int joint1 = -1;
    int joint2 = -1;

    b2Vec2 linearOffset{0.0f, 0.0f};
    float correctionFactor = 0.3f;

    CustomProperties properties;
};

struct RubeDocument
{
    b2Vec2 gravity{0.0f, -10.0f};
    WorldSettings settings;
    std::vector<BodyModel> bodies;
    std::vector<JointModel> joints;
    std::vector<SceneImage> images;
    CustomProperties properties;
    SceneCounts counts;
};

} // namespace cfx::scene_detail
