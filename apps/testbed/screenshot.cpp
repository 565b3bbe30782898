#include "screenshot.h"

#include "contactfx/error.h"
#include "contactfx/scene/text_file.h"

#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>
#include <cairo.h>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cfx::testbed
{

namespace
{

cairo_status_t Append(void* closure, const unsigned char* data, unsigned int length)
{
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

} // namespace

void SaveScreenshot(int width, int height, const std::filesystem::path& path)
{
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());

    // Cairo's ARGB32 is one native-endian 32-bit word per pixel; OpenGL's rows start at the bottom.
    const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_ARGB32, width);
    std::vector<std::uint8_t> argb(static_cast<std::size_t>(stride) * static_cast<std::size_t>(height));
    for (int y = 0; y < height; ++y)
    {
        const std::uint8_t* source = rgba.data() + static_cast<std::size_t>(height - 1 - y) * width * 4;
        auto* target = reinterpret_cast<std::uint32_t*>(argb.data() + static_cast<std::size_t>(y) * stride);
        for (int x = 0; x < width; ++x)
        {
            const std::uint8_t* pixel = source + static_cast<std::size_t>(x) * 4;
            target[x] =
                0xFF000000u | (std::uint32_t{pixel[0]} << 16) | (std::uint32_t{pixel[1]} << 8) | pixel[2];
        }
    }
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create_for_data(argb.data(), CAIRO_FORMAT_ARGB32, width, height, stride),
        cairo_surface_destroy);
    std::string png;
    const cairo_status_t status = cairo_surface_write_to_png_stream(surface.get(), Append, &png);
    if (status != CAIRO_STATUS_SUCCESS)
    {
        throw InputError(path.string(), "",
                         std::string("cannot encode PNG: ") + cairo_status_to_string(status));
    }
    WriteTextFileAtomically(path, png);
}

} // namespace cfx::testbed
