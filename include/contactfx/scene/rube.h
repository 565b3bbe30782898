// contactfx_scene: RUBE JSON (the b2dJson format) <-> b2World.
//
// A Scene owns a b2World built from a RUBE file and remembers what Box2D itself cannot hold for us:
// the names and custom properties of bodies, fixtures, joints and images, and the world settings RUBE
// stores (step rate, iterations). Fixture user data and body user data stay untouched: they belong to the
// application. Format facts: ../shared/rube-samples/README.md and docs/rube.md.
//
// Threading: a Scene is a plain owner; use it from one thread at a time.
#pragma once

#include "contactfx/error.h"

#include <box2d/box2d.h>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace cfx
{

/// An 8-bit RGBA colour, as RUBE stores colour custom properties.
struct Rgba8
{
    std::uint8_t r = 0, g = 0, b = 0, a = 255;
    bool operator==(const Rgba8&) const = default;
};

/// One RUBE custom property: int, float, string, bool, vec2 or color.
struct CustomProperty
{
    std::string name;
    std::variant<int, float, std::string, bool, b2Vec2, Rgba8> value;
};

/// The custom properties of one object, in file order.
struct CustomProperties
{
    std::vector<CustomProperty> items;

    const CustomProperty* Find(std::string_view name) const;
    /// The string property `name`, or nullptr when absent or of another type.
    const std::string* FindString(std::string_view name) const;
};

struct SceneBody
{
    b2Body* body = nullptr;
    std::string name;
    CustomProperties properties;
};

struct SceneFixture
{
    b2Fixture* fixture = nullptr;
    /// RUBE scenes are Box2D 2.3 scenes, where chains and edges with ghost vertices collide on both sides;
    /// Box2D 2.4 makes them one-sided. Such a fixture therefore gets a second fixture on its body, the same
    /// shape reversed (same friction, restitution, density, filter, sensor flag, material): together they
    /// collide on both sides, smoothly. Null for every other shape. The writer saves the pair as the one
    /// fixture of the file.
    b2Fixture* backSide = nullptr;
    int bodyIndex = -1; ///< index into Scene::bodies
    std::string name;
    CustomProperties properties;
};

struct SceneJoint
{
    b2Joint* joint = nullptr;
    std::string name;
    std::string type; ///< RUBE type name as read ("revolute", "wheel", "rope", ...)
    CustomProperties properties;
};

/// A RUBE image, kept as data (contactfx does not draw images).
struct SceneImage
{
    std::string name;
    std::string file;
    int bodyIndex = -1; ///< -1 when not attached to a body
    b2Vec2 center{0.0f, 0.0f};
    float angle = 0.0f;
    float scale = 1.0f;
    float aspectScale = 1.0f;
    bool flip = false;
    float opacity = 1.0f;
    int filter = 1;
    float renderOrder = 0.0f;
    float colorTint[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    std::vector<b2Vec2> corners;
    std::vector<b2Vec2> uvCoords;
    std::vector<int> glDrawElements;
    CustomProperties properties;
};

/// World settings RUBE stores beside the bodies.
struct WorldSettings
{
    float stepsPerSecond = 60.0f; ///< Hz, > 0
    int velocityIterations = 8;
    int positionIterations = 3;
    bool allowSleep = true;
    bool autoClearForces = true;
    bool warmStarting = true;
    bool continuousPhysics = true;
    bool subStepping = false;
};

/// A loaded scene: the world plus everything RUBE knows about it.
class Scene
{
public:
    std::unique_ptr<b2World> world;
    WorldSettings settings;
    std::vector<SceneBody> bodies;      ///< file order; body index = RUBE body index
    std::vector<SceneFixture> fixtures; ///< file order, body by body
    std::vector<SceneJoint> joints;     ///< file order
    std::vector<SceneImage> images;     ///< file order
    CustomProperties properties;        ///< the world's own custom properties
    /// What loaded but may not be what the file meant (Diagnostic::warning): unknown keys (with the nearest
    /// known one), polygon vertices Box2D drops (welded, or not on the convex hull).
    std::vector<Diagnostic> warnings;

    /// First object with this name, or nullptr.
    const SceneBody* FindBody(std::string_view name) const;
    const SceneFixture* FindFixture(std::string_view name) const;
    const SceneJoint* FindJoint(std::string_view name) const;
    /// The entry of a Box2D object created by this scene (of a fixture or its back side), or nullptr.
    const SceneFixture* FindFixture(const b2Fixture* fixture) const;
    const SceneBody* FindBody(const b2Body* body) const;
    const SceneJoint* FindJoint(const b2Joint* joint) const;
    /// First image with this name, or nullptr.
    const SceneImage* FindImage(std::string_view name) const;
};

/// Loads a RUBE JSON file. Throws InputError listing every problem found (file, JSON path, expected and
/// found, line and column for malformed JSON). Never modifies the file.
Scene LoadRubeFile(const std::filesystem::path& path);

/// Same, from text; `fileName` is only used in diagnostics.
Scene LoadRubeString(std::string_view json, std::string_view fileName);

/// Checks a RUBE file without keeping the world: every error, or an empty list when the file loads.
/// `counts` (optional) receives bodies, fixtures, joints and images found; `warnings` (optional) the
/// warnings (Scene::warnings), which do not stop the file from loading.
struct SceneCounts
{
    int bodies = 0, fixtures = 0, joints = 0, images = 0;
};
std::vector<Diagnostic> ValidateRubeFile(const std::filesystem::path& path, SceneCounts* counts = nullptr,
                                         std::vector<Diagnostic>* warnings = nullptr);

/// Same, from text; `fileName` is only used in diagnostics.
std::vector<Diagnostic> ValidateRubeString(std::string_view json, std::string_view fileName,
                                           SceneCounts* counts = nullptr,
                                           std::vector<Diagnostic>* warnings = nullptr);

/// RUBE JSON of the scene's current world (positions and velocities as they are now).
std::string SaveRubeString(const Scene& scene);

/// Writes SaveRubeString to `path` atomically (a temporary file renamed over the target): never a
/// half-written file. Throws InputError naming the path when it cannot be written.
void SaveRubeFile(const Scene& scene, const std::filesystem::path& path);

} // namespace cfx
