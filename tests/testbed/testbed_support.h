// Running contactfx-testbed from tests, under Xvfb when it needs a display, and reading its PNGs.
#pragma once

#include "cli/cli_support.h"

#include <array>
#include <cairo.h>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

namespace cfx::test
{

inline std::string TestbedBinary()
{
    return std::string(CONTACTFX_BINARY_DIR) + "/bin/contactfx-testbed";
}

/// `contactfx-testbed ARGS` as it is, with whatever display the environment has (or none).
inline CliResult RunTestbed(const std::string& args)
{
    return RunCommand(TestbedBinary() + " " + args);
}

/// Mesa's OpenGL driver is unloaded at exit and leaves a few allocations that LeakSanitizer can then
/// neither attribute nor suppress, so sanitized builds check the testbed's OpenGL runs for everything
/// but leaks. What the testbed does without a window is leak-checked in-process (session_test.cpp);
/// the flag tests run without OpenGL and keep the leak check.
inline constexpr const char* kNoLeakCheckForTheDriver =
    "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0";

/// `contactfx-testbed ARGS` on a fresh virtual display (Xvfb with Mesa's software OpenGL). Tests run in
/// parallel, so each process starts looking for a free display number at its own place, and tries
/// once more should Xvfb still lose a race for one.
inline CliResult RunTestbedOnXvfb(const std::string& args)
{
    CliResult result;
    for (int attempt = 0; attempt < 2; ++attempt)
    {
        const int start = 100 + static_cast<int>((getpid() * 7 + attempt * 131) % 700);
        result =
            RunCommand(std::string(kNoLeakCheckForTheDriver) + " xvfb-run -a -n " + std::to_string(start) +
                       " -s \"-screen 0 1280x720x24\" " + TestbedBinary() + " " + args);
        if (result.output.find("Xvfb failed to start") == std::string::npos)
        {
            break;
        }
    }
    return result;
}

/// An opaque RGB image, channels in [0, 1].
struct Image
{
    int width = 0;
    int height = 0;
    std::vector<std::array<float, 3>> pixels; ///< row by row from the top left

    const std::array<float, 3>& At(int x, int y) const
    {
        return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
};

/// Reads a PNG with Cairo; an empty image when it cannot be read.
inline Image LoadPng(const std::filesystem::path& path)
{
    Image image;
    cairo_surface_t* surface = cairo_image_surface_create_from_png(path.c_str());
    if (cairo_surface_status(surface) == CAIRO_STATUS_SUCCESS)
    {
        image.width = cairo_image_surface_get_width(surface);
        image.height = cairo_image_surface_get_height(surface);
        const int stride = cairo_image_surface_get_stride(surface);
        const unsigned char* data = cairo_image_surface_get_data(surface);
        image.pixels.reserve(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
        for (int y = 0; y < image.height; ++y)
        {
            const auto* row =
                reinterpret_cast<const std::uint32_t*>(data + static_cast<std::size_t>(y) * stride);
            for (int x = 0; x < image.width; ++x)
            {
                const std::uint32_t argb = row[x];
                image.pixels.push_back({static_cast<float>((argb >> 16) & 0xFFu) / 255.0f,
                                        static_cast<float>((argb >> 8) & 0xFFu) / 255.0f,
                                        static_cast<float>(argb & 0xFFu) / 255.0f});
            }
        }
    }
    cairo_surface_destroy(surface);
    return image;
}

/// Lines of `text` that are not empty.
inline int CountLines(const std::string& text)
{
    int lines = 0;
    bool content = false;
    for (char c : text)
    {
        if (c == '\n')
        {
            lines += content ? 1 : 0;
            content = false;
        }
        else
        {
            content = true;
        }
    }
    return lines + (content ? 1 : 0);
}

} // namespace cfx::test
