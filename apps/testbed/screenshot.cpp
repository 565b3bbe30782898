#include "screenshot.h"

#include "contactfx/files/text_file.h"
#include "contactfx/render/png.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>
#include <cstdint>
#include <cstring>
#include <vector>

namespace cfx::testbed
{

void SaveScreenshot(int width, int height, const std::filesystem::path& path)
{
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());

    // EncodePng takes native-endian 32-bit ARGB words, top row first; OpenGL's rows start at the bottom.
    const int stride = 4 * width;
    std::vector<std::uint8_t> argb(static_cast<std::size_t>(stride) * static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y)
    {
        const std::uint8_t* source = rgba.data() + static_cast<std::size_t>(height - 1 - y) * width * 4;
        std::uint8_t* target = argb.data() + static_cast<std::size_t>(y) * stride;
        for (int x = 0; x < width; ++x)
        {
            const std::uint8_t* pixel = source + static_cast<std::size_t>(x) * 4;
            const std::uint32_t word =
                0xFF000000u | (std::uint32_t{pixel[0]} << 16) | (std::uint32_t{pixel[1]} << 8) | pixel[2];
            std::memcpy(target + static_cast<std::size_t>(x) * 4, &word, sizeof word);
        }
    }
    WriteTextFileAtomically(path, render::EncodePng(argb.data(), width, height, stride));
}

} // namespace cfx::testbed
