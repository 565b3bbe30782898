// The scene and render components of an installed contactfx: loads a bundled scene from the installed
// share/contactfx/scenes, steps it with effects and draws one frame with Cairo.
#include <contactfx/effects.h>
#include <contactfx/presets.h>
#include <contactfx/render/cairo_renderer.h>
#include <contactfx/render/frame.h>
#include <contactfx/scene/rube.h>
#include <contactfx/scene/scene_materials.h>
#include <cstdio>

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::fprintf(stderr, "usage: consumer_components SCENE.json\n");
        return 2;
    }
    cfx::Scene scene = cfx::LoadRubeFile(argv[1]);
    cfx::Effects fx(*scene.world, cfx::EffectsDef{cfx::DefaultPreset()});
    cfx::AssignSceneMaterials(scene, fx, argv[1]);
    for (int step = 0; step < 60; ++step)
    {
        scene.world->Step(1.0f / 60.0f, 8, 3);
        fx.Step(1.0f / 60.0f);
    }
    cfx::render::CairoRenderer renderer(320, 180);
    cfx::Camera camera = cfx::MakeCamera(320, 180, 40.0f, b2Vec2(0.0f, 0.0f));
    cfx::FitWorld(camera, *scene.world);
    cfx::FrameScratch scratch;
    cfx::render::RenderFrame(fx, 1.0f, camera, cfx::FrameOptions{}, renderer, scratch);
    const std::string png = renderer.EncodePng();
    std::printf("%zu bodies, %u particles alive, a %zu-byte PNG\n", scene.bodies.size(), fx.Particles().count,
                png.size());
    return scene.bodies.empty() || png.size() < 100 ? 1 : 0;
}
