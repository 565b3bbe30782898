// contactfx render (SCENE.json | --scene NAME | --demo) --out FILE: the simulation as pictures.
//
// Frame k shows the simulation at time k / fps (after round(k / fps * hz) steps), so the same flags
// give the same pixels, and a single PNG at --time T is the frame a video would show at T. Everything
// that can be checked is checked before the simulation runs: flags, the output's kind, every output
// file (outputs.h: folder, kind of file, not an input), and that ffmpeg and ffprobe are there for a
// video. An .mp4 gets the run's sound as its audio track (sound_output.h; muxed in by a second ffmpeg pass,
// audio_mux.h), and --audio writes that sound as a WAV for any output; the audio covers what the pictures
// show (a video's frames / fps, a single frame's time). All outputs (the picture or every frame of a
// sequence, --stats, --audio) are written together at the end, or none are.
#include "render_command.h"

#include "audio_mux.h"
#include "cli_common.h"
#include "contactfx/error.h"
#include "contactfx/files/text_file.h"
#include "contactfx/render/frame.h"
#include "contactfx/render/frame_output.h"
#include "outputs.h"
#include "progress.h"
#include "quoted_text.h"
#include "scenario.h"
#include "sound_output.h"

#include <box2d/b2_body.h>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

namespace cfx::cli
{

namespace
{

struct RenderOptions
{
    RunOptions run;
    bool demo = false; ///< --demo: --scene tutorial
    std::string out;
    std::optional<double> time; ///< s; a single PNG of this moment
    int width = 1280;           ///< px
    int height = 720;           ///< px
    double fps = 30.0;
    std::string follow = "car";           ///< body the camera follows; empty or absent: the whole world
    bool followGiven = false;             ///< --follow was on the command line (a name it lacks is a typo)
    double view = 14.0;                   ///< m across the picture when following
    bool debug = false;                   ///< --debug: every debug layer
    std::vector<std::string> debugLayers; ///< --debug-layers: some of them (kDebugLayerNames)
    bool scaleBar = false;
};

// The names --debug-layers takes, each with the layer it switches on.
struct DebugLayerName
{
    const char* name;
    bool DebugLayers::*layer;
};
constexpr DebugLayerName kDebugLayerNames[] = {
    {"points", &DebugLayers::manifoldPoints}, {"normals", &DebugLayers::normals},
    {"impulses", &DebugLayers::impulses},     {"rules", &DebugLayers::ruleNames},
    {"velocities", &DebugLayers::velocities},
};

DebugLayers SelectedDebugLayers(const RenderOptions& options, float stepTime)
{
    DebugLayers layers = options.debug ? DebugLayers::All() : DebugLayers{};
    for (const std::string& wanted : options.debugLayers)
    {
        for (const DebugLayerName& entry : kDebugLayerNames)
        {
            if (wanted == entry.name)
            {
                layers.*entry.layer = true;
            }
        }
    }
    layers.stepTime = stepTime;
    return layers;
}

constexpr int kMaxSide = 8192;
// A GIF frame's delay is a whole number of hundredths of a second, and players show a delay below 2 as 10.
constexpr double kMaxGifFps = 50.0;

[[noreturn]] void Refuse(const std::string& flag, const std::string& message)
{
    throw InputError(kCommandLine, flag, message);
}

// What --out names: the kind of picture, or the problem that keeps it from being written (reported with
// the other outputs' problems, Render).
struct RenderTarget
{
    render::OutputKind kind = render::OutputKind::png;
    std::optional<Diagnostic> problem;
};

RenderTarget CheckRenderOptions(const RenderOptions& options)
{
    CheckRunOptions(options.run);
    if (!std::isfinite(options.fps) || options.fps <= 0.0 || options.fps > 240.0)
    {
        Refuse("--fps", "expected a number in (0, 240], found " + NumberText(options.fps));
    }
    if (!std::isfinite(options.view) || options.view <= 0.0 || options.view > 1e6)
    {
        Refuse("--view", "expected metres in (0, 1e6], found " + NumberText(options.view));
    }
    // What the target is comes before what its name says (`--out /dev/full` is a device). Either problem
    // is reported with the other outputs' (Render), and the checks below take the target as one .png.
    RenderTarget target;
    if (const std::string problem = OutputFileProblem(options.out); !problem.empty())
    {
        target.problem = Diagnostic{options.out, "--out", problem};
    }
    else
    {
        try
        {
            target.kind = render::ClassifyOutput(options.out);
        }
        catch (const std::invalid_argument& error)
        {
            target.problem = Diagnostic{kCommandLine, "--out", error.what()};
        }
    }
    const render::OutputKind kind = target.kind;
    if (options.time)
    {
        if (!std::isfinite(*options.time) || *options.time < 0.0 || *options.time > 86400.0)
        {
            Refuse("--time", "expected a number in [0, 86400], found " + NumberText(*options.time));
        }
        if (kind != render::OutputKind::png)
        {
            Refuse("--time", "only for one frame (--out FILE.png); a sequence or video covers --seconds");
        }
    }
    if (kind == render::OutputKind::gif && options.fps > kMaxGifFps)
    {
        Refuse("--fps", "a .gif plays at most 50 frames a second (its frame delays are whole hundredths of a "
                        "second, and players slow shorter ones down), found " +
                            NumberText(options.fps));
    }
    if (kind == render::OutputKind::mp4 && (options.width % 2 != 0 || options.height % 2 != 0))
    {
        Refuse(options.width % 2 != 0 ? "--width" : "--height",
               "an .mp4 needs an even width and height, found " + std::to_string(options.width) + "x" +
                   std::to_string(options.height));
    }
    if (kind == render::OutputKind::mp4 || kind == render::OutputKind::gif)
    {
        if (render::FindProgram("ffmpeg").empty())
        {
            throw std::runtime_error("ffmpeg not found: install ffmpeg to write .mp4/.gif");
        }
        if (render::FindProgram("ffprobe").empty())
        {
            throw std::runtime_error("ffprobe not found: install ffmpeg (with ffprobe) to write .mp4/.gif");
        }
    }
    return target;
}

int Render(RenderOptions options)
{
    if (options.demo)
    {
        if (!options.run.scene.empty() || !options.run.sceneName.empty())
        {
            Refuse("--demo", "give a scene file, --scene NAME or --demo, not two of them");
        }
        options.run.sceneName = "tutorial";
    }
    const RenderTarget target = CheckRenderOptions(options);
    const render::OutputKind kind = target.kind;
    const Scenario scenario = SelectScenario(options.run);
    const SimulationDef& def = scenario.def;

    const bool single = kind == render::OutputKind::png;
    const bool video = kind == render::OutputKind::mp4 || kind == render::OutputKind::gif;
    const double firstTime = single ? options.time.value_or(options.run.seconds) : 0.0;
    const auto frames =
        single ? 1LL : std::max(1LL, static_cast<long long>(std::llround(options.run.seconds * options.fps)));

    // Every file is checked before anything is simulated, and all are written at the end or none.
    OutputFiles outputs;
    AddScenarioInputs(outputs, options.run, scenario);
    std::vector<OutputFiles::Handle> pictures; // one per PNG frame; one video
    if (target.problem)
    {
        outputs.Refuse(*target.problem); // once, not once per frame of a sequence
    }
    else if (kind == render::OutputKind::pngSequence)
    {
        for (long long k = 0; k < frames; ++k)
        {
            pictures.push_back(outputs.Add("--out", render::SequenceFile(options.out, k)));
        }
    }
    else
    {
        pictures.push_back(outputs.Add("--out", options.out));
    }
    std::optional<OutputFiles::Handle> stats;
    if (!options.run.stats.empty())
    {
        stats = outputs.Add("--stats", options.run.stats);
    }
    // The audio covers what the pictures show: up to the one frame's time, or the whole video.
    const bool mp4 = kind == render::OutputKind::mp4;
    const double audioEnd = single ? firstTime : static_cast<double>(frames) / options.fps;
    if (!options.run.audio.empty() || mp4)
    {
        CheckAudioSeconds(audioEnd, options.run.audio.empty() ? "--out" : "--audio");
    }
    SoundOutput sound(outputs, options.run.audio, "", mp4 ? std::filesystem::path(options.out) : "");
    std::optional<OutputFiles::Handle> muxed; // the video with its audio, before it replaces the video
    if (mp4)
    {
        muxed = outputs.AddScratch("--out", options.out + ".muxed.mp4");
    }
    outputs.Prepare();

    Simulation simulation(def);
    PrintSceneWarnings(simulation.GetScene(), options.run);
    sound.Start(simulation.GetEffects().Config(), def.seed);

    const b2Body* followed = nullptr;
    if (!options.follow.empty())
    {
        if (const SceneBody* body = simulation.GetScene().FindBody(options.follow))
        {
            followed = body->body;
        }
        else if (options.followGiven)
        {
            std::cerr << "contactfx: warning: --follow: the scene has no body named "
                      << detail::QuotedText(options.follow) << ": the whole world shows\n";
        }
    }
    Camera camera =
        MakeCamera(options.width, options.height, static_cast<float>(options.view), b2Vec2(0.0f, 0.0f));
    // The followed body sits a little below the middle: what flies up stays in view.
    const float lift = 0.2f * static_cast<float>(options.height) / camera.pixelsPerMetre;
    constexpr float kSmoothing = 0.5f; // s: the view eases up and down, never sideways
    if (followed != nullptr)
    {
        Follow(camera, *followed, lift);
    }
    else
    {
        FitWorld(camera, *simulation.GetScene().world);
    }

    render::CairoRenderer renderer(options.width, options.height);
    FrameOptions look;
    look.caption = (def.config.name.empty() ? std::string("custom") : def.config.name) + " effects";
    look.scaleBar = options.scaleBar;
    look.debug = SelectedDebugLayers(options, simulation.Dt());
    FrameScratch scratch;
    // ffmpeg writes into the video's temporary file; PNG frames go to theirs one by one.
    std::optional<render::VideoSink> sink;
    if (video)
    {
        sink.emplace(options.out, kind, options.width, options.height, options.fps,
                     outputs.Temporary(pictures.front()));
    }
    std::optional<Progress> progress;
    if (frames > 1)
    {
        progress.emplace("render " + options.out, static_cast<std::uint64_t>(frames), "frames");
    }
    for (long long k = 0; k < frames; ++k)
    {
        const double time = single ? firstTime : static_cast<double>(k) / options.fps;
        const auto steps = static_cast<std::uint64_t>(std::llround(time * options.run.hz));
        while (simulation.Steps() < steps)
        {
            scenario.Step(simulation);
            sound.AfterStep(simulation.GetEffects(), simulation.Dt());
            if (followed != nullptr)
            {
                FollowSmoothly(camera, *followed, lift, simulation.Dt(), kSmoothing);
            }
        }
        render::RenderFrame(simulation.GetEffects(), simulation.Time(), camera, look, renderer, scratch);
        outputs.CheckInterrupted();
        if (sink)
        {
            sink->Write(renderer);
        }
        else
        {
            outputs.Write(pictures[static_cast<std::size_t>(k)], renderer.EncodePng());
        }
        if (progress)
        {
            progress->Update(static_cast<std::uint64_t>(k + 1));
        }
    }
    if (sink)
    {
        sink->Finish(); // ffmpeg succeeded and ffprobe found every frame, or it throws
    }
    if (progress)
    {
        progress->Finish();
    }
    const StateHash runHash = simulation.RunHash();
    const double lastFrameTime = simulation.Time(); // what the frames and the stats cover
    if (stats)
    {
        outputs.Write(*stats, StatsJson(simulation.GetEffects(), def.hz, &runHash));
    }
    if (sound.Active())
    {
        // The last frame shows the moment it starts; its sound lasts one frame more (stats end at it).
        const auto audioSteps = static_cast<std::uint64_t>(std::llround(audioEnd * options.run.hz));
        while (simulation.Steps() < audioSteps)
        {
            scenario.Step(simulation);
            sound.AfterStep(simulation.GetEffects(), simulation.Dt());
        }
        sound.Finish(audioEnd);
    }
    if (muxed)
    {
        const std::filesystem::path& silentVideo = outputs.Temporary(pictures.front());
        MuxAudio(silentVideo, sound.WavFile(), outputs.Temporary(*muxed), options.out);
        std::filesystem::rename(outputs.Temporary(*muxed), silentVideo);
    }
    // The summary is printed and flushed before the outputs are committed, so that a failed write of
    // standard output leaves no output file either; it says what was rendered, not that it was written,
    // which a failing Commit() (an error of its own) would make untrue.
    std::printf("contactfx render: %s: %lld frame%s, %dx%d, %.2f s simulated\n", options.out.c_str(), frames,
                frames == 1 ? "" : "s", options.width, options.height, lastFrameTime);
    if (!FlushStandardOutput())
    {
        return kExitError;
    }
    outputs.Commit();
    return kExitOk;
}

} // namespace

void RegisterRenderCommand(CLI::App& app, int& result)
{
    auto options = std::make_shared<RenderOptions>();
    CLI::App* render = app.add_subcommand(
        "render",
        "Pictures of a scene with effects: one PNG (--time), a PNG sequence, or an .mp4/.gif video");
    AddSceneOptions(*render, options->run, "RUBE JSON scene (or --scene NAME, or --demo)");
    render->add_flag("--demo", options->demo, "The demo's scene: the same as --scene tutorial");
    render
        ->add_option(
            "--out", options->out,
            "FILE.png (one frame), DIR/frame_%04d.png (a sequence), FILE.mp4 (with a 48 kHz audio track) "
            "or FILE.gif (ffmpeg)")
        ->required()
        ->check(NamesAFile());
    AddRunOptions(*render, options->run, false);
    render
        ->add_option(
            "--audio", options->run.audio,
            "Also write the sound to this WAV file (48 kHz, 16-bit mono; an .mp4 gets it as its audio "
            "track anyway; docs/sound.md)")
        ->check(NamesAFile());
    render->add_option("--time", options->time, "Time of the one frame of a .png, s (default: --seconds)")
        ->check(DecimalNumber());
    render->add_option("--width", options->width, "Image width, px")
        ->transform(WholeNumberIn(2, kMaxSide))
        ->capture_default_str();
    render->add_option("--height", options->height, "Image height, px")
        ->transform(WholeNumberIn(2, kMaxSide))
        ->capture_default_str();
    render->add_option("--fps", options->fps, "Frames per second of a sequence or video")
        ->check(DecimalNumber())
        ->capture_default_str();
    render
        ->add_option(
            "--follow", options->follow,
            "Body (by name) the camera follows; when the scene has none, the whole world shows (with "
            "a warning when the name was given)")
        ->each([options](const std::string&) { options->followGiven = true; })
        ->capture_default_str();
    render->add_option("--view", options->view, "Metres shown across the picture when following a body")
        ->check(DecimalNumber())
        ->capture_default_str();
    render->add_flag("--scale-bar", options->scaleBar,
                     "Draw a scale bar of a round length in the bottom left corner");
    render->add_flag("--debug", options->debug,
                     "Draw every debug layer: contact points coloured by intensity (blue 0, green the rule's "
                     "threshold, red twice it, ringed above it), normals (cyan), normal impulses (magenta), "
                     "rule names, particle velocities");
    std::vector<std::string> layerNames;
    for (const DebugLayerName& entry : kDebugLayerNames)
    {
        layerNames.emplace_back(entry.name);
    }
    render
        ->add_option("--debug-layers", options->debugLayers,
                     "Some debug layers, comma-separated: points, normals, impulses, rules, velocities")
        ->delimiter(',')
        ->check(CLI::IsMember(layerNames));
    render->callback([render, options, &result]
                     { result = Guarded(*render, [&] { return Render(*options); }); });
}

} // namespace cfx::cli
