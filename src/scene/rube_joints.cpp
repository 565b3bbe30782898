#include "scene/rube_joints.h"

#include "scene/rube_limits.h"
#include "scene/stiffness.h"

#include <array>
#include <cfloat>
#include <cmath>
#include <string>

namespace cfx::scene_detail
{

namespace
{

using M = JointModel;

// Fields several types share.
const JointField kAnchorA{.key = "anchorA", .member = &M::anchorA, .limits = kCoordinate, .common = true};
const JointField kAnchorB{.key = "anchorB", .member = &M::anchorB, .limits = kCoordinate, .common = true};
const JointField kRefAngle{.key = "refAngle", .member = &M::referenceAngle, .limits = kCoordinate};
const JointField kEnableLimit{.key = "enableLimit", .member = &M::enableLimit};
const JointField kLowerLimit{.key = "lowerLimit", .member = &M::lowerLimit, .limits = kCoordinate};
const JointField kUpperLimit{
    .key = "upperLimit", .member = &M::upperLimit, .limits = kCoordinate, .atLeast = "lowerLimit"};
const JointField kEnableMotor{.key = "enableMotor", .member = &M::enableMotor};
const JointField kMotorSpeed{.key = "motorSpeed", .member = &M::motorSpeed, .limits = kSpeed};
const JointField kMaxMotorTorque{.key = "maxMotorTorque", .member = &M::maxMotorTorque, .limits = kForce};
const JointField kFrequencyField{.key = "frequency", .member = &M::frequency, .limits = kFrequency};
const JointField kDampingRatioField{
    .key = "dampingRatio", .member = &M::dampingRatio, .limits = kDampingRatio};
const JointField kMaxForce{.key = "maxForce", .member = &M::maxForce, .limits = kForce};
const JointField kMaxTorque{.key = "maxTorque", .member = &M::maxTorque, .limits = kForce};
// b2dJson also writes the current joint speed of revolute and prismatic joints, which Box2D cannot set.
const JointField kJointSpeed{.key = "jointSpeed"};

// Defaults follow Box2D's b2*JointDef, except as RUBE saves them (springs as frequency and damping ratio).
const JointField kRevoluteFields[] = {kAnchorA,    kAnchorB,     kRefAngle,   kEnableLimit,    kLowerLimit,
                                      kUpperLimit, kEnableMotor, kMotorSpeed, kMaxMotorTorque, kJointSpeed};
const JointField kPrismaticFields[] = {
    kAnchorA,
    kAnchorB,
    {.key = "localAxisA",
     .member = &M::localAxisA,
     .limits = kCoordinate,
     .vector = {1.0f, 0.0f},
     .alias = "localAxis1",
     .nonZero = true},
    kRefAngle,
    kEnableLimit,
    kLowerLimit,
    kUpperLimit,
    kEnableMotor,
    kMotorSpeed,
    {.key = "maxMotorForce", .member = &M::maxMotorForce, .limits = kForce},
    kJointSpeed};
// minLength and maxLength are Box2D 2.4 extensions (written by SaveRubeString): explicit length limits.
// Box2D's default maxLength is FLT_MAX (no limit), and the length is clamped between them, so any bound is
// finite.
const JointField kDistanceFields[] = {
    kAnchorA,
    kAnchorB,
    {.key = "length", .member = &M::length, .limits = kLength, .number = 1.0f},
    kFrequencyField,
    kDampingRatioField,
    {.key = "minLength", .member = &M::minLength, .limits = kNonNegative},
    {.key = "maxLength", .member = &M::maxLength, .limits = kNonNegative, .atLeast = "minLength"}};
const JointField kRopeFields[] = {
    kAnchorA, kAnchorB, {.key = "maxLength", .member = &M::length, .limits = kLength}};
const JointField kPulleyFields[] = {
    {.key = "groundAnchorA", .member = &M::groundAnchorA, .limits = kCoordinate, .vector = {-1.0f, 1.0f}},
    {.key = "groundAnchorB", .member = &M::groundAnchorB, .limits = kCoordinate, .vector = {1.0f, 1.0f}},
    kAnchorA,
    kAnchorB,
    {.key = "lengthA", .member = &M::lengthA, .limits = kLength},
    {.key = "lengthB", .member = &M::lengthB, .limits = kLength},
    {.key = "ratio", .member = &M::ratio, .limits = kPulleyRatio, .number = 1.0f}};
// anchorB of a mouse joint is the grabbed point in world coordinates (afterRead).
const JointField kMouseFields[] = {{.key = "target", .member = &M::target, .limits = kCoordinate},
                                   kAnchorB,
                                   kMaxForce,
                                   kFrequencyField,
                                   kDampingRatioField};
// joint1 and joint2 are read by the reader's gear check, once every joint is read.
const JointField kGearFields[] = {
    {.key = "joint1", .member = &M::joint1},
    {.key = "joint2", .member = &M::joint2},
    {.key = "ratio", .member = &M::ratio, .limits = kGearRatio, .number = 1.0f}};
// enableLimit, lowerLimit and upperLimit are Box2D 2.4 extensions (written by SaveRubeString).
const JointField kWheelFields[] = {
    kAnchorA,
    kAnchorB,
    {.key = "localAxisA",
     .member = &M::localAxisA,
     .limits = kCoordinate,
     .vector = {1.0f, 0.0f},
     .nonZero = true},
    kEnableMotor,
    kMotorSpeed,
    kMaxMotorTorque,
    {.key = "springFrequency", .member = &M::frequency, .limits = kFrequency},
    {.key = "springDampingRatio", .member = &M::dampingRatio, .limits = kDampingRatio},
    kEnableLimit,
    kLowerLimit,
    kUpperLimit};
const JointField kWeldFields[] = {kAnchorA, kAnchorB, kRefAngle, kFrequencyField, kDampingRatioField};
const JointField kFrictionFields[] = {kAnchorA, kAnchorB, kMaxForce, kMaxTorque};
// Before RUBE 1.7 the linear offset was saved as anchorA (afterRead).
const JointField kMotorFields[] = {
    {.key = "linearOffset", .member = &M::linearOffset, .limits = kCoordinate},
    kRefAngle,
    {.key = "maxForce", .member = &M::maxForce, .limits = kForce, .number = 1.0f},
    {.key = "maxTorque", .member = &M::maxTorque, .limits = kForce, .number = 1.0f},
    {.key = "correctionFactor", .member = &M::correctionFactor, .limits = kUnit, .number = 0.3f}};

constexpr std::string_view kCommonKeys[] = {
    "type", "name", "bodyA", "bodyB", "collideConnected", "anchorA", "anchorB", "customProperties"};

b2Joint* Finish(b2JointDef& def, const JointModel& model, JointBuild& context)
{
    def.bodyA = context.bodyA;
    def.bodyB = context.bodyB;
    def.collideConnected = model.collideConnected;
    return context.world.CreateJoint(&def);
}

/// Stiffness and damping from RUBE's frequency and damping ratio; false (after reporting) when they overflow.
bool Stiffness(const JointModel& model, const JointType& type, bool angular, JointBuild& context,
               float& stiffness, float& damping)
{
    if (angular)
    {
        b2AngularStiffness(stiffness, damping, model.frequency, model.dampingRatio, context.bodyA,
                           context.bodyB);
    }
    else
    {
        b2LinearStiffness(stiffness, damping, model.frequency, model.dampingRatio, context.bodyA,
                          context.bodyB);
    }
    if (!std::isfinite(stiffness) || !std::isfinite(damping))
    {
        context.diagnostics.Add(
            JoinPath(model.path, KeyOf(type, &JointModel::frequency)),
            "the spring is too stiff for the masses it connects: stiffness or damping overflows");
        return false;
    }
    return true;
}

Spring LinearSpring(float stiffness, float damping, b2Joint& joint)
{
    return SpringFromStiffness(stiffness, damping, *joint.GetBodyA(), *joint.GetBodyB(), false);
}

void SetSpring(JointModel& model, const Spring& spring)
{
    model.frequency = spring.frequency;
    model.dampingRatio = spring.dampingRatio;
}

// --- revolute
b2Joint* BuildRevolute(const JointModel& model, const JointType&, JointBuild& context)
{
    b2RevoluteJointDef def;
    def.localAnchorA = model.anchorA;
    def.localAnchorB = model.anchorB;
    def.referenceAngle = model.referenceAngle;
    def.enableLimit = model.enableLimit;
    def.lowerAngle = model.lowerLimit;
    def.upperAngle = model.upperLimit;
    def.enableMotor = model.enableMotor;
    def.motorSpeed = model.motorSpeed;
    def.maxMotorTorque = model.maxMotorTorque;
    return Finish(def, model, context);
}
bool ExtractRevolute(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& revolute = static_cast<b2RevoluteJoint&>(joint);
    model.anchorA = revolute.GetLocalAnchorA();
    model.anchorB = revolute.GetLocalAnchorB();
    model.referenceAngle = revolute.GetReferenceAngle();
    model.enableLimit = revolute.IsLimitEnabled();
    model.lowerLimit = revolute.GetLowerLimit();
    model.upperLimit = revolute.GetUpperLimit();
    model.enableMotor = revolute.IsMotorEnabled();
    model.motorSpeed = revolute.GetMotorSpeed();
    model.maxMotorTorque = revolute.GetMaxMotorTorque();
    return true;
}

// --- prismatic
b2Joint* BuildPrismatic(const JointModel& model, const JointType&, JointBuild& context)
{
    b2PrismaticJointDef def;
    def.localAnchorA = model.anchorA;
    def.localAnchorB = model.anchorB;
    def.localAxisA = model.localAxisA;
    def.referenceAngle = model.referenceAngle;
    def.enableLimit = model.enableLimit;
    def.lowerTranslation = model.lowerLimit;
    def.upperTranslation = model.upperLimit;
    def.enableMotor = model.enableMotor;
    def.motorSpeed = model.motorSpeed;
    def.maxMotorForce = model.maxMotorForce;
    return Finish(def, model, context);
}
bool ExtractPrismatic(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& prismatic = static_cast<b2PrismaticJoint&>(joint);
    model.anchorA = prismatic.GetLocalAnchorA();
    model.anchorB = prismatic.GetLocalAnchorB();
    model.localAxisA = prismatic.GetLocalAxisA();
    model.referenceAngle = prismatic.GetReferenceAngle();
    model.enableLimit = prismatic.IsLimitEnabled();
    model.lowerLimit = prismatic.GetLowerLimit();
    model.upperLimit = prismatic.GetUpperLimit();
    model.enableMotor = prismatic.IsMotorEnabled();
    model.motorSpeed = prismatic.GetMotorSpeed();
    model.maxMotorForce = prismatic.GetMaxMotorForce();
    return true;
}

// --- distance
b2Joint* BuildDistance(const JointModel& model, const JointType& type, JointBuild& context)
{
    b2DistanceJointDef def;
    def.localAnchorA = model.anchorA;
    def.localAnchorB = model.anchorB;
    def.length = model.length;
    if (!Stiffness(model, type, false, context, def.stiffness, def.damping))
    {
        return nullptr;
    }
    // Box2D 2.3's distance joint was rigid at `length` unless it had a spring, which had no limits.
    if (model.frequency > 0.0f)
    {
        def.minLength = 0.0f;
        def.maxLength = FLT_MAX;
    }
    else
    {
        def.minLength = model.length;
        def.maxLength = model.length;
    }
    def.minLength = model.minLength.value_or(def.minLength);
    def.maxLength = model.maxLength.value_or(def.maxLength);
    return Finish(def, model, context);
}
bool ExtractDistance(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& distance = static_cast<b2DistanceJoint&>(joint);
    model.anchorA = distance.GetLocalAnchorA();
    model.anchorB = distance.GetLocalAnchorB();
    model.length = distance.GetLength();
    SetSpring(model, LinearSpring(distance.GetStiffness(), distance.GetDamping(), joint));
    model.minLength = distance.GetMinLength();
    model.maxLength = distance.GetMaxLength();
    return true;
}

// --- rope: Box2D 2.4 has none; a distance joint without spring, slack up to its maximum length.
b2Joint* BuildRope(const JointModel& model, const JointType&, JointBuild& context)
{
    b2DistanceJointDef def;
    def.localAnchorA = model.anchorA;
    def.localAnchorB = model.anchorB;
    def.length = model.length;
    def.minLength = 0.0f;
    def.maxLength = model.length;
    def.stiffness = 0.0f;
    def.damping = 0.0f;
    return Finish(def, model, context);
}
bool ExtractRope(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& distance = static_cast<b2DistanceJoint&>(joint);
    model.anchorA = distance.GetLocalAnchorA();
    model.anchorB = distance.GetLocalAnchorB();
    model.length = distance.GetMaxLength();
    return true;
}

// --- pulley
b2Joint* BuildPulley(const JointModel& model, const JointType&, JointBuild& context)
{
    b2PulleyJointDef def;
    def.groundAnchorA = model.groundAnchorA;
    def.groundAnchorB = model.groundAnchorB;
    def.localAnchorA = model.anchorA;
    def.localAnchorB = model.anchorB;
    def.lengthA = model.lengthA;
    def.lengthB = model.lengthB;
    def.ratio = model.ratio;
    return Finish(def, model, context);
}
bool ExtractPulley(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& pulley = static_cast<b2PulleyJoint&>(joint);
    model.groundAnchorA = pulley.GetGroundAnchorA();
    model.groundAnchorB = pulley.GetGroundAnchorB();
    model.anchorA = joint.GetBodyA()->GetLocalPoint(pulley.GetAnchorA());
    model.anchorB = joint.GetBodyB()->GetLocalPoint(pulley.GetAnchorB());
    model.lengthA = pulley.GetLengthA();
    model.lengthB = pulley.GetLengthB();
    model.ratio = pulley.GetRatio();
    return true;
}

// --- mouse
b2Joint* BuildMouse(const JointModel& model, const JointType& type, JointBuild& context)
{
    b2MouseJointDef def;
    // b2dJson saves the grabbed point (world) as anchorB and the point it is pulled to as target.
    def.target = model.mouseAnchor.value_or(model.target);
    def.maxForce = model.maxForce;
    if (!Stiffness(model, type, false, context, def.stiffness, def.damping))
    {
        return nullptr;
    }
    b2Joint* joint = Finish(def, model, context);
    static_cast<b2MouseJoint*>(joint)->SetTarget(model.target);
    return joint;
}
bool ExtractMouse(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& mouse = static_cast<b2MouseJoint&>(joint);
    model.target = mouse.GetTarget();
    model.anchorB = mouse.GetAnchorB();
    model.maxForce = mouse.GetMaxForce();
    SetSpring(model, LinearSpring(mouse.GetStiffness(), mouse.GetDamping(), joint));
    return true;
}
void AfterReadMouse(const ObjectReader& reader, JointModel& model)
{
    if (reader.Has("anchorB"))
    {
        model.mouseAnchor = model.anchorB;
    }
}

// --- gear
b2Joint* BuildGear(const JointModel& model, const JointType&, JointBuild& context)
{
    b2GearJointDef def;
    def.joint1 = context.created[static_cast<std::size_t>(model.joint1)];
    def.joint2 = context.created[static_cast<std::size_t>(model.joint2)];
    if (def.joint1 == nullptr || def.joint2 == nullptr)
    {
        return nullptr; // the problem of that joint is reported already
    }
    def.ratio = model.ratio;
    return Finish(def, model, context);
}
bool ExtractGear(b2Joint& joint, JointModel& model, const JointExtract& context)
{
    auto& gear = static_cast<b2GearJoint&>(joint);
    auto joint1 = context.jointIndex.find(gear.GetJoint1());
    auto joint2 = context.jointIndex.find(gear.GetJoint2());
    if (joint1 == context.jointIndex.end() || joint2 == context.jointIndex.end())
    {
        return false; // refers to a joint that no longer exists
    }
    model.joint1 = joint1->second;
    model.joint2 = joint2->second;
    model.ratio = gear.GetRatio();
    return true;
}

// --- wheel
b2Joint* BuildWheel(const JointModel& model, const JointType& type, JointBuild& context)
{
    b2WheelJointDef def;
    def.localAnchorA = model.anchorA;
    def.localAnchorB = model.anchorB;
    def.localAxisA = model.localAxisA;
    def.enableLimit = model.enableLimit;
    def.lowerTranslation = model.lowerLimit;
    def.upperTranslation = model.upperLimit;
    def.enableMotor = model.enableMotor;
    def.motorSpeed = model.motorSpeed;
    def.maxMotorTorque = model.maxMotorTorque;
    if (!Stiffness(model, type, false, context, def.stiffness, def.damping))
    {
        return nullptr;
    }
    return Finish(def, model, context);
}
bool ExtractWheel(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& wheel = static_cast<b2WheelJoint&>(joint);
    model.anchorA = wheel.GetLocalAnchorA();
    model.anchorB = wheel.GetLocalAnchorB();
    model.localAxisA = wheel.GetLocalAxisA();
    model.enableMotor = wheel.IsMotorEnabled();
    model.motorSpeed = wheel.GetMotorSpeed();
    model.maxMotorTorque = wheel.GetMaxMotorTorque();
    SetSpring(model, LinearSpring(wheel.GetStiffness(), wheel.GetDamping(), joint));
    model.enableLimit = wheel.IsLimitEnabled();
    model.lowerLimit = wheel.GetLowerLimit();
    model.upperLimit = wheel.GetUpperLimit();
    return true;
}

// --- weld
b2Joint* BuildWeld(const JointModel& model, const JointType& type, JointBuild& context)
{
    b2WeldJointDef def;
    def.localAnchorA = model.anchorA;
    def.localAnchorB = model.anchorB;
    def.referenceAngle = model.referenceAngle;
    if (!Stiffness(model, type, true, context, def.stiffness, def.damping))
    {
        return nullptr;
    }
    return Finish(def, model, context);
}
bool ExtractWeld(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& weld = static_cast<b2WeldJoint&>(joint);
    model.anchorA = weld.GetLocalAnchorA();
    model.anchorB = weld.GetLocalAnchorB();
    model.referenceAngle = weld.GetReferenceAngle();
    SetSpring(model, SpringFromStiffness(weld.GetStiffness(), weld.GetDamping(), *joint.GetBodyA(),
                                         *joint.GetBodyB(), true));
    return true;
}

// --- friction
b2Joint* BuildFriction(const JointModel& model, const JointType&, JointBuild& context)
{
    b2FrictionJointDef def;
    def.localAnchorA = model.anchorA;
    def.localAnchorB = model.anchorB;
    def.maxForce = model.maxForce;
    def.maxTorque = model.maxTorque;
    return Finish(def, model, context);
}
bool ExtractFriction(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& friction = static_cast<b2FrictionJoint&>(joint);
    model.anchorA = friction.GetLocalAnchorA();
    model.anchorB = friction.GetLocalAnchorB();
    model.maxForce = friction.GetMaxForce();
    model.maxTorque = friction.GetMaxTorque();
    return true;
}

// --- motor
b2Joint* BuildMotor(const JointModel& model, const JointType&, JointBuild& context)
{
    b2MotorJointDef def;
    def.linearOffset = model.linearOffset;
    def.angularOffset = model.referenceAngle;
    def.maxForce = model.maxForce;
    def.maxTorque = model.maxTorque;
    def.correctionFactor = model.correctionFactor;
    return Finish(def, model, context);
}
bool ExtractMotor(b2Joint& joint, JointModel& model, const JointExtract&)
{
    auto& motor = static_cast<b2MotorJoint&>(joint);
    model.linearOffset = motor.GetLinearOffset();
    model.referenceAngle = motor.GetAngularOffset();
    model.maxForce = motor.GetMaxForce();
    model.maxTorque = motor.GetMaxTorque();
    model.correctionFactor = motor.GetCorrectionFactor();
    return true;
}
void AfterReadMotor(const ObjectReader& reader, JointModel& model)
{
    if (!reader.Has("linearOffset"))
    {
        model.linearOffset = model.anchorA;
    }
}

const std::array<JointType, 11> kJointTypes = {{
    {"revolute", JointKind::revolute, e_revoluteJoint, kRevoluteFields, BuildRevolute, ExtractRevolute},
    {"prismatic", JointKind::prismatic, e_prismaticJoint, kPrismaticFields, BuildPrismatic, ExtractPrismatic},
    {"distance", JointKind::distance, e_distanceJoint, kDistanceFields, BuildDistance, ExtractDistance},
    {"pulley", JointKind::pulley, e_pulleyJoint, kPulleyFields, BuildPulley, ExtractPulley},
    {"mouse", JointKind::mouse, e_mouseJoint, kMouseFields, BuildMouse, ExtractMouse, AfterReadMouse},
    {"gear", JointKind::gear, e_gearJoint, kGearFields, BuildGear, ExtractGear},
    {"wheel", JointKind::wheel, e_wheelJoint, kWheelFields, BuildWheel, ExtractWheel},
    {"weld", JointKind::weld, e_weldJoint, kWeldFields, BuildWeld, ExtractWeld},
    {"friction", JointKind::friction, e_frictionJoint, kFrictionFields, BuildFriction, ExtractFriction},
    {"motor", JointKind::motor, e_motorJoint, kMotorFields, BuildMotor, ExtractMotor, AfterReadMotor},
    {"rope", JointKind::rope, e_distanceJoint, kRopeFields, BuildRope, ExtractRope},
}};

// The present value of a number field of the joint, for the `atLeast` check.
std::optional<float> NumberOf(const JointModel& joint, const JointType& type, std::string_view key)
{
    for (const JointField& field : type.fields)
    {
        if (field.key != key)
        {
            continue;
        }
        if (auto member = std::get_if<float JointModel::*>(&field.member))
        {
            return joint.**member;
        }
        if (auto member = std::get_if<std::optional<float> JointModel::*>(&field.member))
        {
            return joint.**member;
        }
    }
    return std::nullopt;
}

} // namespace

std::span<const JointType> JointTypes()
{
    return kJointTypes;
}

const JointType* FindJointType(std::string_view name)
{
    for (const JointType& type : kJointTypes)
    {
        if (type.name == name)
        {
            return &type;
        }
    }
    return nullptr;
}

const JointType& JointTypeOf(JointKind kind)
{
    for (const JointType& type : kJointTypes)
    {
        if (type.kind == kind)
        {
            return type;
        }
    }
    return kJointTypes[0]; // every kind has a row
}

std::span<const std::string_view> CommonJointKeys()
{
    return kCommonKeys;
}

std::string_view KeyOf(const JointType& type, const JointMember& member)
{
    for (const JointField& field : type.fields)
    {
        if (field.member == member)
        {
            return field.key;
        }
    }
    return {};
}

void ReadJointTypeFields(const ObjectReader& reader, const JointType& type, JointModel& joint)
{
    for (const JointField& field : type.fields)
    {
        if (field.common)
        {
            continue;
        }
        const std::string_view key = field.alias.empty() || reader.Has(field.key) ? field.key : field.alias;
        std::visit(
            [&](auto member)
            {
                using T = decltype(member);
                if constexpr (std::is_same_v<T, float JointModel::*>)
                {
                    joint.*member = reader.Float(key, field.number, field.limits);
                }
                else if constexpr (std::is_same_v<T, std::optional<float> JointModel::*>)
                {
                    joint.*member = reader.OptionalFloat(key, field.limits);
                }
                else if constexpr (std::is_same_v<T, bool JointModel::*>)
                {
                    joint.*member = reader.Bool(key, field.number != 0.0f);
                }
                else if constexpr (std::is_same_v<T, b2Vec2 JointModel::*>)
                {
                    joint.*member = reader.Vec(key, field.vector, field.limits);
                    if (field.nonZero && (joint.*member).Length() < b2_epsilon)
                    {
                        reader.Diagnostics().Add(reader.FieldPath(key),
                                                 "expected a non-zero axis, found (0, 0)");
                        joint.*member = field.vector;
                    }
                }
                // Joint indices (gear) are read once every joint is; ignored keys are only known.
            },
            field.member);
        if (!field.atLeast.empty())
        {
            const std::optional<float> lower = NumberOf(joint, type, field.atLeast);
            const std::optional<float> value = NumberOf(joint, type, field.key);
            if (lower && value && *lower > *value)
            {
                reader.Diagnostics().Add(reader.FieldPath(key), "expected " + std::string(field.key) +
                                                                    " >= " + std::string(field.atLeast) +
                                                                    " (" + FormatFloat(*lower) + "), found " +
                                                                    FormatFloat(*value));
            }
        }
    }
    if (type.afterRead != nullptr)
    {
        type.afterRead(reader, joint);
    }
}

} // namespace cfx::scene_detail
