// contactfx_render: a DrawList (contactfx/draw/draw_list.h) rendered with Cairo into an image in memory.
//
// Headless pictures of a simulation: no window, no GPU, the same pixels on every machine for the same
// inputs. The list decides the look; this backend rasterises it: a vertical background gradient, shapes
// filled and outlined with anti-aliasing (outlines keep their width in pixels whatever the zoom), soft
// points and glows as radial gradients (glows added onto the image), streaks as round-capped lines with a
// linear fade added onto the image, grains as discs in a rim, then labels, the overlay's text in DejaVu
// Sans and the scale bar. The image is an ARGB32 Cairo surface the renderer owns: read pixels back, encode
// it as PNG, or hand its rows to a video encoder.
//
// Lifetime: one renderer per image size; reuse it frame after frame. Threading: one thread at a time.
#pragma once

#include "contactfx/draw/draw_list.h"

#include <cstdint>
#include <string>

using cairo_surface_t = struct _cairo_surface;
using cairo_t = struct _cairo;

namespace cfx::render
{

/// A straight (not premultiplied) 8-bit pixel.
struct Pixel
{
    std::uint8_t r = 0, g = 0, b = 0, a = 0;
};

class CairoRenderer final
{
public:
    /// An image of `width` x `height` pixels, each in [1, 16384]. Throws std::invalid_argument on a bad
    /// size and std::runtime_error when Cairo cannot allocate it.
    CairoRenderer(int width, int height);
    ~CairoRenderer();
    CairoRenderer(const CairoRenderer&) = delete;
    CairoRenderer& operator=(const CairoRenderer&) = delete;

    /// Replaces the image by `list` (its camera's width and height should be the image's): the
    /// background, its shapes, its sprites, its overlay.
    void Render(const DrawList& list);

    int Width() const { return m_width; }
    int Height() const { return m_height; }

    /// The pixel at column x, row y (from the top left), both inside the image.
    Pixel PixelAt(int x, int y) const;
    /// The image rows, top first, each Stride() bytes, pixels as native-endian 32-bit ARGB words (B, G,
    /// R, A bytes on little-endian machines), premultiplied; opaque after Render, as the background is.
    /// Valid until the next Render.
    const unsigned char* Rows() const;
    int Stride() const;
    /// The image as PNG file bytes (EncodePng, png.h).
    std::string EncodePng() const;

private:
    void Clear(const Color& top, const Color& bottom);
    void Shape(const DrawList& list, const ShapeCommand& shape);
    void Sprite(const SpriteCommand& sprite);
    void DrawOverlay(const Overlay& overlay, double textSize);
    void DrawScaleBar(const ScaleBar& bar, double textSize);

    int m_width;
    int m_height;
    cairo_surface_t* m_surface = nullptr;
    cairo_t* m_cr = nullptr;
};

} // namespace cfx::render
