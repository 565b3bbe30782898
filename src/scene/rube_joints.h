// RUBE joints: one table row per joint type, read by the reader, the scene builder and the writer.
//
// A joint type is its RUBE name, its fields (JSON key, the JointModel member it fills, range, default,
// checks) and two functions that are all the Box2D-specific code of the type: Build (JointModel ->
// b2*JointDef -> b2Joint) and Extract (b2Joint -> JointModel). The reader fills a JointModel from the
// fields, the builder calls Build, the writer calls Extract and writes the fields; the unknown-key check
// knows the fields. So a key, its default and its range are written once, and the per-type switch that
// used to be written out in the reader, the builder, the writer and the key lists is this table.
#pragma once

#include "scene/json_reader.h"
#include "scene/rube_model.h"

#include <box2d/box2d.h>
#include <optional>
#include <span>
#include <string_view>
#include <unordered_map>
#include <variant>
#include <vector>

namespace cfx::scene_detail
{

/// The JointModel member a field fills; std::monostate: a known key that nothing reads (b2dJson's
/// `jointSpeed`).
using JointMember = std::variant<std::monostate, float JointModel::*, bool JointModel::*,
                                 b2Vec2 JointModel::*, std::optional<float> JointModel::*, int JointModel::*>;

/// One JSON field of a joint type.
struct JointField
{
    std::string_view key{};
    JointMember member{};
    NumberLimits limits{};     ///< numbers, and each axis of vectors
    float number = 0.0f;       ///< default of numbers; of booleans, non-zero is true
    b2Vec2 vector{0.0f, 0.0f}; ///< default of vectors
    /// Read with the fields every joint has (anchors), before the type's own; listed here for the writer.
    bool common = false;
    std::string_view alias{};   ///< an older key read when `key` is absent (prismatic `localAxis1`)
    std::string_view atLeast{}; ///< must be >= this field of the joint when both are present
    bool nonZero = false;       ///< vectors: an axis, (0, 0) is an error
};

/// What Build needs besides the model.
struct JointBuild
{
    b2World& world;
    b2Body* bodyA;
    b2Body* bodyB;
    const std::vector<b2Joint*>& created; ///< joints made so far, by index (gear joints refer to them)
    DiagnosticList& diagnostics;
};

/// What Extract needs besides the joint.
struct JointExtract
{
    const std::unordered_map<const b2Joint*, int>& jointIndex; ///< file index of every joint written
};

struct JointType
{
    std::string_view name; ///< RUBE's `type`
    JointKind kind;
    b2JointType box2d; ///< what Build makes (a rope is a b2DistanceJoint)
    std::span<const JointField> fields;
    /// Creates the joint, or nullptr after reporting (or when a joint it needs was not made).
    b2Joint* (*build)(const JointModel& model, const JointType& type, JointBuild& context);
    /// The model of an existing joint; false when it cannot be written (a gear whose joints are gone).
    bool (*extract)(b2Joint& joint, JointModel& model, const JointExtract& context);
    /// Reader fix-ups that depend on other keys (mouse: anchorB is the grabbed point; motor: the older
    /// files' linearOffset is anchorA). Never reports.
    void (*afterRead)(const ObjectReader& reader, JointModel& model) = nullptr;
};

/// Every joint type, in the order the reader lists them in its messages.
std::span<const JointType> JointTypes();
const JointType* FindJointType(std::string_view name);
const JointType& JointTypeOf(JointKind kind);

/// The keys every joint has, whatever its type.
std::span<const std::string_view> CommonJointKeys();

/// The key of the field of `type` that fills `member` (the spring's frequency is `springFrequency` on
/// wheels), or an empty view.
std::string_view KeyOf(const JointType& type, const JointMember& member);

/// Reads the type's own fields (not the common ones) into `joint`, with their checks.
void ReadJointTypeFields(const ObjectReader& reader, const JointType& type, JointModel& joint);

} // namespace cfx::scene_detail
