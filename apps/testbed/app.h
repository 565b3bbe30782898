// contactfx-testbed: the frame loop.
#pragma once

#include "options.h"

namespace cfx::testbed
{

/// Opens the window and runs the testbed: interactively until the window closes, or for
/// options.frames frames (then saves the screenshot, if asked). Returns the exit code; throws
/// InputError for bad input files and std::runtime_error when no window can be opened.
int RunTestbed(const Options& options);

} // namespace cfx::testbed
