// contactfx drawing layer: one picture as data.
//
// Sections: DrawList (what backends render) - ShapeRecorder (b2Draw calls into a list) - AddParticles.
//
// As Dear ImGui's core produces draw lists that its backends render, contactfx turns a world, its
// particles and a camera into a DrawList: shapes in world metres with their fill and outline already
// decided (colour, shade, width in pixels), particles as soft points and streaks in pixels, and an
// overlay of text. The Cairo renderer (contactfx::render) and the testbed's OpenGL renderer render a
// list and decide nothing about the look; neither knows the other. A list knows no backend.
//
// Lifetime: a list is a plain value; Begin() clears it and keeps its storage, so building one frame
// after another does not allocate once warmed up. Threading: one thread at a time per list.
#pragma once

#include "contactfx/draw.h"
#include "contactfx/draw/camera.h"
#include "contactfx/draw/style.h"
#include "contactfx/materials.h"
#include "contactfx/particle_types.h"

#include <box2d/b2_draw.h>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace cfx
{

/// The outline of a shape.
enum class ShapeKind : std::uint8_t
{
    polygon, ///< closed, through `count` vertices
    circle,  ///< around vertex `first`, `radius` m
    segment, ///< open, from vertex `first` to `first + 1`
    point,   ///< a square `pointSize` px wide, centred on vertex `first`
};

/// One shape in world metres, filled and then outlined. Stroke widths are in pixels whatever the zoom.
struct ShapeCommand
{
    ShapeKind kind = ShapeKind::polygon;
    std::uint32_t first = 0;  ///< index of its first vertex in DrawList::vertices
    std::uint32_t count = 0;  ///< vertices it uses: polygon >= 2, circle and point 1, segment 2
    float radius = 0.0f;      ///< m, circle only
    float pointSize = 0.0f;   ///< px, point only
    bool filled = false;      ///< polygons, circles and points: fill inside with `fill`
    Color fill;               ///< straight alpha
    float strokeWidth = 0.0f; ///< px, >= 0; 0: no outline (a point is never outlined)
    Color stroke;             ///< straight alpha
};

/// How a sprite is drawn.
enum class SpriteKind : std::uint8_t
{
    soft,   ///< a round point, full colour in the middle fading to nothing at its rim
    streak, ///< a line from `tail` to `head`, `size` px thick, fading towards its tail, with a round
            ///< head; added onto what is below (it glows where streaks cross)
    glow,   ///< a soft point added onto what is below (a spark's halo)
    grain,  ///< a solid disc of `size` px, its outer `rimWidth` px in `rim`
};

/// One particle in pixels (y down, origin at the top left) of the list's camera.
struct SpriteCommand
{
    SpriteKind kind = SpriteKind::soft;
    b2Vec2 head{0.0f, 0.0f}; ///< px: a soft point's centre, a streak's head
    b2Vec2 tail{0.0f, 0.0f}; ///< px: a streak's tail; a soft point's centre too
    float size = 0.0f;       ///< px: a soft point's diameter, a streak's thickness; > 0
    Color color;             ///< straight alpha, in (0, 1]
    Color rim;               ///< grain only: its rim, straight alpha
    float rimWidth = 0.0f;   ///< px, grain only, in [0, size / 2]
    ParticleTypeId type;     ///< invalid for what is not a particle itself (a glow)
};

/// A line of text whose baseline starts at `at` (px of the list's camera), e.g. a rule's name.
struct TextLabel
{
    b2Vec2 at{0.0f, 0.0f};
    std::string text;
    Color color;
};

/// A bar `pixels` long from `from` (px, its left end) to the right, with `label` ("1 m") above it.
struct ScaleBar
{
    bool shown = false;
    b2Vec2 from{0.0f, 0.0f};
    float pixels = 0.0f; ///< > 0 when shown
    float metres = 0.0f; ///< what the bar measures in the world
    std::string label;
};

/// One entry of the overlay's legend: a colour dot, a name and a number.
struct LegendEntry
{
    std::string name;
    Color color;
    std::uint64_t count = 0;
};

/// Text in the top left corner on a dark panel: `title` on the first line, the legend on the second.
/// Backends lay it out, since only they can measure text.
struct Overlay
{
    bool shown = false;
    std::string title;
    std::vector<LegendEntry> legend;
    float textSize = 0.0f; ///< px; 0: from the image height
    ScaleBar scaleBar;     ///< bottom left, drawn over everything
};

/// A picture: drawn as background, then the first `shapesUnderSprites` shapes in order, then `sprites` in
/// order, then the other shapes (debug layers), then `labels`, then the overlay.
struct DrawList
{
    Camera camera;                    ///< world metres -> pixels; its width and height are the image's
    Color background;                 ///< fills the image first: the colour at its top row ...
    Color backgroundBottom;           ///< ... blending linearly into this one at its bottom row
    std::vector<b2Vec2> vertices;     ///< m, world; the shapes' points
    std::vector<ShapeCommand> shapes; ///< world metres
    std::size_t shapesUnderSprites = SIZE_MAX; ///< shapes drawn before the sprites; SIZE_MAX: all
    std::vector<SpriteCommand> sprites;        ///< pixels
    std::vector<TextLabel> labels;             ///< pixels; laid out by the backend
    Overlay overlay;

    /// Empties the list (keeping its storage) for a picture seen through `camera` on `fill` (top and
    /// bottom alike; set backgroundBottom afterwards for a gradient).
    void Begin(const Camera& view, const Color& fill);
};

/// How the solid shapes (DrawSolidPolygon, DrawSolidCircle) of a ShapeRecorder are recorded.
enum class ShapePass : std::uint8_t
{
    solid,    ///< each shape filled with colour * fillShade and outlined in colour
    outlines, ///< only outlines, 2 * outlineWidth + 1 px wide (then `fills` covers their inner half)
    fills,    ///< only fills, widened by half a pixel; open shapes, outlines and points are skipped
};
// Recording a ground made of many polygons with `outlines` then `fills` leaves its outer edge outlined and
// hides the seams between its pieces.

/// A b2Draw that records what it is given into a DrawList, styled: pass it to DrawShapes or to
/// b2World::DebugDraw. It draws shapes only (its flags are e_shapeBit unless changed).
class ShapeRecorder final : public b2Draw
{
public:
    /// Records into `list` (which must outlive the recorder) with a copy of `style`.
    ShapeRecorder(DrawList& list, const DrawStyle& style);

    /// How the following solid shapes are recorded; starts as `solid`.
    void SetPass(ShapePass pass) { m_pass = pass; }

    void DrawPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color) override;
    void DrawSolidPolygon(const b2Vec2* vertices, int32 vertexCount, const b2Color& color) override;
    void DrawCircle(const b2Vec2& center, float radius, const b2Color& color) override;
    /// A spoke from the centre along `axis` shows the rotation (solid pass only), as in Box2D's testbed.
    void DrawSolidCircle(const b2Vec2& center, float radius, const b2Vec2& axis,
                         const b2Color& color) override;
    void DrawSegment(const b2Vec2& p1, const b2Vec2& p2, const b2Color& color) override;
    /// The body axes, 0.4 m long: x red, y green.
    void DrawTransform(const b2Transform& xf) override;
    /// `size` in pixels, as in Box2D's testbed.
    void DrawPoint(const b2Vec2& p, float size, const b2Color& color) override;

private:
    ShapeCommand& Add(ShapeKind kind, std::span<const b2Vec2> points);
    void Outlined(ShapeCommand& shape, const b2Color& color) const;
    void Solid(ShapeCommand& shape, const b2Color& color) const;

    DrawList& m_list;
    DrawStyle m_style; // a copy: a temporary style given to the constructor stays valid
    ShapePass m_pass = ShapePass::solid;
};

/// Appends `sprites` to `list` as pixels of its camera, each at least style.minSpriteSize px (and 0.5 px):
/// - sprites with streak > 0 (sparks) as a glow (style.glowSize streak thicknesses across, opacity
///   style.glowOpacity) and a streak from position - velocity * streak to position, half as thick as the
///   sprite (at least 0.75 * the smallest size), both in HeatColor(life) with the sprite's opacity;
/// - puffs as soft points, (1 + style.puffGrowth * (1 - life)) times the sprite's diameter, drawn
///   style.puffRise * (1 - life) * lifetime metres above the particle;
/// - grains as discs of at least style.minGrainSize px, their colour lifted towards white by
///   style.grainLift inside a dark rim of style.grainRim px.
/// Sprites with no opacity, wholly off the image or not finite are left out, so the sprites with a valid
/// type are the particles on the image.
void AddParticles(DrawList& list, std::span<const ParticleSprite> sprites, const DrawStyle& style);

/// The colour of something glowing hot at `life` in [0, 1] (1: just made): white, then yellow, orange
/// and at last dark red; opaque.
Color HeatColor(float life);

} // namespace cfx
