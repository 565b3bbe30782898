#include "session.h"

#include <algorithm>
#include <box2d/b2_body.h>

namespace cfx::testbed
{

Session::~Session()
{
    m_drag.Release();
}

void Session::Open(const SceneEntry& entry, const std::optional<EffectsConfig>& config)
{
    SimulationDef def = SceneSimulationDef(entry, m_scenesDir);
    if (config)
    {
        def.config = *config;
    }
    auto simulation = std::make_unique<Simulation>(def); // throws before anything here changes
    m_drag.Release();
    m_drag.Forget();
    m_simulation = std::move(simulation);
    m_entry = &entry;
    m_events.Clear();
    ++m_generation;
    m_manual = false;
    m_input = DriveInput{};
    followCar = entry.followCar && m_simulation->GetCar().has_value();
    m_followLift = 0.0f;
    if (followCar)
    {
        render::Camera start; // where Follow puts the centre with no lift
        render::Follow(start, *m_simulation->GetCar()->Body());
        m_followLift = entry.view.center.y - start.center.y;
    }
    stepOnce = false;
    ResetView(m_camera.width, m_camera.height);
}

void Session::Restart()
{
    Open(*m_entry, m_simulation->GetEffects().Config());
}

void Session::ApplyConfig(const EffectsConfig& config)
{
    m_simulation->ReplaceEffects(config);
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
        render::Follow(m_camera, *m_simulation->GetCar()->Body(), m_followLift);
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
    m_camera = render::MakeCamera(std::max(width, 1), std::max(height, 1), view.height * aspect, view.center);
    if (followCar && m_simulation->GetCar())
    {
        render::Follow(m_camera, *m_simulation->GetCar()->Body(), m_followLift);
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
    constexpr float kMinPixelsPerMetre = 0.5f;
    constexpr float kMaxPixelsPerMetre = 2000.0f;
    const float ppm = std::clamp(m_camera.pixelsPerMetre / factor, kMinPixelsPerMetre, kMaxPixelsPerMetre);
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
