// contactfx-testbed: the scene on show and everything the user does to it.
//
// Holds the scene's simulation (a registered scene, or a RUBE scene file opened as it is), its camera, the
// driver's keys, pause and single step, the mouse joint, and the effects configuration in force. Opening
// another scene or changing the configuration never leaves a half-made state: on bad input the session keeps
// what it had and reports the error. One step of the simulation per Advance(), so N frames are N steps
// whatever the frame rate (the screenshot mode's determinism).
#pragma once

#include "contactfx/draw/camera.h"
#include "event_log.h"
#include "harness/scenes.h"
#include "mouse_drag.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace cfx::testbed
{

class Session
{
public:
    explicit Session(std::filesystem::path scenesDir) : m_scenesDir(std::move(scenesDir)) {}
    ~Session();

    /// Opens a registered scene with `config`; when none is given, with the configuration chosen before
    /// (given to an earlier Open, as --effects does, or put in force by ApplyConfig), else with the scene's
    /// own effects. Throws InputError and keeps the current scene (and the chosen configuration) on bad
    /// input.
    void Open(const SceneEntry& entry, const std::optional<EffectsConfig>& config = std::nullopt);
    /// Opens the RUBE scene file `file` as `contactfx run FILE` does: no scripted drive or per-step action,
    /// the whole world in view, with the configuration chosen (see Open), else the default preset. Every
    /// scene steps at its file's own `stepsPerSecond` (as RUBE steps it; 1 Hz at least).
    /// Entry() is then the file's (name: the file name; title and file: its absolute path). Throws
    /// InputError naming the file and keeps the current scene on bad input.
    void OpenFile(const std::filesystem::path& file,
                  const std::optional<EffectsConfig>& config = std::nullopt);
    /// Opens the current scene again from its file, with the effects configuration in force.
    void Restart();
    /// The scenes to choose from, in order: the scene file last opened (if any), then Scenes().
    std::vector<const SceneEntry*> Listed() const;
    /// Opens the scene `step` places after the current one in Listed() order (negative: before), wrapping
    /// around, with the configuration chosen (see Open), else its own effects. One that cannot be opened (a
    /// scene file deleted since) is passed over to the next in the same direction; when none can be, throws
    /// the first one's InputError and keeps the scene.
    void OpenNeighbour(int step);
    /// Launches a steel ball (material "steel" when the effects have it) from the top left of the view
    /// towards the middle of its bottom edge, fast enough to strike sparks.
    void Launch();
    /// Replaces the effects configuration, keeping the world (Simulation::ReplaceEffects); scenes opened
    /// later use it too.
    void ApplyConfig(const EffectsConfig& config);

    /// One simulation step unless paused; when paused, one step if a single step was asked for.
    void Advance();
    /// The view rectangle changed to `width` x `height` px: keeps the centre and the metres shown
    /// vertically.
    void Resize(int width, int height);
    /// Puts the camera where the scene says (centre, height), for a view of `width` x `height` px.
    void ResetView(int width, int height);

    // The driver's keys. Pressing any of a, s, d takes the car from its script.
    void SetKeys(bool left, bool right, bool brake);
    void ToggleFourWheelDrive() { m_input.fourWheelDrive = !m_input.fourWheelDrive; }
    bool FourWheelDrive() const { return m_input.fourWheelDrive; }
    bool Manual() const { return m_manual; }

    /// Zooms by `factor` (> 1 shows more) about the world point `anchor`, which stays put on screen.
    void Zoom(float factor, b2Vec2 anchor);
    /// Moves the view by `pixels` (screen px, y down).
    void Pan(b2Vec2 pixels);

    MouseDrag& Drag() { return m_drag; }
    Simulation& Sim() { return *m_simulation; }
    const Simulation& Sim() const { return *m_simulation; }
    const SceneEntry& Entry() const { return *m_entry; }
    /// What the scene on show loaded with but may not be what its file meant (Scene::warnings: unknown keys,
    /// dropped vertices), and for a scene whose stepsPerSecond is under the testbed's lowest rate (1 Hz),
    /// that.
    std::vector<Diagnostic> Warnings() const;
    /// Every file the listed scenes are read from: their RUBE files and the registered scenes' effects
    /// files (not a configuration given with --effects, which Save as may update).
    std::vector<std::filesystem::path> SceneFiles() const;
    /// The folder of the registered scenes (BundledScenesDir() in the testbed).
    const std::filesystem::path& ScenesDir() const { return m_scenesDir; }
    const cfx::Camera& Camera() const { return m_camera; }
    /// Effect events of the recent steps (cleared when a simulation is opened).
    const EventLog& Events() const { return m_events; }
    /// Changes each time a simulation is opened (another scene, a restart).
    std::uint64_t Generation() const { return m_generation; }

    bool paused = false;
    bool stepOnce = false;
    bool followCar = false;

private:
    /// A scene file's entry and the text its views show.
    struct FileScene
    {
        std::string name;
        std::string path; ///< absolute
        SceneEntry entry;
    };

    std::filesystem::path m_scenesDir;
    const SceneEntry* m_entry = nullptr; ///< a registered entry, or m_file's
    std::unique_ptr<FileScene> m_file;   ///< the scene file last opened; null: none was
    std::unique_ptr<Simulation> m_simulation;
    /// The configuration the user chose (--effects, an applied edit): every scene opened uses it.
    std::optional<EffectsConfig> m_chosenConfig;
    cfx::Camera m_camera;
    MouseDrag m_drag;
    EventLog m_events;
    DriveInput m_input;
    bool m_manual = false;
    std::uint64_t m_generation = 0;
    float m_followLift = 0.0f; // m: the scene's view centre above where Follow centres at the start
};

} // namespace cfx::testbed
