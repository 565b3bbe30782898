// The registry of named scenes. Adding a scene: its RUBE file in scenes/ (fixtures carry `material`),
// an entry below, and the particle types it promises, which tests/sim/scenes_test.cpp then checks.
#include "harness/scenes.h"

#include "contactfx/scene/effects_json.h"
#include "harness/command_line.h"

#include <array>
#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <cstdlib>

namespace cfx
{

namespace
{

// The skid pad's drive: launches with wheelspin, full-lock skids and reversals, repeated for a minute.
std::span<const DriveSegment> SkidpadDrive()
{
    constexpr int kLaps = 12;
    static constexpr std::array kLap{
        DriveSegment{1.6f, DriveInput{+1, false, true}}, // launch, four-wheel drive: wheelspin
        DriveSegment{2.6f, DriveInput{0, true, false}},  // brake: the tyres lock and skid
        DriveSegment{4.3f, DriveInput{-1, false, true}}, // the same backwards
        DriveSegment{5.3f, DriveInput{0, true, false}},
    };
    static const auto drive = []
    {
        std::array<DriveSegment, kLaps * kLap.size()> segments{};
        const float lapTime = kLap.back().until;
        for (int lap = 0; lap < kLaps; ++lap)
        {
            for (std::size_t i = 0; i < kLap.size(); ++i)
            {
                DriveSegment segment = kLap[i];
                segment.until += static_cast<float>(lap) * lapTime;
                segments[static_cast<std::size_t>(lap) * kLap.size() + i] = segment;
            }
        }
        return segments;
    }();
    return drive;
}

// True when no fixture of another dynamic body overlaps the box of half size `reach` around `point`.
bool IsFree(b2World& world, const b2Body* self, b2Vec2 point, float reach)
{
    struct Query final : b2QueryCallback
    {
        const b2Body* self = nullptr;
        bool free = true;
        bool ReportFixture(b2Fixture* fixture) override
        {
            const b2Body* body = fixture->GetBody();
            if (body != self && body->GetType() == b2_dynamicBody)
            {
                free = false;
                return false;
            }
            return true;
        }
    };
    Query query;
    query.self = self;
    b2AABB box;
    box.lowerBound = point - b2Vec2(reach, reach);
    box.upperBound = point + b2Vec2(reach, reach);
    world.QueryAABB(&query, box);
    return query.free;
}

// Bodies with a vec2 custom property `home` go back there, at rest, once they fell asleep or out of the
// world (below y = -50 m), as soon as nothing else is in the way.
void ReturnHome(Simulation& simulation)
{
    constexpr float kFloor = -50.0f;
    constexpr float kReach = 1.2f; // m, about the largest body sent home
    Scene& scene = simulation.GetScene();
    for (const SceneBody& entry : scene.bodies)
    {
        const CustomProperty* home = entry.properties.Find("home");
        const b2Vec2* target = home != nullptr ? std::get_if<b2Vec2>(&home->value) : nullptr;
        b2Body* body = entry.body;
        if (target == nullptr || body->GetType() != b2_dynamicBody)
        {
            continue;
        }
        const bool done = !body->IsAwake() || body->GetPosition().y < kFloor;
        if (done && IsFree(*scene.world, body, *target, kReach))
        {
            body->SetTransform(*target, body->GetAngle());
            body->SetLinearVelocity(b2Vec2(0.0f, 0.0f));
            body->SetAngularVelocity(0.0f);
            body->SetAwake(true);
        }
    }
}

constexpr std::array<std::string_view, 3> kAllThree{"smoke", "sparks", "dirt"};
constexpr std::array<std::string_view, 1> kSparks{"sparks"};
constexpr std::array<std::string_view, 1> kSmoke{"smoke"};
constexpr std::array<std::string_view, 2> kDirtAndSparks{"dirt", "sparks"};

const std::array<SceneEntry, 4>& Registry()
{
    static const std::array<SceneEntry, 4> scenes{
        SceneEntry{.name = "tutorial",
                   .title = "The tutorial's scene and its demo drive: smoke, sparks and dirt",
                   .file = "physics_driven_particles.json",
                   .drive = TutorialDrive(),
                   .view = SceneView{b2Vec2(-52.6f, 4.0f), 16.0f},
                   .followCar = true,
                   .makes = kAllThree},
        SceneEntry{.name = "grinder",
                   .title = "A motorised concrete wheel grinding a steel bar: a fountain of sparks",
                   .file = "grinder.json",
                   .view = SceneView{b2Vec2(3.5f, 3.0f), 10.0f},
                   .makes = kSparks},
        SceneEntry{.name = "skidpad",
                   .title = "A long, low car launching and skidding on a concrete pad: tyre smoke",
                   .file = "skidpad.json",
                   .drive = SkidpadDrive(),
                   .view = SceneView{b2Vec2(-8.0f, 3.0f), 14.0f},
                   .followCar = true,
                   .makes = kSmoke},
        SceneEntry{.name = "rockslide",
                   .title = "Steel boulders tumbling down a dirt slope onto concrete: dirt and sparks",
                   .file = "rockslide.json",
                   .beforeStep = ReturnHome,
                   .view = SceneView{.wholeWorld = true},
                   .makes = kDirtAndSparks},
    };
    return scenes;
}

} // namespace

std::span<const SceneEntry> Scenes()
{
    return Registry();
}

const SceneEntry* FindScene(std::string_view name)
{
    for (const SceneEntry& entry : Registry())
    {
        if (entry.name == name)
        {
            return &entry;
        }
    }
    return nullptr;
}

std::string SceneNames()
{
    std::string names;
    for (const SceneEntry& entry : Registry())
    {
        names += (names.empty() ? "" : ", ") + std::string(entry.name);
    }
    return names;
}

std::filesystem::path BundledScenesDir()
{
    const char* overridden = std::getenv("CONTACTFX_SCENES");
    if (overridden != nullptr && *overridden != '\0')
    {
        return overridden;
    }
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    if (error)
    {
        return std::filesystem::path(CONTACTFX_SCENES_FROM_BIN);
    }
    return (program.parent_path() / CONTACTFX_SCENES_FROM_BIN).lexically_normal();
}

void CheckNotASceneName(const std::string& file)
{
    std::error_code error;
    if (FindScene(file) != nullptr && !std::filesystem::exists(file, error))
    {
        throw InputError(kCommandLine, "scene",
                         "no file \"" + file + "\"; for the registered scene give --scene " + file);
    }
}

SimulationDef SceneSimulationDef(const SceneEntry& entry, const std::filesystem::path& scenesDir)
{
    SimulationDef def;
    def.scene = scenesDir / entry.file;
    if (!entry.effectsFile.empty())
    {
        def.config = LoadEffectsFile(scenesDir / entry.effectsFile);
    }
    def.drive = entry.drive;
    return def;
}

void StepScene(const SceneEntry& entry, Simulation& simulation)
{
    if (entry.beforeStep != nullptr)
    {
        entry.beforeStep(simulation);
    }
    simulation.Step();
}

} // namespace cfx
