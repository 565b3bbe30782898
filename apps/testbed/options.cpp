#include "options.h"

#include "contactfx/error.h"
#include "harness/command_line.h"
#include "harness/scenes.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace cfx::testbed
{

namespace
{

/// The screenshot must not replace a file the testbed reads (the scene file, the effects config): refused as
/// the command line program refuses an output that is one of its inputs (apps/contactfx/outputs.cpp), also
/// when the two names are one file through a symbolic or hard link.
void CheckNotAnInput(const Options& options)
{
    for (const std::string* input : {&options.sceneFile, &options.effects})
    {
        if (SameFile(options.screenshot, *input))
        {
            throw InputError(kCommandLine, "--screenshot",
                             options.screenshot + ": is the input file \"" + *input +
                                 "\" of this command: not overwritten");
        }
    }
}

} // namespace

int HeadlessFrameCount(int frames)
{
    return std::max(frames, kHeadlessDrawnFrames);
}

HeadlessFrame HeadlessFramePlan(int frame, int frames)
{
    const int count = HeadlessFrameCount(frames);
    const int layoutOnly = count - frames; // drawn, not stepped: the first ones
    HeadlessFrame plan;
    plan.draw = frame > count - kHeadlessDrawnFrames;
    plan.step = frame > layoutOnly;
    return plan;
}

std::string_view SceneName(const Options& options)
{
    return options.scene.empty() ? std::string_view("tutorial") : std::string_view(options.scene);
}

void CheckOptions(const Options& options, bool framesGiven)
{
    if (!options.sceneFile.empty() && !options.scene.empty())
    {
        throw InputError(kCommandLine, "scene", "give either a scene file or --scene NAME, not both");
    }
    CheckNotASceneName(options.sceneFile);
    if (options.sceneFile.empty() && FindScene(SceneName(options)) == nullptr)
    {
        throw InputError(kCommandLine, "--scene",
                         "unknown scene \"" + options.scene + "\" (registered: " + SceneNames() + ")");
    }
    if (!options.screenshot.empty())
    {
        if (!framesGiven)
        {
            throw InputError(kCommandLine, "--screenshot", "needs --frames N (the frame to save)");
        }
        CheckOutputFile("--screenshot", options.screenshot);
        CheckNotAnInput(options);
        CheckExtension("--screenshot", options.screenshot, ".png");
    }
}

} // namespace cfx::testbed
