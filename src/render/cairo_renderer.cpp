// The Cairo renderer. Shapes are built in world coordinates (Cairo's matrix maps metres to pixels), then
// stroked with the identity matrix so outlines keep their width in pixels whatever the zoom. Particles
// are placed in pixels directly: a radial gradient for a soft point, a round-capped line added onto the
// image for a spark's streak.
#include "contactfx/render/cairo_renderer.h"

#include "png_bytes.h"

#include <algorithm>
#include <cairo.h>
#include <cmath>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace cfx::render
{

namespace
{

constexpr int kMaxSide = 16384;
constexpr double kTurn = 2.0 * std::numbers::pi;

float Clamp01(float value)
{
    return std::clamp(value, 0.0f, 1.0f);
}

} // namespace

CairoRenderer::CairoRenderer(int width, int height, const RenderStyle& style)
    : m_width(width), m_height(height), m_style(style)
{
    if (width < 1 || width > kMaxSide || height < 1 || height > kMaxSide)
    {
        throw std::invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " outside 1 .. " + std::to_string(kMaxSide) + " pixels");
    }
    m_surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
    m_cr = cairo_create(m_surface);
    if (cairo_status(m_cr) != CAIRO_STATUS_SUCCESS)
    {
        const std::string reason = cairo_status_to_string(cairo_status(m_cr));
        cairo_destroy(m_cr);
        cairo_surface_destroy(m_surface);
        throw std::runtime_error("cannot create a " + std::to_string(width) + "x" + std::to_string(height) +
                                 " image: " + reason);
    }
    m_camera.width = width;
    m_camera.height = height;
    SetFlags(e_shapeBit);
}

CairoRenderer::~CairoRenderer()
{
    cairo_destroy(m_cr);
    cairo_surface_destroy(m_surface);
}

void CairoRenderer::Begin(const Camera& camera)
{
    m_camera = camera;
    cairo_identity_matrix(m_cr);
    cairo_set_operator(m_cr, CAIRO_OPERATOR_SOURCE);
    const Color& bg = m_style.background;
    cairo_set_source_rgb(m_cr, bg.r, bg.g, bg.b);
    cairo_paint(m_cr);
    cairo_set_operator(m_cr, CAIRO_OPERATOR_OVER);
    cairo_set_line_join(m_cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(m_cr, CAIRO_LINE_CAP_ROUND);
    m_pass = ShapePass::solid;
}

void CairoRenderer::SetWorldTransform()
{
    cairo_identity_matrix(m_cr);
    cairo_translate(m_cr, 0.5 * m_camera.width, 0.5 * m_camera.height);
    cairo_scale(m_cr, m_camera.pixelsPerMetre, -m_camera.pixelsPerMetre);
    cairo_translate(m_cr, -m_camera.center.x, -m_camera.center.y);
}

void CairoRenderer::Outline(const b2Color& color)
{
    cairo_identity_matrix(m_cr); // the path stays where it is; the line width is now in pixels
    if (m_pass != ShapePass::fills && m_style.outlineWidth > 0.0f)
    {
        cairo_set_source_rgba(m_cr, color.r, color.g, color.b, color.a);
        cairo_set_line_width(m_cr, m_style.outlineWidth);
        cairo_stroke(m_cr);
    }
    cairo_new_path(m_cr);
}

void CairoRenderer::FillAndOutline(const b2Color& color)
{
    const float shade = Clamp01(m_style.fillShade);
    switch (m_pass)
    {
    case ShapePass::solid:
        cairo_set_source_rgba(m_cr, color.r * shade, color.g * shade, color.b * shade, color.a);
        cairo_fill_preserve(m_cr);
        Outline(color);
        break;
    case ShapePass::outlines:
        cairo_identity_matrix(m_cr);
        cairo_set_source_rgba(m_cr, color.r, color.g, color.b, color.a);
        cairo_set_line_width(m_cr, 2.0 * m_style.outlineWidth + 1.0);
        cairo_stroke(m_cr);
        break;
    case ShapePass::fills:
        // Half a pixel wider than the shape, so that neighbouring pieces leave no anti-aliased seam.
        cairo_set_source_rgba(m_cr, color.r * shade, color.g * shade, color.b * shade, color.a);
        cairo_fill_preserve(m_cr);
        cairo_identity_matrix(m_cr);
        cairo_set_line_width(m_cr, 1.0);
        cairo_stroke(m_cr);
        break;
    }
}

void CairoRenderer::PolygonPath(const b2Vec2* vertices, int32 vertexCount)
{
    SetWorldTransform();
    for (int32 i = 0; i < vertexCount; ++i)
    {
        cairo_line_to(m_cr, vertices[i].x, vertices[i].y);
    }
    cairo_close_path(m_cr);
}

void CairoRenderer::DrawPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color)
{
    PolygonPath(vertices, vertexCount);
    Outline(color);
}

void CairoRenderer::DrawSolidPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color)
{
    PolygonPath(vertices, vertexCount);
    FillAndOutline(color);
}

void CairoRenderer::DrawCircle(const b2Vec2& center, float radius, const b2Color& color)
{
    SetWorldTransform();
    cairo_arc(m_cr, center.x, center.y, radius, 0.0, kTurn);
    Outline(color);
}

void CairoRenderer::DrawSolidCircle(const b2Vec2& center, float radius, const b2Vec2& axis,
                                    const b2Color& color)
{
    SetWorldTransform();
    cairo_arc(m_cr, center.x, center.y, radius, 0.0, kTurn);
    FillAndOutline(color);
    if (m_pass != ShapePass::solid)
    {
        return;
    }
    // A spoke shows the rotation, as Box2D's testbed does.
    SetWorldTransform();
    cairo_move_to(m_cr, center.x, center.y);
    cairo_line_to(m_cr, center.x + radius * axis.x, center.y + radius * axis.y);
    Outline(color);
}

void CairoRenderer::DrawSegment(const b2Vec2& p1, const b2Vec2& p2, const b2Color& color)
{
    SetWorldTransform();
    cairo_move_to(m_cr, p1.x, p1.y);
    cairo_line_to(m_cr, p2.x, p2.y);
    Outline(color);
}

void CairoRenderer::DrawTransform(const b2Transform& xf)
{
    constexpr float kAxisLength = 0.4f; // m
    const b2Vec2 p = xf.p;
    DrawSegment(p, p + kAxisLength * xf.q.GetXAxis(), b2Color(1.0f, 0.0f, 0.0f));
    DrawSegment(p, p + kAxisLength * xf.q.GetYAxis(), b2Color(0.0f, 1.0f, 0.0f));
}

void CairoRenderer::DrawPoint(const b2Vec2& p, float size, const b2Color& color)
{
    const b2Vec2 at = m_camera.ToPixels(p);
    cairo_identity_matrix(m_cr);
    cairo_set_source_rgba(m_cr, color.r, color.g, color.b, color.a);
    cairo_rectangle(m_cr, at.x - 0.5 * size, at.y - 0.5 * size, size, size);
    cairo_fill(m_cr);
}

void CairoRenderer::DrawParticles(std::span<const ParticleSprite> sprites)
{
    cairo_identity_matrix(m_cr);
    const float minSize = std::max(m_style.minSpriteSize, 0.5f);
    const float ppm = m_camera.pixelsPerMetre;
    const double reach = 0.5 * std::max(m_width, m_height);
    for (const ParticleSprite& sprite : sprites)
    {
        const Color& c = sprite.color;
        if (!(c.a > 0.0f))
        {
            continue;
        }
        const b2Vec2 at = m_camera.ToPixels(sprite.position);
        const float size = std::max(sprite.size * ppm, minSize);
        if (!(std::abs(at.x - 0.5 * m_width) < reach + size &&
              std::abs(at.y - 0.5 * m_height) < reach + size))
        {
            continue; // off screen (or not a number)
        }
        if (sprite.streak > 0.0f)
        {
            // A spark: a line over the last `streak` seconds of its motion, half as thick as the sprite
            // is big, fading towards its tail, with a hot round head; added onto the image so that
            // sparks glow where they cross.
            const float width = std::max(0.5f * size, 0.75f * minSize);
            const b2Vec2 tail(at.x - sprite.velocity.x * sprite.streak * ppm,
                              at.y + sprite.velocity.y * sprite.streak * ppm);
            cairo_set_operator(m_cr, CAIRO_OPERATOR_ADD);
            cairo_pattern_t* fade = cairo_pattern_create_linear(tail.x, tail.y, at.x, at.y);
            cairo_pattern_add_color_stop_rgba(fade, 0.0, c.r, c.g, c.b, 0.0);
            cairo_pattern_add_color_stop_rgba(fade, 1.0, c.r, c.g, c.b, Clamp01(c.a));
            cairo_set_source(m_cr, fade);
            cairo_set_line_width(m_cr, width);
            cairo_move_to(m_cr, tail.x, tail.y);
            cairo_line_to(m_cr, at.x, at.y);
            cairo_stroke(m_cr);
            cairo_pattern_destroy(fade);
            cairo_set_source_rgba(m_cr, c.r, c.g, c.b, Clamp01(c.a));
            cairo_arc(m_cr, at.x, at.y, 0.5 * width, 0.0, kTurn);
            cairo_fill(m_cr);
            cairo_set_operator(m_cr, CAIRO_OPERATOR_OVER);
            continue;
        }
        // A soft point: full colour in the middle, fading to nothing at its edge. Points of a few pixels
        // keep a solid core so that they still read; big ones (smoke) are soft all through.
        const double radius = 0.5 * size;
        const double core = 1.0 - 0.45 * std::clamp((radius - 2.0) / 6.0, 0.0, 1.0);
        cairo_pattern_t* soft = cairo_pattern_create_radial(at.x, at.y, 0.0, at.x, at.y, radius);
        cairo_pattern_add_color_stop_rgba(soft, 0.0, c.r, c.g, c.b, Clamp01(c.a));
        cairo_pattern_add_color_stop_rgba(soft, 0.5, c.r, c.g, c.b, Clamp01(c.a) * core);
        cairo_pattern_add_color_stop_rgba(soft, 1.0, c.r, c.g, c.b, 0.0);
        cairo_set_source(m_cr, soft);
        cairo_arc(m_cr, at.x, at.y, radius, 0.0, kTurn);
        cairo_fill(m_cr);
        cairo_pattern_destroy(soft);
    }
}

void CairoRenderer::DrawOverlay(const std::string& title, std::span<const LegendEntry> legend)
{
    cairo_identity_matrix(m_cr);
    const double size = m_style.textSize > 0.0f ? m_style.textSize : std::max(9.0, 0.026 * m_height);
    cairo_select_font_face(m_cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(m_cr, size);
    const double pad = 0.6 * size;
    const double lineHeight = 1.35 * size;
    const double dot = 0.7 * size;

    // Lay out the legend first to size the panel behind the text.
    std::vector<std::string> labels;
    labels.reserve(legend.size());
    double legendWidth = 0.0;
    for (const LegendEntry& entry : legend)
    {
        labels.push_back(entry.name + " " + std::to_string(entry.count));
        cairo_text_extents_t extents;
        cairo_text_extents(m_cr, labels.back().c_str(), &extents);
        legendWidth += dot + 0.4 * size + extents.x_advance + size;
    }
    cairo_text_extents_t titleExtents;
    cairo_text_extents(m_cr, title.c_str(), &titleExtents);
    const int lines = (title.empty() ? 0 : 1) + (legend.empty() ? 0 : 1);
    if (lines == 0)
    {
        return;
    }
    const double panelWidth = std::max(titleExtents.x_advance, legendWidth) + 2.0 * pad;
    const double panelHeight = lines * lineHeight + pad;
    cairo_set_source_rgba(m_cr, 0.0, 0.0, 0.0, 0.55);
    cairo_rectangle(m_cr, pad * 0.5, pad * 0.5, panelWidth, panelHeight);
    cairo_fill(m_cr);

    double y = pad * 0.5 + 0.5 * pad + size;
    cairo_set_source_rgb(m_cr, 0.92, 0.92, 0.92);
    if (!title.empty())
    {
        cairo_move_to(m_cr, pad * 1.5, y);
        cairo_show_text(m_cr, title.c_str());
        y += lineHeight;
    }
    double x = pad * 1.5;
    for (std::size_t i = 0; i < legend.size(); ++i)
    {
        const Color& c = legend[i].color;
        cairo_set_source_rgb(m_cr, c.r, c.g, c.b);
        cairo_arc(m_cr, x + 0.5 * dot, y - 0.35 * size, 0.5 * dot, 0.0, kTurn);
        cairo_fill(m_cr);
        x += dot + 0.4 * size;
        cairo_set_source_rgb(m_cr, 0.92, 0.92, 0.92);
        cairo_move_to(m_cr, x, y);
        cairo_show_text(m_cr, labels[i].c_str());
        cairo_text_extents_t extents;
        cairo_text_extents(m_cr, labels[i].c_str(), &extents);
        x += extents.x_advance + size;
    }
    cairo_new_path(m_cr);
}

Pixel CairoRenderer::PixelAt(int x, int y) const
{
    cairo_surface_flush(m_surface);
    const unsigned char* row = cairo_image_surface_get_data(m_surface) +
                               static_cast<std::ptrdiff_t>(y) * cairo_image_surface_get_stride(m_surface);
    std::uint32_t argb = 0;
    std::memcpy(&argb, row + 4 * x, sizeof argb); // native-endian ARGB, premultiplied
    Pixel pixel;
    pixel.a = static_cast<std::uint8_t>(argb >> 24);
    auto straight = [&](std::uint32_t channel)
    {
        return pixel.a == 0 ? std::uint8_t{0}
                            : static_cast<std::uint8_t>(
                                  std::min<std::uint32_t>(255, (channel * 255 + pixel.a / 2) / pixel.a));
    };
    pixel.r = straight((argb >> 16) & 0xFF);
    pixel.g = straight((argb >> 8) & 0xFF);
    pixel.b = straight(argb & 0xFF);
    return pixel;
}

const unsigned char* CairoRenderer::Rows() const
{
    cairo_surface_flush(m_surface);
    return cairo_image_surface_get_data(m_surface);
}

int CairoRenderer::Stride() const
{
    return cairo_image_surface_get_stride(m_surface);
}

std::string CairoRenderer::EncodePng() const
{
    return detail::EncodePng(m_surface);
}

} // namespace cfx::render
