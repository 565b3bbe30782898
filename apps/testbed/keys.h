// contactfx-testbed: the keyboard, as in Box2D's testbed where there is a counterpart.
//
// One table maps keys to actions; it drives the key callback, the --help text and the panel's key list,
// so none of them can disagree. ApplyKey carries an action out on the window-free state (the session and
// whether the UI shows), so the tests drive keys without a window. The car's a / s / d are held keys,
// read every frame by the frame loop, and listed here for help only.
#pragma once

#include "session.h"

#include <span>
#include <string>

namespace cfx::testbed
{

enum class KeyAction
{
    none,
    pause,          ///< p
    singleStep,     ///< o
    restart,        ///< r
    followCar,      ///< f
    fourWheelDrive, ///< 4
    resetView,      ///< Home
    zoomIn,         ///< x (Box2D's testbed)
    zoomOut,        ///< z (Box2D's testbed)
    panLeft,        ///< arrows
    panRight,
    panUp,
    panDown,
    previousScene, ///< [
    nextScene,     ///< ]
    toggleUi,      ///< Tab
    launch,        ///< Space: a steel ball into the scene (Box2D's testbed launches a bomb)
    quit,          ///< Escape
};

/// One row of the key table.
struct KeyBinding
{
    int key; ///< GLFW key code; 0 for rows that only document (held keys, the mouse)
    KeyAction action;
    const char* name;    ///< as the user reads it, e.g. "x"
    const char* meaning; ///< what it does
};

/// Every key the testbed knows, in help order.
std::span<const KeyBinding> KeyBindings();

/// The action of a GLFW key code, or none.
KeyAction ActionForKey(int key);

/// The key table as text, one "  NAME  MEANING" line per row, for --help.
std::string KeysHelp();

/// What the keys change outside the session.
struct KeyTarget
{
    Session& session;
    bool& uiHidden;          ///< Tab flips it
    std::string& sceneError; ///< a scene that failed to open says why here
    int viewWidth = 1;       ///< px of the world view, for Home
    int viewHeight = 1;
};

/// Zoom factor of one press of x or z, and pan step of an arrow key.
inline constexpr float kKeyZoomStep = 1.1f;
inline constexpr float kKeyPanPixels = 40.0f;

/// Restarts the scene; a failure (its file went bad meanwhile) goes to `error`.
void RestartScene(Session& session, std::string& error);

/// Carries out `action` (quit is the caller's). Returns false for none and quit.
bool ApplyKey(KeyAction action, KeyTarget& target);

} // namespace cfx::testbed
