// contactfx: the command line.
//
//   contactfx demo      the tutorial scene, driven by a script, headless
//   contactfx run       any RUBE scene with effects
//   contactfx preset    a built-in effects configuration as JSON
//   contactfx validate  every problem of scenes and effects configs
//   contactfx bench     time the particles (pool against a body per particle) and the effects layer
//
// Exit code 0 on success, 1 on any error (one line per problem on stderr, naming file and field).
#include "bench_command.h"
#include "cli_common.h"
#include "preset_command.h"
#include "render_command.h"
#include "run_command.h"
#include "validate_command.h"

#include <CLI/CLI.hpp>
#include <iostream>

int main(int argc, char** argv)
{
    CLI::App app{"contactfx: physically driven particle effects from Box2D contacts"};
    app.require_subcommand(1);
    int result = cfx::cli::kExitOk;
    cfx::cli::RegisterRunCommands(app, result);
    cfx::cli::RegisterBenchCommand(app, result);
    cfx::cli::RegisterPresetCommand(app, result);
    cfx::cli::RegisterRenderCommand(app, result);
    cfx::cli::RegisterValidateCommand(app, result);
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::CallForHelp& help)
    {
        return app.exit(help);
    }
    catch (const CLI::CallForAllHelp& help)
    {
        return app.exit(help);
    }
    catch (const CLI::ParseError& error)
    {
        std::cerr << "contactfx: error: " << error.what() << '\n';
        return cfx::cli::kExitError;
    }
    return result;
}
