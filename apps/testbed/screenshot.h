// contactfx-testbed: saving what the window shows.
#pragma once

#include <filesystem>

namespace cfx::testbed
{

/// Reads the `width` x `height` pixels of the current OpenGL read buffer (call after drawing, before
/// swapping) and writes them as an opaque PNG (render::EncodePng), atomically (WriteTextFileAtomically):
/// the file is complete or absent. Throws InputError naming the path when it cannot be written (a
/// folder, a device, a read-only file).
void SaveScreenshot(int width, int height, const std::filesystem::path& path);

} // namespace cfx::testbed
