#include "contactfx/render/png.h"

#include <cairo.h>
#include <memory>
#include <stdexcept>

namespace cfx::render
{

namespace
{

cairo_status_t Append(void* closure, const unsigned char* data, unsigned int length)
{
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

} // namespace

std::string EncodePng(const unsigned char* rows, int width, int height, int stride)
{
    if (width < 1 || width > kMaxImageSide || height < 1 || height > kMaxImageSide || stride < 4 * width ||
        stride % 4 != 0 || rows == nullptr)
    {
        throw std::invalid_argument("cannot encode a PNG of " + std::to_string(width) + "x" +
                                    std::to_string(height) + " pixels with rows " + std::to_string(stride) +
                                    " bytes apart");
    }
    // Cairo's PNG writer only reads the pixels: the surface borrows them.
    const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create_for_data(const_cast<unsigned char*>(rows), CAIRO_FORMAT_ARGB32, width,
                                            height, stride),
        cairo_surface_destroy);
    std::string bytes;
    cairo_status_t status = cairo_surface_status(surface.get());
    if (status == CAIRO_STATUS_SUCCESS)
    {
        status = cairo_surface_write_to_png_stream(surface.get(), Append, &bytes);
    }
    if (status != CAIRO_STATUS_SUCCESS)
    {
        throw std::runtime_error(std::string("cannot encode PNG: ") + cairo_status_to_string(status));
    }
    return bytes;
}

} // namespace cfx::render
