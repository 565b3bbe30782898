// The draw list and what fills it. Everything that decides the look (fill shade, outline widths, the
// smallest sprite, streak geometry, a spark's heat and glow, a puff's growth and rise, a grain's rim,
// culling) is computed here once, so the Cairo and OpenGL backends only rasterise.
#include "contactfx/draw/draw_list.h"

#include <algorithm>
#include <cmath>

namespace cfx
{

namespace
{

Color ToColor(const b2Color& color)
{
    return Color{color.r, color.g, color.b, color.a};
}

} // namespace

void DrawList::Begin(const Camera& view, const Color& fill)
{
    camera = view;
    background = fill;
    backgroundBottom = fill;
    vertices.clear();
    shapes.clear();
    shapesUnderSprites = SIZE_MAX;
    sprites.clear();
    labels.clear();
    overlay.shown = false;
    overlay.title.clear();
    overlay.legend.clear();
    overlay.scaleBar.shown = false;
}

ShapeRecorder::ShapeRecorder(DrawList& list, const DrawStyle& style) : m_list(list), m_style(style)
{
    SetFlags(e_shapeBit);
}

ShapeCommand& ShapeRecorder::Add(ShapeKind kind, std::span<const b2Vec2> points)
{
    ShapeCommand& shape = m_list.shapes.emplace_back();
    shape.kind = kind;
    shape.first = static_cast<std::uint32_t>(m_list.vertices.size());
    shape.count = static_cast<std::uint32_t>(points.size());
    m_list.vertices.insert(m_list.vertices.end(), points.begin(), points.end());
    return shape;
}

// Open shapes and plain outlines: in the colour, outlineWidth px wide.
void ShapeRecorder::Outlined(ShapeCommand& shape, const b2Color& color) const
{
    shape.strokeWidth = std::max(m_style.outlineWidth, 0.0f);
    shape.stroke = ToColor(color);
}

// Solid shapes by pass (ShapePass).
void ShapeRecorder::Solid(ShapeCommand& shape, const b2Color& color) const
{
    const float shade = std::clamp(m_style.fillShade, 0.0f, 1.0f);
    const Color shaded{color.r * shade, color.g * shade, color.b * shade, color.a};
    switch (m_pass)
    {
    case ShapePass::solid:
        shape.filled = true;
        shape.fill = shaded;
        Outlined(shape, color);
        break;
    case ShapePass::outlines:
        shape.strokeWidth = 2.0f * m_style.outlineWidth + 1.0f;
        shape.stroke = ToColor(color);
        break;
    case ShapePass::fills:
        // Half a pixel wider than the shape, so that neighbouring pieces leave no anti-aliased seam.
        shape.filled = true;
        shape.fill = shaded;
        shape.strokeWidth = 1.0f;
        shape.stroke = shaded;
        break;
    }
}

void ShapeRecorder::DrawPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color)
{
    if (m_pass != ShapePass::fills)
    {
        Outlined(Add(ShapeKind::polygon, std::span(vertices, static_cast<std::size_t>(vertexCount))), color);
    }
}

void ShapeRecorder::DrawSolidPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color)
{
    Solid(Add(ShapeKind::polygon, std::span(vertices, static_cast<std::size_t>(vertexCount))), color);
}

void ShapeRecorder::DrawCircle(const b2Vec2& center, float radius, const b2Color& color)
{
    if (m_pass != ShapePass::fills)
    {
        ShapeCommand& circle = Add(ShapeKind::circle, std::span(&center, 1));
        circle.radius = radius;
        Outlined(circle, color);
    }
}

void ShapeRecorder::DrawSolidCircle(const b2Vec2& center, float radius, const b2Vec2& axis,
                                    const b2Color& color)
{
    ShapeCommand& circle = Add(ShapeKind::circle, std::span(&center, 1));
    circle.radius = radius;
    Solid(circle, color);
    if (m_pass == ShapePass::solid)
    {
        DrawSegment(center, center + radius * axis, color);
    }
}

void ShapeRecorder::DrawSegment(const b2Vec2& p1, const b2Vec2& p2, const b2Color& color)
{
    if (m_pass != ShapePass::fills)
    {
        const b2Vec2 ends[2] = {p1, p2};
        Outlined(Add(ShapeKind::segment, ends), color);
    }
}

void ShapeRecorder::DrawTransform(const b2Transform& xf)
{
    constexpr float kAxisLength = 0.4f; // m
    const b2Vec2 p = xf.p;
    DrawSegment(p, p + kAxisLength * xf.q.GetXAxis(), b2Color(1.0f, 0.0f, 0.0f));
    DrawSegment(p, p + kAxisLength * xf.q.GetYAxis(), b2Color(0.0f, 1.0f, 0.0f));
}

void ShapeRecorder::DrawPoint(const b2Vec2& p, float size, const b2Color& color)
{
    if (m_pass != ShapePass::fills)
    {
        ShapeCommand& point = Add(ShapeKind::point, std::span(&p, 1));
        point.pointSize = size;
        point.filled = true;
        point.fill = ToColor(color);
    }
}

Color HeatColor(float life)
{
    // Stops from cold to hot; between them the colour is blended linearly.
    struct Stop
    {
        float life;
        Color color;
    };
    static constexpr Stop kStops[] = {
        {0.0f, Color{0.55f, 0.04f, 0.0f, 1.0f}}, // dark red
        {0.3f, Color{1.0f, 0.25f, 0.03f, 1.0f}}, // red-orange
        {0.6f, Color{1.0f, 0.85f, 0.25f, 1.0f}}, // yellow
        {0.85f, Color{1.0f, 1.0f, 0.9f, 1.0f}},  // white
    };
    const float t = std::isnan(life) ? 0.0f : std::clamp(life, 0.0f, 1.0f);
    if (t >= kStops[3].life)
    {
        return kStops[3].color;
    }
    std::size_t i = 1;
    while (t > kStops[i].life)
    {
        ++i;
    }
    const Stop& low = kStops[i - 1];
    const Stop& high = kStops[i];
    const float f = (t - low.life) / (high.life - low.life);
    auto mix = [f](float a, float b) { return a + f * (b - a); };
    return Color{mix(low.color.r, high.color.r), mix(low.color.g, high.color.g),
                 mix(low.color.b, high.color.b), 1.0f};
}

namespace
{

// Whether the box from `low` to `high` (px) touches the camera's image.
bool OnImage(const Camera& camera, b2Vec2 low, b2Vec2 high)
{
    // Written so that NaN fails every comparison and is left out.
    return high.x >= 0.0f && high.y >= 0.0f && low.x <= static_cast<float>(camera.width) &&
           low.y <= static_cast<float>(camera.height);
}

void AddSpark(DrawList& list, const ParticleSprite& sprite, b2Vec2 at, float size, const DrawStyle& style)
{
    const float minSize = std::max(style.minSpriteSize, 0.5f);
    const float ppm = list.camera.pixelsPerMetre;
    const float thickness = std::max(0.5f * size, 0.75f * minSize);
    // The last `streak` seconds of its motion (pixels run down).
    const b2Vec2 tail(at.x - sprite.velocity.x * sprite.streak * ppm,
                      at.y + sprite.velocity.y * sprite.streak * ppm);
    const float glow = std::max(style.glowSize, 0.0f) * thickness;
    const float reach = std::max(0.5f * glow, 0.5f * thickness);
    if (!OnImage(list.camera, b2Vec2(std::min(at.x, tail.x) - reach, std::min(at.y, tail.y) - reach),
                 b2Vec2(std::max(at.x, tail.x) + reach, std::max(at.y, tail.y) + reach)))
    {
        return;
    }
    Color hot = HeatColor(sprite.life);
    hot.a = std::min(sprite.color.a, 1.0f);
    const float glowOpacity = std::clamp(style.glowOpacity, 0.0f, 1.0f);
    if (glow > thickness && glowOpacity > 0.0f)
    {
        SpriteCommand& halo = list.sprites.emplace_back();
        halo.kind = SpriteKind::glow;
        halo.head = at;
        halo.tail = at;
        halo.size = glow;
        halo.color = Color{hot.r, hot.g, hot.b, hot.a * glowOpacity};
    }
    SpriteCommand& streak = list.sprites.emplace_back();
    streak.kind = SpriteKind::streak;
    streak.head = at;
    streak.tail = tail;
    streak.size = thickness;
    streak.color = hot;
    streak.type = sprite.type;
}

} // namespace

void AddParticles(DrawList& list, std::span<const ParticleSprite> sprites, const DrawStyle& style)
{
    const Camera& camera = list.camera;
    const float minSize = std::max(style.minSpriteSize, 0.5f);
    const float ppm = camera.pixelsPerMetre;
    for (const ParticleSprite& sprite : sprites)
    {
        const Color& c = sprite.color;
        if (!(c.a > 0.0f))
        {
            continue;
        }
        const float size = std::max(sprite.size * ppm, minSize);
        if (sprite.streak > 0.0f)
        {
            AddSpark(list, sprite, camera.ToPixels(sprite.position), size, style);
            continue;
        }
        const float age = 1.0f - std::clamp(sprite.life, 0.0f, 1.0f);
        SpriteCommand command;
        command.color = c;
        command.type = sprite.type;
        if (sprite.look == SpriteLook::grain)
        {
            command.kind = SpriteKind::grain;
            command.size = std::max(size, style.minGrainSize);
            command.rimWidth = std::clamp(style.grainRim, 0.0f, 0.5f * command.size);
            const float lift = std::clamp(style.grainLift, 0.0f, 1.0f);
            command.color =
                Color{c.r + lift * (1.0f - c.r), c.g + lift * (1.0f - c.g), c.b + lift * (1.0f - c.b), c.a};
            command.rim = Color{0.25f * c.r, 0.25f * c.g, 0.25f * c.b, std::min(1.0f, c.a)};
            command.head = camera.ToPixels(sprite.position);
        }
        else
        {
            command.kind = SpriteKind::soft;
            command.size = size * (1.0f + std::max(style.puffGrowth, 0.0f) * age);
            const float rise = std::max(style.puffRise, 0.0f) * age * std::max(sprite.lifetime, 0.0f);
            command.head = camera.ToPixels(sprite.position + b2Vec2(0.0f, rise));
        }
        command.tail = command.head;
        const float half = 0.5f * command.size;
        if (OnImage(camera, command.head - b2Vec2(half, half), command.head + b2Vec2(half, half)))
        {
            list.sprites.push_back(command);
        }
    }
}

} // namespace cfx
