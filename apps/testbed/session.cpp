#include "session.h"

#include "harness/command_line.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>

namespace cfx::testbed
{

Session::~Session()
{
    m_drag.Release();
}

void Session::Open(const SceneEntry& entry, const std::optional<EffectsConfig>& config)
{
    SimulationDef def = SceneSimulationDef(entry, m_scenesDir);
    def.hz = 0.0f; // the scene's own stepsPerSecond, as RUBE steps it
    const std::optional<EffectsConfig>& chosen = config ? config : m_chosenConfig;
    if (chosen)
    {
        def.config = *chosen;
    }
    auto simulation = std::make_unique<Simulation>(def); // throws before anything here changes
    m_drag.Release();
    m_drag.Forget();
    m_simulation = std::move(simulation);
    m_chosenConfig = chosen;
    m_entry = &entry;
    m_events.Clear();
    ++m_generation;
    m_manual = false;
    m_input = DriveInput{};
    followCar = entry.followCar && m_simulation->GetCar().has_value();
    m_followLift = 0.0f;
    if (followCar)
    {
        cfx::Camera start; // where Follow puts the centre with no lift
        Follow(start, *m_simulation->GetCar()->Body());
        m_followLift = entry.view.center.y - start.center.y;
    }
    stepOnce = false;
    ResetView(m_camera.width, m_camera.height);
}

void Session::OpenFile(const std::filesystem::path& file, const std::optional<EffectsConfig>& config)
{
    auto scene = std::make_unique<FileScene>();
    scene->name = file.filename().string();
    scene->path = std::filesystem::absolute(file).lexically_normal().string();
    scene->entry = SceneEntry{.name = scene->name,
                              .title = scene->path,
                              .file = scene->path, // an absolute path: the scenes folder is not prepended
                              .view = SceneView{.wholeWorld = true}};
    Open(scene->entry, config); // throws before anything here changes
    m_file = std::move(scene);
}

std::vector<Diagnostic> Session::Warnings() const
{
    std::vector<Diagnostic> warnings = m_simulation->GetScene().warnings;
    const float sceneHz = m_simulation->GetScene().settings.stepsPerSecond;
    const float testbedHz = 1.0f / m_simulation->Dt();
    if (sceneHz < 1.0f) // Simulation steps at 1 Hz at least
    {
        Diagnostic warning{m_file && m_entry == &m_file->entry ? m_file->path : std::string(m_entry->file),
                           "stepsPerSecond",
                           "the scene steps at " + NumberText(sceneHz) + " Hz; the testbed steps at " +
                               NumberText(testbedHz) + " Hz, its lowest rate"};
        warning.warning = true;
        warnings.push_back(std::move(warning));
    }
    return warnings;
}

void Session::Restart()
{
    Open(*m_entry, m_simulation->GetEffects().Config());
}

std::vector<const SceneEntry*> Session::Listed() const
{
    std::vector<const SceneEntry*> listed;
    if (m_file)
    {
        listed.push_back(&m_file->entry);
    }
    for (const SceneEntry& entry : Scenes())
    {
        listed.push_back(&entry);
    }
    return listed;
}

std::vector<std::filesystem::path> Session::SceneFiles() const
{
    std::vector<std::filesystem::path> files;
    for (const SceneEntry* entry : Listed())
    {
        files.push_back(m_scenesDir / entry->file);
        if (!entry->effectsFile.empty())
        {
            files.push_back(m_scenesDir / entry->effectsFile);
        }
    }
    return files;
}

void Session::OpenNeighbour(int step)
{
    const std::vector<const SceneEntry*> listed = Listed();
    const auto count = static_cast<long>(listed.size());
    const long current = std::find(listed.begin(), listed.end(), m_entry) - listed.begin();
    const long direction = step < 0 ? -1 : 1;
    std::optional<InputError> first;
    for (long tried = 0; tried < count - 1; ++tried)
    {
        const long next = ((current + step + direction * tried) % count + count) % count;
        try
        {
            Open(*listed[static_cast<std::size_t>(next)]);
            return;
        }
        catch (const InputError& error)
        {
            if (!first)
            {
                first = error;
            }
        }
    }
    if (first)
    {
        throw *first;
    }
}

void Session::Launch()
{
    constexpr float kRadius = 0.25f;    // m
    constexpr float kDensity = 8.0f;    // kg/m^2
    constexpr float kFlightTime = 0.6f; // s to cover the distance at launch speed
    const b2Vec2 from = m_camera.ToWorld(
        b2Vec2(0.1f * static_cast<float>(m_camera.width), 0.1f * static_cast<float>(m_camera.height)));
    const b2Vec2 to = m_camera.ToWorld(
        b2Vec2(0.5f * static_cast<float>(m_camera.width), static_cast<float>(m_camera.height)));
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.bullet = true;
    def.position = from;
    def.linearVelocity = (1.0f / kFlightTime) * (to - from);
    b2Body* ball = m_simulation->GetScene().world->CreateBody(&def);
    b2CircleShape circle;
    circle.m_radius = kRadius;
    b2FixtureDef fixture;
    fixture.shape = &circle;
    fixture.density = kDensity;
    fixture.friction = 0.6f;
    fixture.restitution = 0.2f;
    Effects& effects = m_simulation->GetEffects();
    effects.SetMaterial(ball->CreateFixture(&fixture), effects.FindMaterial("steel"));
}

void Session::ApplyConfig(const EffectsConfig& config)
{
    m_simulation->ReplaceEffects(config);
    m_chosenConfig = config;
    m_events.Clear(); // their rules were the old configuration's
}

void Session::Advance()
{
    if (paused && !stepOnce)
    {
        return;
    }
    stepOnce = false;
    if (m_manual)
    {
        m_simulation->SetInput(m_input);
    }
    StepScene(*m_entry, *m_simulation);
    m_events.Record(m_simulation->GetEffects(), m_simulation->Time());
    if (followCar && m_simulation->GetCar())
    {
        Follow(m_camera, *m_simulation->GetCar()->Body(), m_followLift);
    }
}

void Session::Resize(int width, int height)
{
    if (width == m_camera.width && height == m_camera.height)
    {
        return;
    }
    const float metresHigh = static_cast<float>(m_camera.height) / m_camera.pixelsPerMetre;
    m_camera.width = std::max(width, 1);
    m_camera.height = std::max(height, 1);
    m_camera.pixelsPerMetre = static_cast<float>(m_camera.height) / metresHigh;
}

void Session::ResetView(int width, int height)
{
    const SceneView& view = m_entry->view;
    const float aspect = static_cast<float>(std::max(width, 1)) / static_cast<float>(std::max(height, 1));
    m_camera = MakeCamera(std::max(width, 1), std::max(height, 1), view.height * aspect, view.center);
    if (view.wholeWorld)
    {
        FitWorld(m_camera, *m_simulation->GetScene().world);
    }
    if (followCar && m_simulation->GetCar())
    {
        Follow(m_camera, *m_simulation->GetCar()->Body(), m_followLift);
    }
}

void Session::SetKeys(bool left, bool right, bool brake)
{
    if (left || right || brake)
    {
        m_manual = true;
    }
    m_input.direction = (right ? 1 : 0) - (left ? 1 : 0);
    m_input.brake = brake;
}

void Session::Zoom(float factor, b2Vec2 anchor)
{
    constexpr float kMinPixelsPerMetre = 1.0e-3f; // a 1,000 km level on 1,000 px
    constexpr float kMaxPixelsPerMetre = 1.0e5f;  // a 1 cm level on 1,000 px
    // A view fitted to a world outside the limits (40 km across, 5 cm) keeps zooming the way asked, toward
    // the limits, never jumping to one (zooming out of 0.02 px/m went to 0.5).
    const float current = m_camera.pixelsPerMetre;
    const float ppm = std::clamp(current / factor, std::min(kMinPixelsPerMetre, current),
                                 std::max(kMaxPixelsPerMetre, current));
    const float applied = m_camera.pixelsPerMetre / ppm;
    m_camera.center = anchor + applied * (m_camera.center - anchor);
    m_camera.pixelsPerMetre = ppm;
}

void Session::Pan(b2Vec2 pixels)
{
    m_camera.center += (1.0f / m_camera.pixelsPerMetre) * b2Vec2(-pixels.x, pixels.y);
    followCar = false;
}

} // namespace cfx::testbed
