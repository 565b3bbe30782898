// Internal to contactfx_render: a Cairo image as PNG file bytes, in memory (files are then written
// atomically by the caller).
#pragma once

#include <cairo.h>
#include <string>

namespace cfx::render::detail
{

/// Throws std::runtime_error when Cairo cannot encode the surface.
std::string EncodePng(cairo_surface_t* surface);

} // namespace cfx::render::detail
