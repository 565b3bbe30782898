// The frame loop: input, one simulation step, the world view, the panels. The keys (keys.h) follow the
// tutorial (a / d drive, s brakes, 4 four-wheel drive, f follows the car) and Box2D's testbed (p pause,
// o single step, r restart, x / z zoom in / out, [ ] scenes, Tab hides the panels, Space launches).
#include "app.h"

#include "contactfx/draw/frame_builder.h"
#include "contactfx/scene/effects_json.h"
#include "gl_draw.h"
#include "keys.h"
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
#include <iostream>

namespace cfx::testbed
{

namespace
{

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
        return WorldViewRect(width, height, !panels.hidden);
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
        const KeyAction what = ActionForKey(key);
        if (what == KeyAction::quit)
        {
            glfwSetWindowShouldClose(window.Handle(), GLFW_TRUE);
            return;
        }
        const PixelRect view = View();
        KeyTarget target{session, panels.hidden, panels.sceneError, view.width, view.height};
        ApplyKey(what, target);
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
            session.Zoom(std::pow(kKeyZoomStep, -static_cast<float>(offset)), world);
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

// The world view as a draw list, as the Cairo pictures build it (RecordWorldShapes, AddParticles), with
// what the panels switch on.
void DrawWorld(Session& session, GlRenderer& renderer, const DrawToggles& toggles, const FrameOptions& look,
               FrameScratch& scratch)
{
    const Effects& effects = session.Sim().GetEffects();
    DrawList& list = scratch.list;
    list.Begin(session.Camera(), look.style.background);
    list.backgroundBottom = look.style.backgroundBottom;
    ShapeRecorder draw(list, look.style);
    if (toggles.shapes)
    {
        RecordWorldShapes(effects, look.palette, draw);
    }
    if (toggles.joints)
    {
        b2World& world = *session.Sim().GetScene().world;
        draw.SetFlags(b2Draw::e_jointBit);
        world.SetDebugDraw(&draw);
        world.DebugDraw();
        world.SetDebugDraw(nullptr);
    }
    // A ring where each recent event happened: impacts large and red, scrapes small (green while they
    // go on, grey when they end). They fade out over half a second.
    const float now = session.Sim().Time();
    for (const LoggedEvent& logged : session.Events().Entries())
    {
        const float age = now - logged.time;
        if (!toggles.events || age > 0.5f || logged.event.type == EffectEventType::particleHits) // too many
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
    scratch.sprites.clear();
    if (toggles.particles)
    {
        CollectSprites(effects, scratch.sprites);
        AddParticles(list, scratch.sprites, look.style);
    }
    list.shapesUnderSprites = list.shapes.size(); // the debug layers show over the particles
    DebugLayers debug = toggles.debug;
    debug.stepTime = session.Sim().Dt();
    AddDebugLayers(list, effects, scratch.sprites, debug, look.style);
    if (toggles.scaleBar)
    {
        list.overlay.scaleBar = MakeScaleBar(list.camera);
    }
    renderer.Render(list);
}

// The list's text (rule names, the scale bar's length), which the OpenGL renderer leaves to ImGui, over the
// world view whose top left corner is at `origin` (window px).
void DrawListText(const DrawList& list, ImVec2 origin)
{
    ImDrawList& draw = *ImGui::GetBackgroundDrawList();
    for (const TextLabel& label : list.labels)
    {
        const ImVec2 at(origin.x + label.at.x, origin.y + label.at.y - ImGui::GetFontSize());
        draw.AddText(ImVec2(at.x + 1.0f, at.y + 1.0f), IM_COL32(0, 0, 0, 180), label.text.c_str());
        draw.AddText(at,
                     ImGui::ColorConvertFloat4ToU32(
                         ImVec4(label.color.r, label.color.g, label.color.b, label.color.a)),
                     label.text.c_str());
    }
    const ScaleBar& bar = list.overlay.scaleBar;
    if (bar.shown)
    {
        draw.AddText(
            ImVec2(origin.x + bar.from.x + 4.0f, origin.y + bar.from.y - 6.0f - ImGui::GetFontSize()),
            IM_COL32(235, 235, 235, 230), bar.label.c_str());
    }
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
    if (options.sceneFile.empty())
    {
        session.Open(*FindScene(SceneName(options)), config);
    }
    else
    {
        session.OpenFile(options.sceneFile, config);
    }
    for (const Diagnostic& warning : session.Warnings()) // as `contactfx run` warns ("...: warning: ...")
    {
        std::cerr << "contactfx-testbed: " << warning.ToString() << '\n';
    }

    const bool headless = options.frames > 0;
    Window window(kDefaultWidth, kDefaultHeight, "contactfx testbed", !headless);
    PanelState panels;
    panels.toggles.particles = !options.hideParticles;
    if (options.debug)
    {
        panels.toggles.debug = DebugLayers::All();
    }
    App app{window, session, panels};
    InstallCallbacks(window.Handle(), app);
    window.StartUi();

    const FrameOptions look;
    GlRenderer renderer;
    FrameScratch scratch;
    {
        const PixelRect view = app.View();
        session.ResetView(view.width, view.height);
    }

    using Clock = std::chrono::steady_clock;
    Clock::time_point last = Clock::now();
    Pacer pacer;
    // Without interaction only the last frames are drawn, so that ImGui's layout settles (HeadlessFramePlan).
    const int headlessFrames = headless ? HeadlessFrameCount(options.frames) : 0;
    for (int frame = 1; headless ? frame <= headlessFrames : !window.ShouldClose(); ++frame)
    {
        const HeadlessFrame plan = headless ? HeadlessFramePlan(frame, options.frames) : HeadlessFrame{};
        if (headless && !plan.draw)
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
            headless ? (plan.step ? 1 : 0)
            : session.stepOnce
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
        const PixelRect view = WorldViewRect(width, height, !panels.hidden);
        session.Resize(view.width, view.height);
        glViewport(0, 0, width, height);
        const Color& background = look.style.background;
        glClearColor(background.r, background.g, background.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glViewport(view.x, height - view.y - view.height, view.width, view.height);
        DrawWorld(session, renderer, panels.toggles, look, scratch);
        DrawListText(scratch.list, ImVec2(static_cast<float>(view.x), static_cast<float>(view.y)));
        if (!panels.hidden)
        {
            DrawPanels(session, panels, width, height, kPanelWidth);
        }
        window.RenderUi();
        if (headless && frame == headlessFrames && !options.screenshot.empty())
        {
            SaveScreenshot(width, height, options.screenshot);
        }
        window.Present();
    }
    return 0;
}

} // namespace cfx::testbed
