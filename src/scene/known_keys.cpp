#include "scene/known_keys.h"

#include "scene/rube_joints.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <vector>

namespace cfx::scene_detail
{

namespace
{

using Keys = std::span<const std::string_view>;

constexpr std::string_view kWorldKeys[] = {
    "gravity",     "allowSleep",     "autoClearForces",    "warmStarting",       "continuousPhysics",
    "subStepping", "stepsPerSecond", "velocityIterations", "positionIterations", "body",
    "joint",       "image",          "customProperties",   "collisionbitplanes"}; // RUBE's collision bit
                                                                                  // names: read by nobody
constexpr std::string_view kBodyKeys[] = {"name",
                                          "type",
                                          "position",
                                          "angle",
                                          "linearVelocity",
                                          "angularVelocity",
                                          "linearDamping",
                                          "angularDamping",
                                          "gravityScale",
                                          "bullet",
                                          "allowSleep",
                                          "awake",
                                          "active",
                                          "fixedRotation",
                                          "massData-mass",
                                          "massData-center",
                                          "massData-I",
                                          "fixture",
                                          "customProperties"};
constexpr std::string_view kFixtureKeys[] = {"name",
                                             "friction",
                                             "restitution",
                                             "density",
                                             "sensor",
                                             "filter-categoryBits",
                                             "filter-maskBits",
                                             "filter-groupIndex",
                                             "customProperties",
                                             "circle",
                                             "polygon",
                                             "edge",
                                             "chain",
                                             "loop"};
constexpr std::string_view kCircleKeys[] = {"radius", "center"};
constexpr std::string_view kPolygonKeys[] = {"vertices"};
constexpr std::string_view kEdgeKeys[] = {"vertex0", "vertex1",    "vertex2",
                                          "vertex3", "hasVertex0", "hasVertex3"};
constexpr std::string_view kChainKeys[] = {"vertices", "hasPrevVertex", "hasNextVertex", "prevVertex",
                                           "nextVertex"};
constexpr std::string_view kVertexListKeys[] = {"x", "y"};
constexpr std::string_view kImageKeys[] = {"name",
                                           "file",
                                           "body",
                                           "center",
                                           "angle",
                                           "scale",
                                           "aspectScale",
                                           "flip",
                                           "opacity",
                                           "filter",
                                           "renderOrder",
                                           "colorTint",
                                           "corners",
                                           "glTexCoordPointer",
                                           "glDrawElements",
                                           "glVertexPointer",
                                           "customProperties"};
constexpr std::string_view kPropertyKeys[] = {"name", "int", "float", "string", "bool", "vec2", "color"};

constexpr std::string_view kEffectsTopKeys[] = {"materials", "particleTypes", "rules", "assignments",
                                                "budget"};
constexpr std::string_view kRubeTopKeys[] = {
    "body", "joint", "image", "gravity", "stepsPerSecond", "velocityIterations", "positionIterations"};

bool Contains(Keys keys, std::string_view key)
{
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

/// Warns about the keys of `object` in none of `first` and `second`.
void WarnKeys(const Json& object, const std::string& path, Keys first, Keys second,
              DiagnosticList& diagnostics)
{
    if (!object.is_object())
    {
        return;
    }
    for (auto it = object.begin(); it != object.end(); ++it)
    {
        const std::string& key = it.key();
        if (Contains(first, key) || Contains(second, key))
        {
            continue;
        }
        std::vector<std::string_view> known(first.begin(), first.end());
        known.insert(known.end(), second.begin(), second.end());
        diagnostics.Warn(JoinPath(path, key), UnknownKeyMessage(key, known));
    }
}

void WarnKeys(const Json& object, const std::string& path, Keys keys, DiagnosticList& diagnostics)
{
    WarnKeys(object, path, keys, {}, diagnostics);
}

/// Calls `each(element, path)` for every element of the array `object[key]`, if it is one.
template <typename F> void ForEach(const Json& object, const std::string& path, const char* key, F each)
{
    if (!object.is_object())
    {
        return;
    }
    auto it = object.find(key);
    if (it == object.end() || !it->is_array())
    {
        return;
    }
    for (std::size_t i = 0; i < it->size(); ++i)
    {
        each((*it)[i], IndexPath(JoinPath(path, key), i));
    }
}

void WarnProperties(const Json& object, const std::string& path, DiagnosticList& diagnostics)
{
    ForEach(object, path, "customProperties",
            [&](const Json& property, const std::string& at)
            { WarnKeys(property, at, kPropertyKeys, diagnostics); });
}

void WarnShape(const Json& fixture, const std::string& path, DiagnosticList& diagnostics)
{
    struct ShapeKeys
    {
        const char* name;
        Keys keys;
        bool vertexList;
    };
    const ShapeKeys shapes[] = {{"circle", kCircleKeys, false},
                                {"polygon", kPolygonKeys, true},
                                {"edge", kEdgeKeys, false},
                                {"chain", kChainKeys, true},
                                {"loop", kPolygonKeys, true}};
    for (const ShapeKeys& shape : shapes)
    {
        auto it = fixture.find(shape.name);
        if (it == fixture.end() || !it->is_object())
        {
            continue;
        }
        const std::string at = JoinPath(path, shape.name);
        WarnKeys(*it, at, shape.keys, diagnostics);
        auto vertices = it->find("vertices");
        if (shape.vertexList && vertices != it->end())
        {
            WarnKeys(*vertices, JoinPath(at, "vertices"), kVertexListKeys, diagnostics);
        }
    }
}

} // namespace

std::string UnknownKeyMessage(std::string_view key, std::span<const std::string_view> known,
                              std::string_view noun, std::string_view ignored)
{
    const std::optional<std::string_view> nearest = NearestKey(key, known);
    if (nearest)
    {
        return "unknown " + std::string(noun) + ", did you mean `" + std::string(*nearest) + "`?";
    }
    return "unknown " + std::string(noun) + std::string(ignored);
}

void WarnUnknownRubeKeys(const Json& root, DiagnosticList& diagnostics)
{
    if (!root.is_object())
    {
        return;
    }
    WarnKeys(root, "", kWorldKeys, diagnostics);
    WarnProperties(root, "", diagnostics);
    ForEach(root, "", "body",
            [&](const Json& body, const std::string& bodyPath)
            {
                WarnKeys(body, bodyPath, kBodyKeys, diagnostics);
                WarnProperties(body, bodyPath, diagnostics);
                ForEach(body, bodyPath, "fixture",
                        [&](const Json& fixture, const std::string& fixturePath)
                        {
                            if (!fixture.is_object())
                            {
                                return;
                            }
                            WarnKeys(fixture, fixturePath, kFixtureKeys, diagnostics);
                            WarnProperties(fixture, fixturePath, diagnostics);
                            WarnShape(fixture, fixturePath, diagnostics);
                        });
            });
    ForEach(root, "", "joint",
            [&](const Json& joint, const std::string& jointPath)
            {
                if (!joint.is_object())
                {
                    return;
                }
                auto type = joint.find("type");
                if (type == joint.end() || !type->is_string())
                {
                    return; // the reader reports the type; the other keys depend on it
                }
                if (const JointType* jointType = FindJointType(type->get_ref<const std::string&>()))
                {
                    // The keys of every joint, then those of its type (an older spelling after its key).
                    std::vector<std::string_view> keys;
                    for (const JointField& field : jointType->fields)
                    {
                        if (!field.common)
                        {
                            keys.push_back(field.key);
                            if (!field.alias.empty())
                            {
                                keys.push_back(field.alias);
                            }
                        }
                    }
                    WarnKeys(joint, jointPath, CommonJointKeys(), keys, diagnostics);
                }
                WarnProperties(joint, jointPath, diagnostics);
            });
    ForEach(root, "", "image",
            [&](const Json& image, const std::string& imagePath)
            {
                WarnKeys(image, imagePath, kImageKeys, diagnostics);
                WarnProperties(image, imagePath, diagnostics);
            });
}

namespace
{

std::string FoundKeys(const Json& root, Keys keys)
{
    std::string found;
    if (!root.is_object())
    {
        return found;
    }
    for (std::string_view key : keys)
    {
        if (root.contains(std::string(key)))
        {
            found += (found.empty() ? "\"" : ", \"") + std::string(key) + "\"";
        }
    }
    return found;
}

} // namespace

std::string EffectsConfigKeys(const Json& root)
{
    return FoundKeys(root, kEffectsTopKeys);
}

std::string RubeSceneKeys(const Json& root)
{
    return FoundKeys(root, kRubeTopKeys);
}

} // namespace cfx::scene_detail
