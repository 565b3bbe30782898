#include "options.h"

#include "contactfx/error.h"
#include "harness/command_line.h"
#include "harness/scenes.h"

namespace cfx::testbed
{

void CheckOptions(const Options& options, bool framesGiven)
{
    if (FindScene(options.scene) == nullptr)
    {
        throw InputError(kCommandLine, "--scene",
                         "unknown scene \"" + options.scene + "\" (registered: " + SceneNames() + ")");
    }
    if (framesGiven && options.frames < 1)
    {
        throw InputError(kCommandLine, "--frames",
                         "expected a whole number >= 1, found " + std::to_string(options.frames));
    }
    if (!options.screenshot.empty())
    {
        if (!framesGiven)
        {
            throw InputError(kCommandLine, "--screenshot", "needs --frames N (the frame to save)");
        }
        CheckOutputFile("--screenshot", options.screenshot);
        CheckExtension("--screenshot", options.screenshot, ".png");
    }
}

} // namespace cfx::testbed
