#include "png_bytes.h"

#include <stdexcept>

namespace cfx::render::detail
{

namespace
{

cairo_status_t Append(void* closure, const unsigned char* data, unsigned int length)
{
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

} // namespace

std::string EncodePng(cairo_surface_t* surface)
{
    std::string bytes;
    cairo_surface_flush(surface);
    const cairo_status_t status = cairo_surface_write_to_png_stream(surface, Append, &bytes);
    if (status != CAIRO_STATUS_SUCCESS)
    {
        throw std::runtime_error(std::string("cannot encode PNG: ") + cairo_status_to_string(status));
    }
    return bytes;
}

} // namespace cfx::render::detail
