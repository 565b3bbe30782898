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

std::size_t EditDistance(std::string_view a, std::string_view b)
{
    // Optimal string alignment: three rows of the table, for the prefixes of `a` of length i - 2, i - 1, i.
    const std::size_t columns = b.size() + 1;
    std::vector<std::size_t> older(columns), previous(columns), current(columns);
    for (std::size_t j = 0; j < columns; ++j)
    {
        previous[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        current[0] = i;
        for (std::size_t j = 1; j < columns; ++j)
        {
            const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
            {
                current[j] = std::min(current[j], older[j - 2] + 1);
            }
        }
        std::swap(older, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::optional<std::string_view> NearestKey(std::string_view key, std::span<const std::string_view> known)
{
    auto lower = [](std::string_view text)
    {
        std::string out(text);
        for (char& c : out)
        {
            c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        }
        return out;
    };
    const std::size_t limit =
        std::min(std::max<std::size_t>(2, key.size() / 3), key.empty() ? 0 : (key.size() - 1) / 2);
    const std::string wanted = lower(key);
    std::optional<std::string_view> nearest;
    std::size_t best = limit + 1;
    for (std::string_view candidate : known)
    {
        const std::size_t longer = std::max(key.size(), candidate.size());
        if (longer - std::min(key.size(), candidate.size()) > limit)
        {
            continue; // at least that many insertions: too far (and cheap for a hostile 1 MB key)
        }
        // A case slip ("Gravity") is one edit, whatever its length.
        const std::size_t folded = EditDistance(wanted, lower(candidate));
        const std::size_t distance = folded == 0 ? (candidate == key ? 0 : 1) : folded;
        if (distance < best)
        {
            best = distance;
            nearest = candidate;
        }
    }
    if (best == 0)
    {
        return std::nullopt;
    }
    return nearest;
}

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
