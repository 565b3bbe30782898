// contactfx example: drive the tutorial's car and draw its effects with SDL2.
//
// This is the file to read when putting contactfx into your own engine. It shows the whole loop:
//   1. load a RUBE scene (contactfx::scene) and give its fixtures their materials,
//   2. create one cfx::Effects for the world,
//   3. each fixed step: apply the player's input, world.Step(dt), fx.Step(dt) with the same dt,
//   4. each frame: draw the bodies, then the particles of fx.Particles() with the looks the config gives
//      each particle type (cfx::LookAt), in one batched SDL_RenderGeometry call.
// Nothing here is SDL-specific except the drawing calls: an engine with its own sprite batcher replaces
// DrawParticles and keeps the rest.
//
// Usage: contactfx-example-sdl2 [SCENE.json] [--frames N] [--screenshot FILE.bmp]
//   keys: a / d drive left / right, s brake, 4 toggles four-wheel drive, f toggles the camera following
//   the car, r reloads the scene, mouse wheel zooms, F12 saves a screenshot (--screenshot FILE, else
//   contactfx-sdl2.bmp), Esc quits.
//   --frames N runs N frames with a scripted drive instead of the keyboard, one fixed step a frame, saves
//   the last frame to --screenshot FILE if given, prints what was emitted and exits non-zero when no
//   particle was ever alive (for CI: SDL_VIDEODRIVER=dummy needs no display).
#define SDL_MAIN_HANDLED // we call SDL_SetMainReady ourselves: no SDL2main library needed
#include <SDL.h>
#include <algorithm>
#include <array>
#include <box2d/box2d.h>
#include <cctype>
#include <cmath>
#include <contactfx/effects.h>
#include <contactfx/error.h>
#include <contactfx/particle_system.h>
#include <contactfx/particle_types.h>
#include <contactfx/presets.h>
#include <contactfx/scene/rube.h>
#include <contactfx/scene/scene_materials.h>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#ifndef CONTACTFX_EXAMPLE_SCENE // set by CMake to the source tree's or the installed scene
#define CONTACTFX_EXAMPLE_SCENE "scenes/physics_driven_particles.json"
#endif

namespace
{

// ---------------------------------------------------------------------------------------------------
// Driving: the tutorial's controls, written against the scene's named bodies and joints.

/// The tutorial's motor speed: 1600 degrees per second, in rad/s.
constexpr float kMotorSpeed = 1600.0f * b2_pi / 180.0f;

/// What the player asks for this step.
struct DriveInput
{
    int direction = 0;  ///< +1 drive right (d), -1 drive left (a), 0 roll freely
    bool brake = false; ///< s: both motors hold their wheels still
    bool fourWheelDrive = false;
};

/// The car of the tutorial scene: body "car", wheel joints "suspension_rear" and "suspension_front"
/// (car -> wheel, motors limited to the scene's max motor torque).
struct Car
{
    b2Body* body = nullptr;
    b2WheelJoint* rear = nullptr;
    b2WheelJoint* front = nullptr;

    /// Throws cfx::InputError naming `file` (the scene's) when the scene has no such car.
    static Car Find(const cfx::Scene& scene, const std::string& file)
    {
        auto wheelJoint = [&](const char* name)
        {
            const cfx::SceneJoint* joint = scene.FindJoint(name);
            if (joint == nullptr || joint->joint->GetType() != e_wheelJoint)
            {
                throw cfx::InputError(file, "joint",
                                      std::string("no wheel joint named \"") + name +
                                          "\": this example drives the tutorial's car");
            }
            return static_cast<b2WheelJoint*>(joint->joint);
        };
        const cfx::SceneBody* car = scene.FindBody("car");
        if (car == nullptr)
        {
            throw cfx::InputError(file, "body",
                                  "no body named \"car\": this example drives the tutorial's car");
        }
        return Car{car->body, wheelJoint("suspension_rear"), wheelJoint("suspension_front")};
    }

    /// Rear-wheel drive (both wheels with 4WD) at the tutorial's speed; braking holds both wheels; no
    /// input switches the motors off so the car rolls freely.
    void Apply(const DriveInput& input) const
    {
        if (input.brake)
        {
            SetMotor(rear, true, 0.0f);
            SetMotor(front, true, 0.0f);
            return;
        }
        const bool driving = input.direction != 0;
        const float speed = -static_cast<float>(input.direction) * kMotorSpeed; // right = clockwise
        SetMotor(rear, driving, speed);
        SetMotor(front, driving && input.fourWheelDrive, speed);
        if (driving)
        {
            body->SetAwake(true); // a sleeping car would ignore its motors
        }
    }

private:
    static void SetMotor(b2WheelJoint* joint, bool on, float speed)
    {
        joint->EnableMotor(on);
        joint->SetMotorSpeed(speed);
    }
};

/// The drive --frames uses instead of the keyboard (the tutorial drive of `contactfx demo`): launch with
/// wheelspin in 4WD (smoke), full reverse at speed so the tyres skid (smoke), forward over the bump where
/// the car tips onto its body and grinds on the concrete (sparks), rocking on the dirt hills (dirt), then
/// rolling freely. The world is deterministic: the same drive does the same thing every time.
DriveInput ScriptedInput(float time)
{
    struct Segment
    {
        float until; // s
        DriveInput input;
    };
    static constexpr std::array kScript{
        Segment{4.07f, DriveInput{+1, false, true}},   Segment{7.16f, DriveInput{-1, false, false}},
        Segment{11.26f, DriveInput{+1, false, false}}, Segment{15.59f, DriveInput{-1, false, false}},
        Segment{17.12f, DriveInput{+1, false, false}}, Segment{18.33f, DriveInput{+1, false, true}},
    };
    for (const Segment& segment : kScript)
    {
        if (time < segment.until)
        {
            return segment.input;
        }
    }
    return DriveInput{};
}

// ---------------------------------------------------------------------------------------------------
// One load of the scene. Members are destroyed in reverse order, so the Effects object goes before the
// world it watches (the contract of cfx::Effects). Not movable (Effects is not): held by unique_ptr.

struct Session
{
    cfx::Scene scene;
    cfx::Effects fx;
    Car car;

    explicit Session(const std::string& path)
        : scene(cfx::LoadRubeFile(path)), fx(*scene.world, cfx::EffectsDef{cfx::DefaultPreset()}),
          car(Car::Find(scene, path))
    {
        // The scene's fixtures carry a `material` custom property; plain RUBE scenes get the config's
        // assignment rules instead.
        cfx::AssignSceneMaterials(scene, fx, path);
    }
};

// ---------------------------------------------------------------------------------------------------
// Drawing.

/// World (m, y up) to screen (px, y down).
struct Camera
{
    b2Vec2 center{0.0f, 0.0f};    ///< m, world point at the middle of the screen
    float pixelsPerMetre = 40.0f; ///< > 0
    float width = 1280.0f;        ///< px
    float height = 720.0f;        ///< px

    SDL_FPoint ToScreen(b2Vec2 point) const
    {
        return SDL_FPoint{0.5f * width + (point.x - center.x) * pixelsPerMetre,
                          0.5f * height - (point.y - center.y) * pixelsPerMetre};
    }
};

Uint8 ToByte(float channel)
{
    return static_cast<Uint8>(std::clamp(channel, 0.0f, 1.0f) * 255.0f + 0.5f);
}

SDL_Color ToSdl(const cfx::Color& color)
{
    return SDL_Color{ToByte(color.r), ToByte(color.g), ToByte(color.b), ToByte(color.a)};
}

/// A fixture's colour from its material (the tutorial's colours); light blue for no material.
SDL_Color MaterialColor(const cfx::Effects& fx, const b2Fixture* fixture)
{
    const cfx::MaterialId material = fx.Material(fixture);
    const std::string_view name =
        material.IsValid() ? std::string_view(fx.Config().materials[material.index]) : std::string_view();
    if (name == "steel")
    {
        return SDL_Color{230, 60, 50, 255};
    }
    if (name == "rubber")
    {
        return SDL_Color{150, 150, 150, 255};
    }
    if (name == "concrete")
    {
        return SDL_Color{230, 230, 230, 255};
    }
    if (name == "dirt")
    {
        return SDL_Color{255, 153, 102, 255};
    }
    return SDL_Color{120, 170, 255, 255};
}

/// Fills the convex outline `points` (a triangle fan) darker than `color` and strokes it in `color`.
void DrawFilledOutline(SDL_Renderer* renderer, std::vector<SDL_FPoint>& points, SDL_Color color,
                       std::vector<SDL_Vertex>& scratch)
{
    const SDL_Color fill{static_cast<Uint8>(color.r * 2 / 5), static_cast<Uint8>(color.g * 2 / 5),
                         static_cast<Uint8>(color.b * 2 / 5), 255};
    scratch.clear();
    for (std::size_t i = 1; i + 1 < points.size(); ++i)
    {
        for (const SDL_FPoint& corner : {points[0], points[i], points[i + 1]})
        {
            scratch.push_back(SDL_Vertex{corner, fill, SDL_FPoint{0.0f, 0.0f}});
        }
    }
    SDL_RenderGeometry(renderer, nullptr, scratch.data(), static_cast<int>(scratch.size()), nullptr, 0);
    points.push_back(points[0]); // close the outline
    SDL_SetRenderDrawColor(renderer, color.r, color.g, color.b, color.a);
    SDL_RenderDrawLinesF(renderer, points.data(), static_cast<int>(points.size()));
}

/// Every fixture of the world: polygons and circles filled with an outline, edges and chains as lines.
/// (b2World::DebugDraw with a b2Draw implementation is the other way; this one is shorter to read.)
void DrawBodies(SDL_Renderer* renderer, const b2World& world, const cfx::Effects& fx, const Camera& camera)
{
    std::vector<SDL_FPoint> points;
    std::vector<SDL_Vertex> scratch;
    for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
    {
        const b2Transform& transform = body->GetTransform();
        for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr;
             fixture = fixture->GetNext())
        {
            const SDL_Color color = MaterialColor(fx, fixture);
            points.clear();
            switch (fixture->GetType())
            {
            case b2Shape::e_polygon:
            {
                const auto* polygon = static_cast<const b2PolygonShape*>(fixture->GetShape());
                for (int i = 0; i < polygon->m_count; ++i)
                {
                    points.push_back(camera.ToScreen(b2Mul(transform, polygon->m_vertices[i])));
                }
                DrawFilledOutline(renderer, points, color, scratch);
                break;
            }
            case b2Shape::e_circle:
            {
                const auto* circle = static_cast<const b2CircleShape*>(fixture->GetShape());
                const b2Vec2 center = b2Mul(transform, circle->m_p);
                constexpr int kSegments = 24;
                for (int i = 0; i < kSegments; ++i)
                {
                    const float angle = 2.0f * b2_pi * static_cast<float>(i) / kSegments;
                    points.push_back(camera.ToScreen(center + circle->m_radius *
                                                                  b2Vec2(std::cos(angle), std::sin(angle))));
                }
                DrawFilledOutline(renderer, points, color, scratch);
                // A spoke, so that a spinning wheel looks like one.
                const SDL_FPoint hub = camera.ToScreen(center);
                const SDL_FPoint rim = camera.ToScreen(center + circle->m_radius * transform.q.GetXAxis());
                SDL_RenderDrawLineF(renderer, hub.x, hub.y, rim.x, rim.y);
                break;
            }
            case b2Shape::e_edge:
            {
                const auto* edge = static_cast<const b2EdgeShape*>(fixture->GetShape());
                const SDL_FPoint a = camera.ToScreen(b2Mul(transform, edge->m_vertex1));
                const SDL_FPoint b = camera.ToScreen(b2Mul(transform, edge->m_vertex2));
                SDL_SetRenderDrawColor(renderer, color.r, color.g, color.b, color.a);
                SDL_RenderDrawLineF(renderer, a.x, a.y, b.x, b.y);
                break;
            }
            case b2Shape::e_chain:
            {
                const auto* chain = static_cast<const b2ChainShape*>(fixture->GetShape());
                for (int i = 0; i < chain->m_count; ++i)
                {
                    points.push_back(camera.ToScreen(b2Mul(transform, chain->m_vertices[i])));
                }
                SDL_SetRenderDrawColor(renderer, color.r, color.g, color.b, color.a);
                SDL_RenderDrawLinesF(renderer, points.data(), static_cast<int>(points.size()));
                break;
            }
            case b2Shape::e_typeCount:
                break;
            }
        }
    }
}

/// A 32 x 32 white dot whose alpha falls off from the centre: every particle is this texture tinted
/// with its colour (SDL multiplies the texture by the vertex colour).
SDL_Texture* CreateSoftDot(SDL_Renderer* renderer)
{
    constexpr int kSize = 32;
    SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormat(0, kSize, kSize, 32, SDL_PIXELFORMAT_ARGB8888);
    if (surface == nullptr)
    {
        return nullptr;
    }
    for (int y = 0; y < kSize; ++y)
    {
        auto* row = reinterpret_cast<Uint32*>(static_cast<Uint8*>(surface->pixels) + y * surface->pitch);
        for (int x = 0; x < kSize; ++x)
        {
            const float dx = (static_cast<float>(x) + 0.5f) / kSize * 2.0f - 1.0f;
            const float dy = (static_cast<float>(y) + 0.5f) / kSize * 2.0f - 1.0f;
            const float falloff = std::clamp(1.0f - std::sqrt(dx * dx + dy * dy), 0.0f, 1.0f);
            const Uint32 alpha = ToByte(std::min(1.0f, 1.6f * falloff));
            row[x] = (alpha << 24) | 0x00FFFFFFu;
        }
    }
    SDL_Texture* texture = SDL_CreateTextureFromSurface(renderer, surface);
    SDL_FreeSurface(surface);
    if (texture != nullptr)
    {
        SDL_SetTextureBlendMode(texture, SDL_BLENDMODE_BLEND);
    }
    return texture;
}

/// The live particles as one batch of textured quads. ParticleView is structure-of-arrays: particle i
/// (0 <= i < count, oldest first) lives at slot view.Slot(i) of every array. Its looks are not stored:
/// cfx::LookAt gives the colour (alpha already follows life) and size (m) of its type at its life.
/// Types with a streak (sparks) are stretched along their velocity over `streak` seconds of motion.
void DrawParticles(SDL_Renderer* renderer, SDL_Texture* dot, const cfx::Effects& fx, const Camera& camera,
                   std::vector<SDL_Vertex>& vertices, std::vector<int>& indices)
{
    const cfx::ParticleView view = fx.Particles();
    const std::vector<cfx::ParticleTypeDef>& types = fx.Config().particleTypes;
    vertices.clear();
    indices.clear();
    for (std::uint32_t i = 0; i < view.count; ++i)
    {
        const std::uint32_t slot = view.Slot(i);
        const cfx::ParticleTypeDef& type = types[view.type[slot]];
        const cfx::ParticleLook look = cfx::LookAt(type, view.life[slot]);
        const SDL_Color color = ToSdl(look.color);
        const b2Vec2 position(view.positionX[slot], view.positionY[slot]); // m
        const b2Vec2 velocity(view.velocityX[slot], view.velocityY[slot]); // m/s

        const float halfSize = std::max(1.5f, 0.5f * look.size * camera.pixelsPerMetre); // px
        const SDL_FPoint head = camera.ToScreen(position);
        const SDL_FPoint tail = camera.ToScreen(position - type.streak * velocity);
        // The quad's axis: along the streak, or any axis for a round point.
        float axisX = head.x - tail.x, axisY = head.y - tail.y;
        const float length = std::sqrt(axisX * axisX + axisY * axisY);
        if (length > 0.5f)
        {
            axisX /= length;
            axisY /= length;
        }
        else
        {
            axisX = 1.0f;
            axisY = 0.0f;
        }
        const float alongX = axisX * halfSize, alongY = axisY * halfSize;    // half a size along the axis
        const float acrossX = -axisY * halfSize, acrossY = axisX * halfSize; // and across it
        const SDL_FPoint back{tail.x - alongX, tail.y - alongY};
        const SDL_FPoint front{head.x + alongX, head.y + alongY};
        const int first = static_cast<int>(vertices.size());
        vertices.push_back({{back.x - acrossX, back.y - acrossY}, color, {0.0f, 0.0f}});
        vertices.push_back({{front.x - acrossX, front.y - acrossY}, color, {1.0f, 0.0f}});
        vertices.push_back({{front.x + acrossX, front.y + acrossY}, color, {1.0f, 1.0f}});
        vertices.push_back({{back.x + acrossX, back.y + acrossY}, color, {0.0f, 1.0f}});
        for (const int corner : {0, 1, 2, 0, 2, 3})
        {
            indices.push_back(first + corner);
        }
    }
    if (!indices.empty())
    {
        SDL_RenderGeometry(renderer, dot, vertices.data(), static_cast<int>(vertices.size()), indices.data(),
                           static_cast<int>(indices.size()));
    }
}

/// Saves what the renderer has drawn so far (call before SDL_RenderPresent) as a BMP.
bool SaveScreenshot(SDL_Renderer* renderer, const std::string& file)
{
    int width = 0, height = 0;
    SDL_GetRendererOutputSize(renderer, &width, &height);
    SDL_Surface* surface = SDL_CreateRGBSurfaceWithFormat(0, width, height, 32, SDL_PIXELFORMAT_ARGB8888);
    bool saved = surface != nullptr &&
                 SDL_RenderReadPixels(renderer, nullptr, SDL_PIXELFORMAT_ARGB8888, surface->pixels,
                                      surface->pitch) == 0 &&
                 SDL_SaveBMP(surface, file.c_str()) == 0;
    SDL_FreeSurface(surface);
    if (!saved)
    {
        std::fprintf(stderr, "cannot save %s: %s\n", file.c_str(), SDL_GetError());
    }
    return saved;
}

// ---------------------------------------------------------------------------------------------------

struct Options
{
    std::string scene = CONTACTFX_EXAMPLE_SCENE;
    int frames = 0; ///< > 0: run this many frames with the scripted drive, then exit
    std::string screenshot;
};

bool ParseOptions(int argc, char** argv, Options& options)
{
    bool sceneGiven = false;
    for (int i = 1; i < argc; ++i)
    {
        const std::string arg = argv[i];
        if (arg == "--frames" && i + 1 < argc)
        {
            options.frames = std::atoi(argv[++i]);
            if (options.frames <= 0)
            {
                return false;
            }
        }
        else if (arg == "--screenshot" && i + 1 < argc)
        {
            // SDL_SaveBMP writes BMP whatever the name says.
            options.screenshot = argv[++i];
            const std::size_t dot = options.screenshot.rfind('.');
            std::string extension = dot == std::string::npos ? "" : options.screenshot.substr(dot);
            std::transform(extension.begin(), extension.end(), extension.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            if (extension != ".bmp")
            {
                std::fprintf(stderr, "--screenshot: expected a .bmp file, found \"%s\"\n",
                             options.screenshot.c_str());
                return false;
            }
        }
        else if (!arg.empty() && arg[0] != '-' && !sceneGiven) // one scene
        {
            options.scene = arg;
            sceneGiven = true;
        }
        else
        {
            return false;
        }
    }
    return true;
}

int Run(const Options& options, SDL_Window* window, SDL_Renderer* renderer)
{
    auto session = std::make_unique<Session>(options.scene);
    const float dt = 1.0f / session->scene.settings.stepsPerSecond; // s, fixed physics step
    const int velocityIterations = session->scene.settings.velocityIterations;
    const int positionIterations = session->scene.settings.positionIterations;
    const bool scripted = options.frames > 0;

    SDL_Texture* dot = CreateSoftDot(renderer);
    if (dot == nullptr)
    {
        std::fprintf(stderr, "cannot create the particle texture: %s\n", SDL_GetError());
        return 1;
    }
    std::vector<SDL_Vertex> vertices;
    std::vector<int> indices;

    Camera camera;
    bool followCar = true;
    bool fourWheelDrive = false;
    bool screenshotRequested = false;
    bool screenshotSaved = true; // the last screenshot asked for was saved
    const std::string screenshotFile = options.screenshot.empty() ? "contactfx-sdl2.bmp" : options.screenshot;
    float simulatedTime = 0.0f; // s since the scene was loaded
    double lag = 0.0;           // s of real time not yet simulated
    std::uint32_t mostAlive = 0;
    const Uint64 frequency = SDL_GetPerformanceFrequency();
    Uint64 start = SDL_GetPerformanceCounter(); // of the run since the scene was (re)loaded
    Uint64 previous = start;
    Uint64 lastTitle = 0;

    int frame = 0;
    for (bool running = true; running; ++frame)
    {
        SDL_Event event;
        while (SDL_PollEvent(&event))
        {
            if (event.type == SDL_QUIT)
            {
                running = false;
            }
            else if (event.type == SDL_MOUSEWHEEL)
            {
                camera.pixelsPerMetre = std::clamp(
                    camera.pixelsPerMetre * std::pow(1.15f, static_cast<float>(event.wheel.y)), 2.0f, 400.0f);
            }
            else if (event.type == SDL_KEYDOWN && event.key.keysym.sym == SDLK_ESCAPE)
            {
                running = false;
            }
            else if (event.type == SDL_KEYDOWN && event.key.repeat == 0 && !scripted)
            {
                switch (event.key.keysym.sym)
                {
                case SDLK_4:
                    fourWheelDrive = !fourWheelDrive;
                    break;
                case SDLK_f:
                    followCar = !followCar;
                    break;
                case SDLK_r: // reload; a file that no longer loads leaves the running scene as it is
                    try
                    {
                        std::unique_ptr<Session> reloaded = std::make_unique<Session>(options.scene);
                        session = std::move(reloaded); // the old Effects goes with its world
                        simulatedTime = 0.0f;
                        // The summary at exit counts from here, as the new Effects' statistics do.
                        frame = -1; // the loop's increment makes it 0
                        mostAlive = 0;
                        start = SDL_GetPerformanceCounter();
                        std::printf("reloaded %s\n", options.scene.c_str());
                    }
                    catch (const std::exception& error)
                    {
                        std::fprintf(stderr, "%s\nnot reloaded: the scene keeps running\n", error.what());
                    }
                    break;
                case SDLK_F12: // saved below, once this frame is drawn
                    screenshotRequested = true;
                    break;
                default:
                    break;
                }
            }
        }

        // Fixed steps: one per frame when scripted (the same run every time), else as many as real
        // time asks for (at most 4 a frame, so that a slow frame cannot snowball).
        const Uint64 now = SDL_GetPerformanceCounter();
        lag += static_cast<double>(now - previous) / static_cast<double>(frequency);
        previous = now;
        int steps = scripted ? 1 : std::min(4, static_cast<int>(lag / dt));
        lag = scripted ? 0.0 : std::min(lag - steps * static_cast<double>(dt), static_cast<double>(dt));
        for (; steps > 0; --steps)
        {
            DriveInput input;
            if (scripted)
            {
                input = ScriptedInput(simulatedTime);
            }
            else
            {
                const Uint8* keys = SDL_GetKeyboardState(nullptr); // physical key positions
                input.direction = (keys[SDL_SCANCODE_D] ? 1 : 0) - (keys[SDL_SCANCODE_A] ? 1 : 0);
                input.brake = keys[SDL_SCANCODE_S] != 0;
                input.fourWheelDrive = fourWheelDrive;
            }
            session->car.Apply(input);
            session->scene.world->Step(dt, velocityIterations, positionIterations);
            session->fx.Step(dt); // right after the world step, with the same dt
            simulatedTime += dt;
        }
        mostAlive = std::max(mostAlive, session->fx.Particles().count);

        // Draw: bodies, then particles over them.
        int width = 0, height = 0;
        SDL_GetRendererOutputSize(renderer, &width, &height);
        camera.width = static_cast<float>(width);
        camera.height = static_cast<float>(height);
        if (followCar)
        {
            camera.center = session->car.body->GetPosition() + b2Vec2(0.0f, 2.0f);
        }
        SDL_SetRenderDrawColor(renderer, 24, 26, 32, 255);
        SDL_RenderClear(renderer);
        DrawBodies(renderer, *session->scene.world, session->fx, camera);
        DrawParticles(renderer, dot, session->fx, camera, vertices, indices);

        // The back buffer is undefined after SDL_RenderPresent: read it back before.
        const bool lastFrame = scripted && frame + 1 >= options.frames;
        if (screenshotRequested || (lastFrame && !options.screenshot.empty()))
        {
            screenshotSaved = SaveScreenshot(renderer, screenshotFile);
            screenshotRequested = false;
        }
        SDL_RenderPresent(renderer);

        if (now - lastTitle > frequency / 4) // the window title is our HUD
        {
            lastTitle = now;
            const std::string title =
                "contactfx SDL2 example | particles " + std::to_string(session->fx.Particles().count) +
                " | 4WD " + (fourWheelDrive ? "on" : "off") + " | follow " + (followCar ? "on" : "off") +
                " | a/d drive, s brake, 4 4WD, f follow, r reload, wheel zoom";
            SDL_SetWindowTitle(window, title.c_str());
        }
        if (lastFrame)
        {
            running = false;
        }
    }
    SDL_DestroyTexture(dot);

    const double seconds =
        static_cast<double>(SDL_GetPerformanceCounter() - start) / static_cast<double>(frequency);
    const cfx::EffectsStats& stats = session->fx.Stats();
    std::printf("%d frames, %llu steps (%.1f s simulated) in %.2f s (%.2f ms a frame)\n", frame,
                static_cast<unsigned long long>(stats.steps), stats.time, seconds, 1000.0 * seconds / frame);
    for (std::size_t type = 0; type < stats.spawnedByType.size(); ++type)
    {
        std::printf("  %-8s %llu emitted\n", session->fx.Config().particleTypes[type].name.c_str(),
                    static_cast<unsigned long long>(stats.spawnedByType[type]));
    }
    std::printf("most particles alive at once: %u\n", mostAlive);
    if (!screenshotSaved)
    {
        return 1;
    }
    if (scripted && mostAlive == 0) // the scripted drive always makes smoke: something is broken
    {
        std::fprintf(stderr, "no particle was ever alive\n");
        return 1;
    }
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    Options options;
    if (!ParseOptions(argc, argv, options))
    {
        std::fprintf(stderr, "usage: %s [SCENE.json] [--frames N] [--screenshot FILE.bmp]\n", argv[0]);
        return 2;
    }

    SDL_SetMainReady();
    if (SDL_Init(SDL_INIT_VIDEO) != 0)
    {
        std::fprintf(stderr, "SDL_Init: %s\n", SDL_GetError());
        return 1;
    }
    SDL_Window* window = SDL_CreateWindow("contactfx SDL2 example", SDL_WINDOWPOS_CENTERED,
                                          SDL_WINDOWPOS_CENTERED, 1280, 720, SDL_WINDOW_RESIZABLE);
    // The first renderer SDL offers (a GPU one when there is a GPU), else the software one (headless
    // under the offscreen or dummy video driver). Interactive runs wait for vsync; --frames runs as fast
    // as it can.
    const Uint32 vsync = options.frames > 0 ? 0 : SDL_RENDERER_PRESENTVSYNC;
    SDL_Renderer* renderer = window == nullptr ? nullptr : SDL_CreateRenderer(window, -1, vsync);
    if (window != nullptr && renderer == nullptr)
    {
        renderer = SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE | vsync);
    }
    if (renderer == nullptr)
    {
        std::fprintf(stderr, "cannot create a window and renderer: %s\n", SDL_GetError());
        SDL_Quit();
        return 1;
    }
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_BLEND);
    SDL_RendererInfo info;
    if (SDL_GetRendererInfo(renderer, &info) == 0)
    {
        std::printf("video driver %s, renderer %s\n", SDL_GetCurrentVideoDriver(), info.name);
    }

    int result = 1;
    try
    {
        result = Run(options, window, renderer);
    }
    catch (const cfx::InputError& error) // a bad scene file: every problem, with file and JSON path
    {
        for (const cfx::Diagnostic& diagnostic : error.Diagnostics())
        {
            std::fprintf(stderr, "%s\n", diagnostic.ToString().c_str());
        }
    }
    catch (const std::exception& error)
    {
        std::fprintf(stderr, "%s\n", error.what());
    }
    SDL_DestroyRenderer(renderer);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return result;
}
