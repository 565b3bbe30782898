// The frame loop: input, one simulation step, the world view, the panels. The keys follow the
// tutorial (a / d drive, s brakes, 4 four-wheel drive, f follows the car) and Box2D's testbed
// (p pause, o single step, r restart).
#include "app.h"

#include "contactfx/render/palette.h"
#include "contactfx/scene/effects_json.h"
#include "gl_draw.h"
#include "layout.h"
#include "panels.h"
#include "screenshot.h"
#include "session.h"
#include "window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>
#include <algorithm>
#include <box2d/b2_world.h>
#include <chrono>
#include <cmath>
#include <imgui.h>

namespace cfx::testbed
{

namespace
{

constexpr float kZoomStep = 1.1f;   // per wheel notch or key press
constexpr float kPanPixels = 40.0f; // per arrow key press
// Without interaction only the last frames are drawn (a couple, so that ImGui's layout settles); the
// ones before are simulated only, one step each, as when drawn.
constexpr int kDrawnFrames = 3;

// Interactive runs keep to the simulation's own rate (1/dt steps per second) whatever the display's
// frame rate; after a stall they drop time instead of racing to catch up.
class Pacer
{
public:
    int StepsDue(double elapsed, double dt, bool running)
    {
        constexpr int kMostPerFrame = 4;
        m_owed = running ? std::min(m_owed + elapsed, kMostPerFrame * dt) : 0.0;
        const int steps = static_cast<int>(m_owed / dt);
        m_owed -= steps * dt;
        return steps;
    }

private:
    double m_owed = 0.0; // s of simulation time due
};

struct App
{
    Window& window;
    Session& session;
    PanelState& panels;
    bool panning = false;
    b2Vec2 lastCursor{0.0f, 0.0f};

    PixelRect View() const
    {
        int width = 0, height = 0;
        window.Size(width, height);
        return WorldViewRect(width, height);
    }

    // World point under a cursor position (window px), or nothing outside the world view.
    bool WorldAt(b2Vec2 cursor, b2Vec2& world) const
    {
        const PixelRect view = View();
        const b2Vec2 local(cursor.x - static_cast<float>(view.x), cursor.y - static_cast<float>(view.y));
        if (local.x < 0.0f || local.y < 0.0f || local.x >= static_cast<float>(view.width) ||
            local.y >= static_cast<float>(view.height))
        {
            return false;
        }
        world = session.Camera().ToWorld(local);
        return true;
    }

    b2Vec2 Cursor() const
    {
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window.Handle(), &x, &y);
        return b2Vec2(static_cast<float>(x), static_cast<float>(y));
    }

    void OnKey(int key, int action)
    {
        if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard)
        {
            return;
        }
        const PixelRect view = View();
        switch (key)
        {
        case GLFW_KEY_P:
            session.paused = !session.paused;
            break;
        case GLFW_KEY_O:
            session.paused = true;
            session.stepOnce = true;
            break;
        case GLFW_KEY_R:
            RestartScene(session, panels.sceneError);
            break;
        case GLFW_KEY_F:
            session.followCar = !session.followCar && session.Sim().GetCar().has_value();
            break;
        case GLFW_KEY_4:
            session.ToggleFourWheelDrive();
            break;
        case GLFW_KEY_HOME:
            session.ResetView(view.width, view.height);
            break;
        case GLFW_KEY_Z:
            session.Zoom(1.0f / kZoomStep, session.Camera().center);
            break;
        case GLFW_KEY_X:
            session.Zoom(kZoomStep, session.Camera().center);
            break;
        case GLFW_KEY_LEFT:
            session.Pan(b2Vec2(kPanPixels, 0.0f));
            break;
        case GLFW_KEY_RIGHT:
            session.Pan(b2Vec2(-kPanPixels, 0.0f));
            break;
        case GLFW_KEY_UP:
            session.Pan(b2Vec2(0.0f, kPanPixels));
            break;
        case GLFW_KEY_DOWN:
            session.Pan(b2Vec2(0.0f, -kPanPixels));
            break;
        case GLFW_KEY_ESCAPE:
            glfwSetWindowShouldClose(window.Handle(), GLFW_TRUE);
            break;
        default:
            break;
        }
    }

    void OnMouseButton(int button, int action)
    {
        if (action == GLFW_RELEASE)
        {
            if (button == GLFW_MOUSE_BUTTON_LEFT)
            {
                session.Drag().Release();
            }
            if (button == GLFW_MOUSE_BUTTON_RIGHT)
            {
                panning = false;
            }
            return;
        }
        b2Vec2 world;
        if (ImGui::GetIO().WantCaptureMouse || !WorldAt(Cursor(), world))
        {
            return;
        }
        if (button == GLFW_MOUSE_BUTTON_LEFT)
        {
            session.Drag().Grab(session.Sim().GetScene(), world);
        }
        else if (button == GLFW_MOUSE_BUTTON_RIGHT)
        {
            panning = true;
            lastCursor = Cursor();
        }
    }

    void OnCursor(b2Vec2 cursor)
    {
        if (panning)
        {
            session.Pan(cursor - lastCursor);
            lastCursor = cursor;
        }
        b2Vec2 world;
        if (session.Drag().Active() && WorldAt(cursor, world))
        {
            session.Drag().MoveTo(world);
        }
    }

    void OnScroll(double offset)
    {
        b2Vec2 world;
        if (!ImGui::GetIO().WantCaptureMouse && WorldAt(Cursor(), world))
        {
            session.Zoom(std::pow(kZoomStep, -static_cast<float>(offset)), world);
        }
    }

    // The keys held down, read every frame: the car's throttle and brake.
    void ReadHeldKeys()
    {
        if (ImGui::GetIO().WantCaptureKeyboard)
        {
            return;
        }
        auto held = [&](int key) { return glfwGetKey(window.Handle(), key) == GLFW_PRESS; };
        const bool left = held(GLFW_KEY_A), right = held(GLFW_KEY_D), brake = held(GLFW_KEY_S);
        if (left || right || brake || session.Manual())
        {
            session.SetKeys(left, right, brake);
        }
    }
};

App& FromWindow(GLFWwindow* window)
{
    return *static_cast<App*>(glfwGetWindowUserPointer(window));
}

void InstallCallbacks(GLFWwindow* window, App& app)
{
    glfwSetWindowUserPointer(window, &app);
    glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int)
                       { FromWindow(w).OnKey(key, action); });
    glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int)
                               { FromWindow(w).OnMouseButton(button, action); });
    glfwSetCursorPosCallback(window,
                             [](GLFWwindow* w, double x, double y) {
                                 FromWindow(w).OnCursor(b2Vec2(static_cast<float>(x), static_cast<float>(y)));
                             });
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double y) { FromWindow(w).OnScroll(y); });
}

void DrawWorld(Session& session, GlDraw& draw, const DrawToggles& toggles,
               const render::ShapePalette& palette, std::vector<ParticleSprite>& sprites)
{
    const Effects& effects = session.Sim().GetEffects();
    draw.Begin(session.Camera());
    if (toggles.joints)
    {
        b2World& world = *session.Sim().GetScene().world;
        draw.SetFlags(b2Draw::e_jointBit);
        world.SetDebugDraw(&draw);
        world.DebugDraw();
        world.SetDebugDraw(nullptr);
    }
    if (toggles.shapes)
    {
        render::DrawShapes(effects, draw, palette);
    }
    if (toggles.particles)
    {
        CollectSprites(effects, sprites);
        draw.DrawParticles(sprites);
    }
    // A ring where each recent event happened: impacts large and red, scrapes small (green while they
    // go on, grey when they end). They fade out over half a second.
    const float now = session.Sim().Time();
    for (const LoggedEvent& logged : session.Events().Entries())
    {
        const float age = now - logged.time;
        if (age > 0.5f)
        {
            continue;
        }
        const float fade = 1.0f - 2.0f * age;
        const EffectEvent& event = logged.event;
        const bool impact = event.type == EffectEventType::impact;
        const bool ended = event.type == EffectEventType::scrapeEnded;
        const b2Color color =
            impact ? b2Color(1.0f, 0.3f, 0.2f, fade)
                   : (ended ? b2Color(0.6f, 0.6f, 0.6f, fade) : b2Color(0.3f, 1.0f, 0.4f, fade));
        draw.DrawCircle(event.point, impact ? 0.15f + 0.05f * event.approachSpeed : 0.12f, color);
    }
    draw.End();
}

} // namespace

int RunTestbed(const Options& options)
{
    Session session(BundledScenesDir());
    std::optional<EffectsConfig> config;
    if (!options.effects.empty())
    {
        config = LoadEffectsFile(options.effects);
    }
    session.Open(*FindScene(options.scene), config);

    const bool headless = options.frames > 0;
    Window window(kDefaultWidth, kDefaultHeight, "contactfx testbed", !headless);
    PanelState panels;
    panels.toggles.particles = !options.hideParticles;
    App app{window, session, panels};
    InstallCallbacks(window.Handle(), app);
    window.StartUi();

    const render::RenderStyle style;
    const render::ShapePalette palette = render::TutorialPalette();
    GlDraw draw(style);
    std::vector<ParticleSprite> sprites;
    {
        const PixelRect view = app.View();
        session.ResetView(view.width, view.height);
    }

    using Clock = std::chrono::steady_clock;
    Clock::time_point last = Clock::now();
    Pacer pacer;
    for (int frame = 1; headless ? frame <= options.frames : !window.ShouldClose(); ++frame)
    {
        if (headless && frame <= options.frames - kDrawnFrames)
        {
            session.Advance(); // nobody watches: simulate only
            panels.times.Record(session.Sim().LastStepTimes());
            continue;
        }
        window.BeginFrame();
        app.ReadHeldKeys();
        const Clock::time_point now = Clock::now();
        const double elapsed = std::chrono::duration<double>(now - last).count();
        panels.frameMs = static_cast<float>(elapsed * 1000.0);
        last = now;
        const int steps =
            headless || session.stepOnce
                ? 1
                : pacer.StepsDue(elapsed, static_cast<double>(session.Sim().Dt()), !session.paused);
        for (int i = 0; i < steps; ++i)
        {
            const std::uint64_t before = session.Sim().Steps();
            session.Advance();
            if (session.Sim().Steps() != before)
            {
                panels.times.Record(session.Sim().LastStepTimes());
            }
        }

        int width = 0, height = 0;
        window.Size(width, height);
        const PixelRect view = WorldViewRect(width, height);
        session.Resize(view.width, view.height);
        glViewport(0, 0, width, height);
        glClearColor(style.background.r, style.background.g, style.background.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glViewport(view.x, height - view.y - view.height, view.width, view.height);
        DrawWorld(session, draw, panels.toggles, palette, sprites);

        DrawPanels(session, panels, width, height, kPanelWidth);
        window.RenderUi();
        if (headless && frame == options.frames && !options.screenshot.empty())
        {
            SaveScreenshot(width, height, options.screenshot);
        }
        window.Present();
    }
    return 0;
}

} // namespace cfx::testbed
