// contactfx_render: the drawing interface, implemented with Cairo into an image in memory.
//
// Headless pictures of a simulation: no window, no GPU, the same pixels on every machine for the same
// inputs. Shapes arrive through Box2D's b2Draw (filled in a shade of their colour with an anti-aliased
// outline), particles through cfx::ParticleDraw (soft round points whose opacity follows their life;
// sparks as short glowing streaks along their velocity), then a small text overlay. The image is an
// ARGB32 Cairo surface the renderer owns: read pixels back, encode it as PNG, or hand its rows to a
// video encoder.
//
// Lifetime: one renderer per image size; reuse it frame after frame (Begin clears). Threading: one
// thread at a time.
#pragma once

#include "contactfx/draw.h"
#include "contactfx/particle_types.h"
#include "contactfx/render/camera.h"

#include <box2d/b2_draw.h>
#include <cstdint>
#include <span>
#include <string>

using cairo_surface_t = struct _cairo_surface;
using cairo_t = struct _cairo;

namespace cfx::render
{

/// How things look beyond their own colours.
struct RenderStyle
{
    Color background{0.06f, 0.07f, 0.10f, 1.0f}; ///< dark, so sparks and smoke read
    float fillShade = 0.38f;                     ///< shapes are filled with colour * fillShade, [0, 1]
    float outlineWidth = 1.5f;                   ///< px, outline of shapes in their full colour, >= 0
    float minSpriteSize = 2.0f;                  ///< px: smaller particles are drawn this big
    float textSize = 0.0f;                       ///< px; 0: from the image height
};

/// One entry of the overlay's legend: a colour dot, a name and a number.
struct LegendEntry
{
    std::string name;
    Color color;
    std::uint64_t count = 0;
};

/// How solid shapes (DrawSolidPolygon, DrawSolidCircle) are drawn.
enum class ShapePass
{
    solid,    ///< each shape filled with colour * fillShade and outlined in colour
    outlines, ///< only outlines, 2 * outlineWidth + 1 px wide (then `fills` covers their inner half)
    fills,    ///< only fills, widened by half a pixel; segments and outlines are skipped
};
// Drawing a ground made of many polygons with `outlines` then `fills` leaves its outer edge outlined and
// hides the seams between its pieces.

/// A straight (not premultiplied) 8-bit pixel.
struct Pixel
{
    std::uint8_t r = 0, g = 0, b = 0, a = 0;
};

class CairoRenderer final : public b2Draw, public ParticleDraw
{
public:
    /// An image of `width` x `height` pixels, each in [1, 16384]. Throws std::invalid_argument on a bad
    /// size and std::runtime_error when Cairo cannot allocate it.
    CairoRenderer(int width, int height, const RenderStyle& style = {});
    ~CairoRenderer() override;
    CairoRenderer(const CairoRenderer&) = delete;
    CairoRenderer& operator=(const CairoRenderer&) = delete;

    /// Starts a frame: clears to the background and looks through `camera` (whose width and height
    /// should be the image's).
    void Begin(const Camera& camera);

    // b2Draw, in world metres. Solid shapes: filled with colour * fillShade, outlined in colour.
    void DrawPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color) override;
    void DrawSolidPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color) override;
    void DrawCircle(const b2Vec2& center, float radius, const b2Color& color) override;
    void DrawSolidCircle(const b2Vec2& center, float radius, const b2Vec2& axis,
                         const b2Color& color) override;
    void DrawSegment(const b2Vec2& p1, const b2Vec2& p2, const b2Color& color) override;
    void DrawTransform(const b2Transform& xf) override;
    /// `size` in pixels, as in Box2D's testbed.
    void DrawPoint(const b2Vec2& p, float size, const b2Color& color) override;

    /// How the following solid shapes are drawn; Begin sets `solid`.
    void SetShapePass(ShapePass pass) { m_pass = pass; }

    /// ParticleDraw: soft round points of the sprite's diameter (at least minSpriteSize px); sprites
    /// with streak > 0 as lines half as thick, from position - velocity * streak to position, fading
    /// towards the tail, with a round head, added onto what is below.
    void DrawParticles(std::span<const ParticleSprite> sprites) override;

    /// Text in the top left corner: `title` on the first line, the legend on the second.
    void DrawOverlay(const std::string& title, std::span<const LegendEntry> legend);

    int Width() const { return m_width; }
    int Height() const { return m_height; }
    const Camera& CurrentCamera() const { return m_camera; }
    const RenderStyle& Style() const { return m_style; }

    /// The pixel at column x, row y (from the top left), both inside the image.
    Pixel PixelAt(int x, int y) const;
    /// The image rows, top first, each Stride() bytes, pixels as native-endian 32-bit ARGB words (B, G,
    /// R, A bytes on little-endian machines), premultiplied; opaque after Begin, as the background is.
    /// Valid until the next drawing call.
    const unsigned char* Rows() const;
    int Stride() const;
    /// The image as PNG file bytes.
    std::string EncodePng() const;

private:
    void SetWorldTransform();
    void PolygonPath(const b2Vec2* vertices, int32 vertexCount);
    void FillAndOutline(const b2Color& color);
    void Outline(const b2Color& color);

    int m_width;
    int m_height;
    RenderStyle m_style;
    Camera m_camera;
    ShapePass m_pass = ShapePass::solid;
    cairo_surface_t* m_surface = nullptr;
    cairo_t* m_cr = nullptr;
};

} // namespace cfx::render
