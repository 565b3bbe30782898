// contactfx-testbed: the command line.
//
//   contactfx-testbed [--scene NAME] [--effects FX.json] [--frames N [--screenshot FILE]] [--hide-particles]
//                     [--debug]
//   contactfx-testbed --version        prints "contactfx-testbed VERSION" and exits 0 (main.cpp)
//
// Without --frames the testbed is interactive until its window closes. With --frames it runs N frames of
// one simulation step each without waiting for input, saves the last one as PNG when --screenshot is
// given, and exits 0. Bad flags are found before any window opens.
#pragma once

#include <string>

namespace cfx::testbed
{

struct Options
{
    std::string scene = "tutorial"; ///< a registered scene (scenes.h)
    std::string effects;            ///< effects config file replacing the scene's; empty: the scene's
    int frames = 0;                 ///< frames to run without interaction, >= 1 (main.cpp); 0: interactive
    std::string screenshot;         ///< PNG of the last frame; needs frames
    bool hideParticles = false;     ///< draw the scene without its particles
    bool debug = false;             ///< start with every debug layer on (DebugLayers::All)
};

/// Throws InputError (file "<command line>", the flag as path) for an unknown scene, a screenshot without
/// frames or one OutputFileProblem (contactfx/files) refuses (a folder, a device, a read-only file, a missing
/// or unwritable folder), one that is the effects file (the same name, or the same file through a symbolic or
/// hard link: "is the input file ... not overwritten"), or a name not ending in .png. Empty names are "not
/// given" here (explicitly empty ones are refused while parsing: harness/parse_errors.h, NamesAFile).
void CheckOptions(const Options& options, bool framesGiven);

} // namespace cfx::testbed
