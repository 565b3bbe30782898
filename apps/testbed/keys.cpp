#include "keys.h"

#include "contactfx/error.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <algorithm>

namespace cfx::testbed
{

namespace
{

constexpr KeyBinding kBindings[] = {
    {0, KeyAction::none, "a / d", "drive the car left / right (held; takes it from its script)"},
    {0, KeyAction::none, "s", "brake (held)"},
    {GLFW_KEY_4, KeyAction::fourWheelDrive, "4", "four-wheel drive on / off"},
    {GLFW_KEY_F, KeyAction::followCar, "f", "follow the car on / off"},
    {GLFW_KEY_SPACE, KeyAction::launch, "Space", "launch a steel ball into the scene"},
    {GLFW_KEY_P, KeyAction::pause, "p", "pause / run"},
    {GLFW_KEY_O, KeyAction::singleStep, "o", "one step (pauses)"},
    {GLFW_KEY_R, KeyAction::restart, "r", "restart the scene"},
    {GLFW_KEY_LEFT_BRACKET, KeyAction::previousScene, "[", "previous scene"},
    {GLFW_KEY_RIGHT_BRACKET, KeyAction::nextScene, "]", "next scene"},
    {GLFW_KEY_X, KeyAction::zoomIn, "x", "zoom in"},
    {GLFW_KEY_Z, KeyAction::zoomOut, "z", "zoom out"},
    {0, KeyAction::none, "wheel", "zoom about the cursor"},
    {GLFW_KEY_LEFT, KeyAction::panLeft, "arrows", "pan (so does a right drag)"},
    {GLFW_KEY_RIGHT, KeyAction::panRight, nullptr, nullptr},
    {GLFW_KEY_UP, KeyAction::panUp, nullptr, nullptr},
    {GLFW_KEY_DOWN, KeyAction::panDown, nullptr, nullptr},
    {GLFW_KEY_HOME, KeyAction::resetView, "Home", "reset the view"},
    {0, KeyAction::none, "left drag", "move a body"},
    {GLFW_KEY_TAB, KeyAction::toggleUi, "Tab", "hide / show the panels"},
    {GLFW_KEY_ESCAPE, KeyAction::quit, "Esc", "quit"},
};

// Runs `change` on the session; an InputError it throws goes to `error`, which is cleared on success.
template <typename Change> void Guarded(std::string& error, Change change)
{
    try
    {
        change();
        error.clear();
    }
    catch (const InputError& problem)
    {
        error = problem.what();
    }
}

} // namespace

void RestartScene(Session& session, std::string& error)
{
    Guarded(error, [&] { session.Restart(); });
}

std::span<const KeyBinding> KeyBindings()
{
    return kBindings;
}

KeyAction ActionForKey(int key)
{
    for (const KeyBinding& binding : kBindings)
    {
        if (binding.key != 0 && binding.key == key)
        {
            return binding.action;
        }
    }
    return KeyAction::none;
}

std::string KeysHelp()
{
    std::string text;
    for (const KeyBinding& binding : kBindings)
    {
        if (binding.name != nullptr)
        {
            std::string name = binding.name;
            name.resize(std::max<std::size_t>(name.size(), 10), ' ');
            text += "  " + name + "  " + binding.meaning + "\n";
        }
    }
    return text;
}

bool ApplyKey(KeyAction action, KeyTarget& target)
{
    Session& session = target.session;
    switch (action)
    {
    case KeyAction::pause:
        session.paused = !session.paused;
        return true;
    case KeyAction::singleStep:
        session.paused = true;
        session.stepOnce = true;
        return true;
    case KeyAction::restart:
        RestartScene(session, target.sceneError);
        return true;
    case KeyAction::followCar:
        session.followCar = !session.followCar && session.Sim().GetCar().has_value();
        return true;
    case KeyAction::fourWheelDrive:
        session.ToggleFourWheelDrive();
        return true;
    case KeyAction::resetView:
        session.ResetView(target.viewWidth, target.viewHeight);
        return true;
    case KeyAction::zoomIn:
        session.Zoom(1.0f / kKeyZoomStep, session.Camera().center);
        return true;
    case KeyAction::zoomOut:
        session.Zoom(kKeyZoomStep, session.Camera().center);
        return true;
    case KeyAction::panLeft:
        session.Pan(b2Vec2(kKeyPanPixels, 0.0f));
        return true;
    case KeyAction::panRight:
        session.Pan(b2Vec2(-kKeyPanPixels, 0.0f));
        return true;
    case KeyAction::panUp:
        session.Pan(b2Vec2(0.0f, kKeyPanPixels));
        return true;
    case KeyAction::panDown:
        session.Pan(b2Vec2(0.0f, -kKeyPanPixels));
        return true;
    case KeyAction::previousScene:
        Guarded(target.sceneError, [&] { session.OpenNeighbour(-1); });
        return true;
    case KeyAction::nextScene:
        Guarded(target.sceneError, [&] { session.OpenNeighbour(1); });
        return true;
    case KeyAction::toggleUi:
        target.uiHidden = !target.uiHidden;
        return true;
    case KeyAction::launch:
        session.Launch();
        return true;
    case KeyAction::none:
    case KeyAction::quit:
        break;
    }
    return false;
}

} // namespace cfx::testbed
