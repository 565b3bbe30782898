// The joint table (src/scene/rube_joints.h) against the reader, the builder, the writer and the unknown-key
// check: every row of every joint type, so a field that one of them leaves out fails here.
#include "scene/rube_joints.h"
#include "scene/rube_test_util.h"

#include <cmath>
#include <gtest/gtest.h>
#include <set>

namespace cfx
{
namespace
{

using scene_detail::JointField;
using scene_detail::JointModel;
using scene_detail::JointType;
using Json = nlohmann::json;

bool IsIgnored(const JointField& field)
{
    return std::holds_alternative<std::monostate>(field.member);
}

bool IsIndex(const JointField& field)
{
    return std::holds_alternative<int JointModel::*>(field.member);
}

// A valid value other than the default for each field of `type`, in table order.
Json JointWithEveryField(const JointType& type)
{
    Json joint = {{"type", std::string(type.name)}};
    if (type.kind == scene_detail::JointKind::gear)
    {
        joint["joint1"] = 0;
        joint["joint2"] = 1;
    }
    else
    {
        joint["bodyA"] = 0;
        joint["bodyB"] = 1;
    }
    float next = 0.5f;
    for (const JointField& field : type.fields)
    {
        const std::string key(field.key);
        std::visit(
            [&](auto member)
            {
                using T = decltype(member);
                if constexpr (std::is_same_v<T, float JointModel::*> ||
                              std::is_same_v<T, std::optional<float> JointModel::*>)
                {
                    float value = next;
                    if (value > field.limits.max)
                    {
                        value = static_cast<float>(field.limits.max) * 0.5f;
                    }
                    joint[key] = value;
                    next += 0.25f; // later fields larger: upper limits stay above lower ones
                }
                else if constexpr (std::is_same_v<T, bool JointModel::*>)
                {
                    joint[key] = field.number == 0.0f;
                }
                else if constexpr (std::is_same_v<T, b2Vec2 JointModel::*>)
                {
                    joint[key] =
                        field.nonZero ? Json{{"x", 0.0f}, {"y", 1.0f}} : Json{{"x", next}, {"y", -0.25f}};
                    next += 0.25f;
                }
            },
            field.member);
    }
    return joint;
}

// Two dynamic boxes (bodies 0, 1), a static ground (body 2); for gears, the two joints they couple first.
std::string SceneWith(const JointType& type, const Json& joint)
{
    std::string joints;
    if (type.kind == scene_detail::JointKind::gear)
    {
        joints =
            R"({"type": "revolute", "bodyA": 2, "bodyB": 0}, {"type": "prismatic", "bodyA": 2, "bodyB": 1},)";
    }
    return test::World(test::Box(0.0f) + "," + test::Box(3.0f) + "," + test::Box(0.0f, 0),
                       joints + joint.dump());
}

bool IsSpring(const JointField& field)
{
    return field.member == scene_detail::JointMember(&JointModel::frequency) ||
           field.member == scene_detail::JointMember(&JointModel::dampingRatio);
}

void ExpectNear(const Json& written, const Json& read, const JointField& field, const std::string& where)
{
    const double tolerance = IsSpring(field) ? 1e-3 : 1e-5;
    if (read.is_object())
    {
        ASSERT_TRUE(written.is_object()) << where;
        EXPECT_NEAR(written["x"].get<double>(), read["x"].get<double>(),
                    tolerance * (1 + std::fabs(read["x"].get<double>())))
            << where;
        EXPECT_NEAR(written["y"].get<double>(), read["y"].get<double>(),
                    tolerance * (1 + std::fabs(read["y"].get<double>())))
            << where;
    }
    else if (read.is_number())
    {
        EXPECT_NEAR(written.get<double>(), read.get<double>(),
                    tolerance * (1 + std::fabs(read.get<double>())))
            << where;
    }
    else
    {
        EXPECT_EQ(written, read) << where;
    }
}

} // namespace

TEST(RubeJointTable, EveryFieldOfEveryTypeIsBuiltAndWrittenBack)
{
    for (const JointType& type : scene_detail::JointTypes())
    {
        SCOPED_TRACE(std::string(type.name));
        const Json joint = JointWithEveryField(type);
        Scene scene = LoadRubeString(SceneWith(type, joint), "joints.json");
        const Json saved = Json::parse(SaveRubeString(scene));
        const Json& written = saved["joint"].back();
        EXPECT_EQ(written["type"], std::string(type.name));

        std::set<std::string> expected = {"type", "bodyA", "bodyB", "collideConnected"};
        for (const JointField& field : type.fields)
        {
            if (IsIgnored(field))
            {
                continue;
            }
            const std::string key(field.key);
            expected.insert(key);
            ASSERT_TRUE(written.contains(key)) << "the writer leaves out " << key;
            if (joint.contains(key))
            {
                ExpectNear(written[key], joint[key], field, key);
            }
        }
        std::set<std::string> keys;
        for (auto it = written.begin(); it != written.end(); ++it)
        {
            keys.insert(it.key());
        }
        EXPECT_EQ(keys, expected);
    }
}

TEST(RubeJointTable, EveryKeyOfATypeIsKnownAndAMisspeltOneIsNamed)
{
    for (const JointType& type : scene_detail::JointTypes())
    {
        SCOPED_TRACE(std::string(type.name));
        Json joint = JointWithEveryField(type);
        for (const JointField& field : type.fields)
        {
            if (IsIgnored(field))
            {
                joint[std::string(field.key)] = 0;
            }
            if (!field.alias.empty())
            {
                joint[std::string(field.alias)] = joint[std::string(field.key)];
            }
        }
        std::vector<Diagnostic> warnings;
        EXPECT_TRUE(ValidateRubeString(SceneWith(type, joint), "joints.json", nullptr, &warnings).empty());
        EXPECT_TRUE(warnings.empty()) << warnings[0].path << ": " << warnings[0].message;

        const std::string index = type.kind == scene_detail::JointKind::gear ? "joint[2]" : "joint[0]";
        for (const JointField& field : type.fields)
        {
            if (field.common || IsIndex(field))
            {
                continue;
            }
            Json misspelt = joint;
            const std::string key(field.key);
            misspelt[key + "Q"] = misspelt[key];
            misspelt.erase(key);
            ValidateRubeString(SceneWith(type, misspelt), "joints.json", nullptr, &warnings);
            bool named = false;
            for (const Diagnostic& warning : warnings)
            {
                named |= warning.path == index + "." + key + "Q" &&
                         warning.message == "unknown key, did you mean `" + key + "`?";
            }
            EXPECT_TRUE(named) << key << "Q";
        }
    }
}

TEST(RubeJointTable, EveryNumberOutsideItsLimitsIsAnError)
{
    for (const JointType& type : scene_detail::JointTypes())
    {
        SCOPED_TRACE(std::string(type.name));
        const std::string index = type.kind == scene_detail::JointKind::gear ? "joint[2]" : "joint[0]";
        for (const JointField& field : type.fields)
        {
            const bool number = std::holds_alternative<float JointModel::*>(field.member) ||
                                std::holds_alternative<std::optional<float> JointModel::*>(field.member);
            if (!number || field.common)
            {
                continue;
            }
            for (double bad : {field.limits.max * 2.0 + 1.0, field.limits.min * 2.0 - 1.0})
            {
                if (!std::isfinite(bad))
                {
                    continue;
                }
                Json joint = JointWithEveryField(type);
                joint[std::string(field.key)] = bad;
                std::vector<std::string> paths;
                for (const Diagnostic& problem : ValidateRubeString(SceneWith(type, joint), "joints.json"))
                {
                    paths.push_back(problem.path);
                }
                EXPECT_NE(std::find(paths.begin(), paths.end(), index + "." + std::string(field.key)),
                          paths.end())
                    << field.key << " = " << bad;
            }
        }
    }
}

TEST(RubeJointTable, SpringProblemsNameTheTypesFrequencyKey)
{
    EXPECT_EQ(scene_detail::KeyOf(scene_detail::JointTypeOf(scene_detail::JointKind::wheel),
                                  &JointModel::frequency),
              "springFrequency");
    EXPECT_EQ(
        scene_detail::KeyOf(scene_detail::JointTypeOf(scene_detail::JointKind::weld), &JointModel::frequency),
        "frequency");
}

} // namespace cfx
