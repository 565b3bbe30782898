// contactfx-testbed: the panels (Dear ImGui), all in one column right of the world view.
//
//   Scenes      the registered scenes; pause, single step, restart; the car's keys; what is drawn
//   Statistics  ms per step for the world and for the effects, contacts per rule, particles by type
//   Effects     materials, particle types, pair rules and budget, edited live and saved as JSON
//
// Panels only read and change the Session and their own state; they never step the simulation.
#pragma once

#include "contactfx/config.h"
#include "contactfx/draw/debug_layers.h"
#include "effects_editor.h"
#include "keys.h"
#include "session.h"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace cfx::testbed
{

/// Colours of the panels' messages (r, g, b), and `text` in one, wrapped at the panel's edge (a long error
/// names a file and a JSON path: cut at the edge, its end was lost).
inline constexpr std::array<float, 3> kErrorColour{1.0f, 0.4f, 0.4f};
inline constexpr std::array<float, 3> kWarningColour{1.0f, 0.8f, 0.3f};
inline constexpr std::array<float, 3> kDoneColour{0.5f, 0.9f, 0.5f};
void WrappedText(const std::array<float, 3>& colour, const std::string& text);
/// A tooltip of `text` wrapped at about 35 characters' width (a field's doc line ran off the window).
void WrappedTooltip(std::string_view text);

/// What the world view draws.
struct DrawToggles
{
    bool shapes = true;
    bool joints = true;
    bool particles = true;
    bool events = true; ///< a fading ring where each recent event happened
    bool scaleBar = true;
    DebugLayers debug; ///< contact points, normals, impulses, rule names, particle velocities
};

/// Recent step times, for averages that do not flicker.
class StepTimeWindow
{
public:
    void Record(const Simulation::StepTimes& times);
    /// Mean over the recorded steps (at most the last kCount), ms.
    Simulation::StepTimes Mean() const;

private:
    static constexpr std::size_t kCount = 60;
    std::array<Simulation::StepTimes, kCount> m_times{};
    std::size_t m_next = 0;
    std::size_t m_count = 0;
};

/// Scene list, controls and draw toggles. Errors of opening a scene go to `error`.
void ScenesPanel(Session& session, DrawToggles& toggles, std::string& error);

/// Step times, contacts per rule and particles by type of the running simulation.
void StatisticsPanel(const Session& session, const StepTimeWindow& times, float frameMs);
/// The recent effect events, newest first.
void EventsPanel(const Session& session);

/// Edits a draft of the effects configuration; a finished edit of a valid draft replaces the
/// simulation's effects at once. Save writes the draft as an effects config JSON file.
void EffectsPanel(Session& session, EffectsEditor& editor);

/// The whole panel column, `width` px wide on the right of a `windowWidth` x `windowHeight` window.
struct PanelState
{
    DrawToggles toggles;
    StepTimeWindow times;
    EffectsEditor editor;
    std::string sceneError;
    float frameMs = 0.0f;
    bool hidden = false; ///< Tab: the world view takes the whole window
};
void DrawPanels(Session& session, PanelState& state, int windowWidth, int windowHeight, int width);

} // namespace cfx::testbed
