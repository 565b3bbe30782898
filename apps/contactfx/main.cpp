// contactfx: the command line.
//
//   contactfx demo      the tutorial scene, driven by a script, headless
//   contactfx run       a registered scene (--scene NAME) or any RUBE scene file with effects
//   contactfx render    pictures of the same: one PNG, a PNG sequence or a video (with sound)
//   contactfx validate  every problem of scenes and effects configs
//   contactfx preset    a built-in effects configuration as JSON
//   contactfx bench     time the particles (pool against a body per particle) and the effects layer
//   contactfx help      the commands, or one command's options
//
// Exit code 0 on success (and for --help, --version and help), 1 on any error: one line per problem on
// stderr ("contactfx: error: ..."), naming file and field, or for a command line that is not understood
// the unknown command or option with the nearest valid one and a pointer at --help. A failed write of
// standard output (`> /dev/full`) is an error too.
#include "bench_command.h"
#include "cli_common.h"
#include "contactfx/version.h"
#include "help_command.h"
#include "outputs.h"
#include "preset_command.h"
#include "render_command.h"
#include "run_command.h"
#include "usage.h"
#include "validate_command.h"

#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>
#include <string>
#include <unistd.h>

namespace
{

constexpr const char* kFooter = R"(Examples:
  contactfx demo --seconds 20 --stats out/demo-stats.json
  contactfx run --scene grinder --events out/grinder.jsonl
  contactfx demo --seconds 20 --audio out/demo.wav --voices out/demo-voices.jsonl
  contactfx render --scene rockslide --out out/rockslide.mp4

'contactfx help COMMAND' (or 'contactfx COMMAND --help') shows the options of a command.)";

// `result`, or kExitError when standard output failed (FlushStandardOutput reports it).
int CheckStandardOutput(int result)
{
    return cfx::cli::FlushStandardOutput() ? result : cfx::cli::kExitError;
}

} // namespace

int main(int argc, char** argv)
{
    // A file size limit (ulimit -f) makes writes fail with EFBIG, reported naming the file, instead of
    // killing contactfx (and ffmpeg, which inherits this) with SIGXFSZ halfway through a file.
    std::signal(SIGXFSZ, SIG_IGN);
    // Printing into a pipe whose reader has gone (`contactfx run ... | head -1`) fails with EPIPE and is
    // reported as a failed write of standard output, leaving no output file, instead of killing contactfx
    // with SIGPIPE halfway with its temporary files left behind.
    std::signal(SIGPIPE, SIG_IGN);
    // Ctrl-C while the inputs are read (a FIFO, a huge file) stops with the usual message, not silently.
    cfx::cli::InstallInterruptHandlers();
    // Into a file or pipe, what a command prints goes out in 64 KiB pieces, most outputs in one at the end
    // (CheckStandardOutput), where a failed write still knows its reason; a terminal stays line-buffered.
    if (::isatty(STDOUT_FILENO) == 0)
    {
        static char buffer[1 << 16]; // glibc ignores the size without a buffer
        std::setvbuf(stdout, buffer, _IOFBF, sizeof buffer);
    }
    CLI::App app{"contactfx: physically driven particle effects from Box2D contacts", "contactfx"};
    app.set_version_flag("--version", std::string("contactfx ") + cfx::kVersion,
                         "Print the version and exit");
    app.require_subcommand(1);
    // "Commands" and COMMAND rather than CLI11's "Subcommands": commands inherit the group, and share
    // the formatter.
    app.group("Commands");
    app.get_formatter()->label("SUBCOMMAND", "COMMAND");
    int result = cfx::cli::kExitOk;
    // In the order the help lists them.
    cfx::cli::RegisterRunCommands(app, result);
    cfx::cli::RegisterRenderCommand(app, result);
    cfx::cli::RegisterValidateCommand(app, result);
    cfx::cli::RegisterPresetCommand(app, result);
    cfx::cli::RegisterBenchCommand(app, result);
    cfx::cli::RegisterHelpCommand(app, result);
    app.footer(kFooter); // after the commands, which would inherit it
    try
    {
        app.parse(argc, argv);
    }
    catch (const CLI::Success& helpOrVersion) // --help, --help-all, --version: on stdout, exit code 0
    {
        return CheckStandardOutput(app.exit(helpOrVersion));
    }
    catch (const CLI::ParseError& error)
    {
        return CheckStandardOutput(cfx::cli::ReportParseError(app, error));
    }
    return CheckStandardOutput(result);
}
