// contactfx-testbed: the command line.
//
//   contactfx-testbed [SCENE.json | --scene NAME] [--effects FX.json] [--frames N [--screenshot FILE]]
//   [--hide-particles]
//                     [--debug]
//   contactfx-testbed --version        prints "contactfx-testbed VERSION" and exits 0 (main.cpp)
//
// Without --frames the testbed is interactive until its window closes. With --frames it runs N frames of
// one simulation step each without waiting for input, saves the last one as PNG when --screenshot is
// given, and exits 0. Bad flags are found before any window opens.
#pragma once

#include <string>
#include <string_view>

namespace cfx::testbed
{

struct Options
{
    std::string sceneFile;  ///< a RUBE scene file, opened as it is (Session::OpenFile); empty: `scene`
    std::string scene;      ///< a registered scene (scenes.h); empty: "tutorial" unless sceneFile is given
    std::string effects;    ///< effects config file replacing the scene's; empty: the scene's
    int frames = 0;         ///< frames to run without interaction, >= 1 (main.cpp); 0: interactive
    std::string screenshot; ///< PNG of the last frame; needs frames
    bool hideParticles = false; ///< draw the scene without its particles
    bool debug = false;         ///< start with every debug layer on (DebugLayers::All)
};

/// The registered scene to open when no scene file is given: `scene`, else "tutorial".
std::string_view SceneName(const Options& options);

/// Throws InputError (file "<command line>", the flag as path) for both a scene file and --scene ("scene"),
/// an unknown scene, a screenshot without
/// frames or one OutputFileProblem (contactfx/files) refuses (a folder, a device, a read-only file, a missing
/// or unwritable folder), one that is the effects file (the same name, or the same file through a symbolic or
/// hard link: "is the input file ... not overwritten"), or a name not ending in .png. Empty names are "not
/// given" here (explicitly empty ones are refused while parsing: harness/parse_errors.h, NamesAFile).
void CheckOptions(const Options& options, bool framesGiven);

/// Frames drawn at the end of a run with --frames, so that ImGui's layout settles (its tables size their
/// columns from the frame before): the screenshot is of the last.
inline constexpr int kHeadlessDrawnFrames = 3;

/// What frame `frame` (1-based) of a run with --frames `frames` does. The run has
/// max(frames, kHeadlessDrawnFrames) frames: the last kHeadlessDrawnFrames are drawn, the others only
/// simulated; with fewer than kHeadlessDrawnFrames frames asked for, the first drawn ones lay the panels out
/// without stepping. So a run steps exactly `frames` times and its last frame is always the third drawn.
struct HeadlessFrame
{
    bool draw = false;
    bool step = false;
};
int HeadlessFrameCount(int frames);
HeadlessFrame HeadlessFramePlan(int frame, int frames);

} // namespace cfx::testbed
