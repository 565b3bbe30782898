// contactfx-testbed: look at contactfx's effects live, in the spirit of Box2D's testbed.
//
//   contactfx-testbed [SCENE.json | --scene NAME] [--effects FX.json] [--frames N [--screenshot FILE]]
//   contactfx-testbed --version
//
// Exit code 0 on success (and for --help and --version), 1 on any error (one line on stderr naming the
// flag or file: "contactfx-testbed: error: <command line>: --frames: ...").
#include "app.h"
#include "contactfx/error.h"
#include "contactfx/version.h"
#include "harness/parse_errors.h"
#include "harness/scenes.h"
#include "keys.h"
#include "options.h"

#include <CLI/CLI.hpp>
#include <iostream>
#include <limits>

namespace
{

constexpr int kExitError = 1;

int Fail(const std::string& message)
{
    std::cerr << "contactfx-testbed: error: " << message << '\n';
    return kExitError;
}

} // namespace

int main(int argc, char** argv)
{
    cfx::testbed::Options options;
    CLI::App app{"contactfx-testbed: contactfx's effects live (GLFW, OpenGL 3, Dear ImGui)"};
    app.add_option("scene", options.sceneFile,
                   "RUBE scene file to open as it is: no scripted drive, the whole world in view, the "
                   "default preset unless --effects")
        ->check(cfx::NamesAFile());
    app.add_option("--scene", options.scene,
                   "Registered scene to open instead (default tutorial): " + cfx::SceneNames());
    app.add_option("--effects", options.effects, "Effects config JSON replacing the scene's")
        ->check(cfx::NamesAFile());
    CLI::Option* frames = app.add_option("--frames", options.frames,
                                         "Run this many frames (one simulation step each) without "
                                         "interaction, drawing the last few, then exit")
                              ->transform(cfx::WholeNumberIn(1, std::numeric_limits<int>::max()));
    app.add_option("--screenshot", options.screenshot, "With --frames: save the last frame as PNG")
        ->check(cfx::NamesAFile());
    app.add_flag("--hide-particles", options.hideParticles, "Draw the scene without its particles");
    app.add_flag("--debug", options.debug,
                 "Start with every debug layer on: contact points by intensity, normals, normal impulses, "
                 "rule names, particle velocities");
    app.footer("Keys (Box2D's testbed where it has them):\n" + cfx::testbed::KeysHelp());
    app.set_version_flag("--version", std::string("contactfx-testbed ") + cfx::kVersion,
                         "Print the version and exit");
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::Success& helpOrVersion) // --help, --version: on stdout, exit code 0
    {
        return app.exit(helpOrVersion);
    }
    catch (const CLI::ParseError& error)
    {
        return Fail(cfx::DescribeParseError(app, error).ToString());
    }
    try
    {
        cfx::testbed::CheckOptions(options, frames->count() > 0);
        return cfx::testbed::RunTestbed(options);
    }
    catch (const cfx::InputError& error)
    {
        for (const cfx::Diagnostic& problem : error.Diagnostics())
        {
            std::cerr << "contactfx-testbed: error: " << problem.ToString() << '\n';
        }
    }
    catch (const std::exception& error)
    {
        return Fail(error.what());
    }
    return kExitError;
}
