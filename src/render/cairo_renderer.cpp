// The Cairo backend of the draw list. Shapes are built in world coordinates (Cairo's matrix maps metres
// to pixels), then stroked with the identity matrix so outlines keep their width in pixels whatever the
// zoom. Sprites are in pixels already: a radial gradient for a soft point (added onto the image for a
// glow), a round-capped line added onto the image for a streak, a filled disc inside its rim for a grain.
#include "contactfx/render/cairo_renderer.h"

#include "contactfx/render/png.h"

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

constexpr double kTurn = 2.0 * std::numbers::pi;

float Clamp01(float value)
{
    return std::clamp(value, 0.0f, 1.0f);
}

void SetWorldTransform(cairo_t* cr, const Camera& camera)
{
    cairo_identity_matrix(cr);
    cairo_translate(cr, 0.5 * camera.width, 0.5 * camera.height);
    cairo_scale(cr, camera.pixelsPerMetre, -camera.pixelsPerMetre);
    cairo_translate(cr, -camera.center.x, -camera.center.y);
}

} // namespace

CairoRenderer::CairoRenderer(int width, int height) : m_width(width), m_height(height)
{
    if (width < 1 || width > kMaxImageSide || height < 1 || height > kMaxImageSide)
    {
        throw std::invalid_argument("image size " + std::to_string(width) + "x" + std::to_string(height) +
                                    " outside 1 .. " + std::to_string(kMaxImageSide) + " pixels");
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
}

CairoRenderer::~CairoRenderer()
{
    cairo_destroy(m_cr);
    cairo_surface_destroy(m_surface);
}

void CairoRenderer::Render(const DrawList& list)
{
    Clear(list.background, list.backgroundBottom);
    const std::size_t under = std::min(list.shapesUnderSprites, list.shapes.size());
    for (std::size_t i = 0; i < under; ++i)
    {
        Shape(list, list.shapes[i]);
    }
    cairo_identity_matrix(m_cr);
    for (const SpriteCommand& sprite : list.sprites)
    {
        Sprite(sprite);
    }
    for (std::size_t i = under; i < list.shapes.size(); ++i)
    {
        Shape(list, list.shapes[i]);
    }
    cairo_identity_matrix(m_cr);
    const double textSize =
        list.overlay.textSize > 0.0f ? list.overlay.textSize : std::max(9.0, 0.026 * m_height);
    cairo_select_font_face(m_cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(m_cr, 0.8 * textSize);
    for (const TextLabel& label : list.labels)
    {
        cairo_set_source_rgba(m_cr, 0.0, 0.0, 0.0, 0.7); // a shadow, so it reads on any colour
        cairo_move_to(m_cr, label.at.x + 1.0, label.at.y + 1.0);
        cairo_show_text(m_cr, label.text.c_str());
        cairo_set_source_rgba(m_cr, label.color.r, label.color.g, label.color.b, label.color.a);
        cairo_move_to(m_cr, label.at.x, label.at.y);
        cairo_show_text(m_cr, label.text.c_str());
    }
    cairo_new_path(m_cr);
    cairo_set_font_size(m_cr, textSize);
    if (list.overlay.shown)
    {
        DrawOverlay(list.overlay, textSize);
    }
    if (list.overlay.scaleBar.shown)
    {
        DrawScaleBar(list.overlay.scaleBar, textSize);
    }
}

void CairoRenderer::Clear(const Color& top, const Color& bottom)
{
    cairo_identity_matrix(m_cr);
    cairo_set_operator(m_cr, CAIRO_OPERATOR_SOURCE);
    if (top == bottom)
    {
        cairo_set_source_rgb(m_cr, top.r, top.g, top.b);
        cairo_paint(m_cr);
    }
    else
    {
        cairo_pattern_t* gradient = cairo_pattern_create_linear(0.0, 0.0, 0.0, m_height);
        cairo_pattern_add_color_stop_rgb(gradient, 0.0, top.r, top.g, top.b);
        cairo_pattern_add_color_stop_rgb(gradient, 1.0, bottom.r, bottom.g, bottom.b);
        cairo_set_source(m_cr, gradient);
        cairo_paint(m_cr);
        cairo_pattern_destroy(gradient);
    }
    cairo_set_operator(m_cr, CAIRO_OPERATOR_OVER);
    cairo_set_line_join(m_cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(m_cr, CAIRO_LINE_CAP_ROUND);
}

void CairoRenderer::Shape(const DrawList& list, const ShapeCommand& shape)
{
    const b2Vec2* points = list.vertices.data() + shape.first;
    if (shape.kind == ShapeKind::point)
    {
        const b2Vec2 at = list.camera.ToPixels(points[0]);
        const double size = shape.pointSize;
        cairo_identity_matrix(m_cr);
        cairo_set_source_rgba(m_cr, shape.fill.r, shape.fill.g, shape.fill.b, shape.fill.a);
        cairo_rectangle(m_cr, at.x - 0.5 * size, at.y - 0.5 * size, size, size);
        cairo_fill(m_cr);
        return;
    }
    SetWorldTransform(m_cr, list.camera);
    switch (shape.kind)
    {
    case ShapeKind::polygon:
        for (std::uint32_t i = 0; i < shape.count; ++i)
        {
            cairo_line_to(m_cr, points[i].x, points[i].y);
        }
        cairo_close_path(m_cr);
        break;
    case ShapeKind::circle:
        cairo_arc(m_cr, points[0].x, points[0].y, shape.radius, 0.0, kTurn);
        break;
    default: // segment
        cairo_move_to(m_cr, points[0].x, points[0].y);
        cairo_line_to(m_cr, points[1].x, points[1].y);
        break;
    }
    if (shape.filled)
    {
        cairo_set_source_rgba(m_cr, shape.fill.r, shape.fill.g, shape.fill.b, shape.fill.a);
        cairo_fill_preserve(m_cr);
    }
    cairo_identity_matrix(m_cr); // the path stays where it is; the line width is now in pixels
    if (shape.strokeWidth > 0.0f)
    {
        cairo_set_source_rgba(m_cr, shape.stroke.r, shape.stroke.g, shape.stroke.b, shape.stroke.a);
        cairo_set_line_width(m_cr, shape.strokeWidth);
        cairo_stroke(m_cr);
    }
    cairo_new_path(m_cr);
}

void CairoRenderer::Sprite(const SpriteCommand& sprite)
{
    const Color& c = sprite.color;
    const b2Vec2& at = sprite.head;
    if (sprite.kind == SpriteKind::streak)
    {
        // Fading towards its tail, with a hot round head; added onto the image so that streaks glow
        // where they cross.
        const b2Vec2& tail = sprite.tail;
        const float width = sprite.size;
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
        return;
    }
    if (sprite.kind == SpriteKind::grain)
    {
        const double radius = 0.5 * sprite.size;
        const Color& rim = sprite.rim;
        cairo_set_source_rgba(m_cr, rim.r, rim.g, rim.b, Clamp01(rim.a));
        cairo_arc(m_cr, at.x, at.y, radius, 0.0, kTurn);
        cairo_fill(m_cr);
        cairo_set_source_rgba(m_cr, c.r, c.g, c.b, Clamp01(c.a));
        cairo_arc(m_cr, at.x, at.y, std::max(radius - sprite.rimWidth, 0.0), 0.0, kTurn);
        cairo_fill(m_cr);
        return;
    }
    if (sprite.kind == SpriteKind::glow)
    {
        // Brightest in the middle, falling off quickly, added onto the image.
        const double radius = 0.5 * sprite.size;
        cairo_set_operator(m_cr, CAIRO_OPERATOR_ADD);
        cairo_pattern_t* halo = cairo_pattern_create_radial(at.x, at.y, 0.0, at.x, at.y, radius);
        cairo_pattern_add_color_stop_rgba(halo, 0.0, c.r, c.g, c.b, Clamp01(c.a));
        cairo_pattern_add_color_stop_rgba(halo, 0.3, c.r, c.g, c.b, 0.4 * Clamp01(c.a));
        cairo_pattern_add_color_stop_rgba(halo, 1.0, c.r, c.g, c.b, 0.0);
        cairo_set_source(m_cr, halo);
        cairo_arc(m_cr, at.x, at.y, radius, 0.0, kTurn);
        cairo_fill(m_cr);
        cairo_pattern_destroy(halo);
        cairo_set_operator(m_cr, CAIRO_OPERATOR_OVER);
        return;
    }
    // A soft point: full colour in the middle, fading to nothing at its edge. Points of a few pixels
    // keep a solid core so that they still read; big ones (smoke) are soft all through.
    const double radius = 0.5 * sprite.size;
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

void CairoRenderer::DrawScaleBar(const ScaleBar& bar, double textSize)
{
    const double x0 = bar.from.x;
    const double x1 = bar.from.x + bar.pixels;
    const double y = bar.from.y;
    const double tick = 0.35 * textSize;
    cairo_set_source_rgba(m_cr, 0.92, 0.92, 0.92, 0.9);
    cairo_set_line_width(m_cr, 2.0);
    cairo_move_to(m_cr, x0, y - tick);
    cairo_line_to(m_cr, x0, y);
    cairo_line_to(m_cr, x1, y);
    cairo_line_to(m_cr, x1, y - tick);
    cairo_stroke(m_cr);
    cairo_move_to(m_cr, x0 + 0.3 * textSize, y - 0.5 * textSize);
    cairo_show_text(m_cr, bar.label.c_str());
    cairo_new_path(m_cr);
}

// The smallest font size (px) the overlay is drawn at: a picture without room for it gets none.
constexpr double kSmallestOverlayText = 5.0;

namespace
{

// Where the overlay's parts go at one font size (px): the panel at (pad / 2, pad / 2), its title on the
// first line, legend entry i at x[i] (from the text's left) on legend line row[i], wrapped to fit `room`.
struct OverlayLayout
{
    double size = 0.0;
    double pad = 0.0;
    double lineHeight = 0.0;
    double dot = 0.0;
    double width = 0.0; ///< the panel's
    double height = 0.0;
    std::vector<double> x;
    std::vector<int> row;

    OverlayLayout(cairo_t* cr, const std::string& title, const std::vector<std::string>& labels,
                  double fontSize, double room)
        : size(fontSize), pad(0.6 * fontSize), lineHeight(1.35 * fontSize), dot(0.7 * fontSize),
          x(labels.size()), row(labels.size())
    {
        cairo_set_font_size(cr, size);
        const auto advance = [&](const std::string& text)
        {
            cairo_text_extents_t extents;
            cairo_text_extents(cr, text.c_str(), &extents);
            return extents.x_advance;
        };
        const double textRoom = room - 3.0 * pad;
        double content = title.empty() ? 0.0 : advance(title);
        double at = 0.0;
        int rows = labels.empty() ? 0 : 1;
        for (std::size_t i = 0; i < labels.size(); ++i)
        {
            const double entry = dot + 0.4 * size + advance(labels[i]);
            if (at > 0.0 && at + entry > textRoom)
            {
                ++rows;
                at = 0.0;
            }
            x[i] = at;
            row[i] = rows - 1;
            content = std::max(content, at + entry);
            at += entry + size;
        }
        width = content + 2.0 * pad;
        height = ((title.empty() ? 0 : 1) + rows) * lineHeight + pad;
    }
};

} // namespace

void CairoRenderer::DrawOverlay(const Overlay& overlay, double textSize)
{
    const std::string& title = overlay.title;
    const std::vector<LegendEntry>& legend = overlay.legend;
    if (title.empty() && legend.empty())
    {
        return;
    }
    cairo_identity_matrix(m_cr);
    std::vector<std::string> labels;
    labels.reserve(legend.size());
    for (const LegendEntry& entry : legend)
    {
        labels.push_back(entry.name + " " + std::to_string(entry.count));
    }
    // The panel fits the picture, whatever its size: laid out at the font size asked for, the legend
    // wrapping into as many lines as the width needs; while the panel and a margin (half its padding, at
    // least 2 px: anti-aliased edges reach into the next pixel) are wider or taller than the picture, the
    // font shrinks by what they overflow and the layout is done again.
    const double width = static_cast<double>(m_width);
    const double height = static_cast<double>(m_height);
    OverlayLayout layout(m_cr, title, labels, textSize, width);
    bool fits = false;
    for (int attempt = 0; attempt < 16; ++attempt)
    {
        const double margin = std::max(layout.pad, 2.0);
        const double overflow = std::max((layout.width + margin) / width, (layout.height + margin) / height);
        fits = overflow <= 1.0;
        if (fits)
        {
            break;
        }
        layout = OverlayLayout(m_cr, title, labels, layout.size * 0.98 / overflow, width);
    }
    if (fits && layout.size >= kSmallestOverlayText) // else no overlay rather than a cut or unreadable one
    {
        const double pad = layout.pad;
        cairo_set_source_rgba(m_cr, 0.0, 0.0, 0.0, 0.55);
        cairo_rectangle(m_cr, pad * 0.5, pad * 0.5, layout.width, layout.height);
        cairo_fill(m_cr);
        double y = pad + layout.size;
        cairo_set_source_rgb(m_cr, 0.92, 0.92, 0.92);
        if (!title.empty())
        {
            cairo_move_to(m_cr, pad * 1.5, y);
            cairo_show_text(m_cr, title.c_str());
            y += layout.lineHeight;
        }
        for (std::size_t i = 0; i < legend.size(); ++i)
        {
            const double left = pad * 1.5 + layout.x[i];
            const double baseline = y + layout.row[i] * layout.lineHeight;
            const Color& c = legend[i].color;
            cairo_set_source_rgb(m_cr, c.r, c.g, c.b);
            cairo_arc(m_cr, left + 0.5 * layout.dot, baseline - 0.35 * layout.size, 0.5 * layout.dot, 0.0,
                      kTurn);
            cairo_fill(m_cr);
            cairo_set_source_rgb(m_cr, 0.92, 0.92, 0.92);
            cairo_move_to(m_cr, left + layout.dot + 0.4 * layout.size, baseline);
            cairo_show_text(m_cr, labels[i].c_str());
        }
        cairo_new_path(m_cr);
    }
    cairo_set_font_size(m_cr, textSize);
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
    return render::EncodePng(Rows(), m_width, m_height, Stride());
}

} // namespace cfx::render
