// contactfx drawing layer: what colour each shape is.
//
// Box2D's own b2World::DebugDraw colours bodies by state (static, sleeping, awake), which says nothing
// about what they are made of. A viewer of effects wants the car red and the dirt brown, so shapes are
// coloured by their fixture's material (the tutorial's colours), falling back to the body type for
// fixtures without a material. DrawShapes walks the world and feeds every fixture to any b2Draw with
// that colour, usually a ShapeRecorder that writes them into a DrawList (draw_list.h).
#pragma once

#include <box2d/b2_draw.h>
#include <string>
#include <vector>

class b2Fixture;

namespace cfx
{

class Effects;

/// Colours of shapes.
struct ShapePalette
{
    struct Entry
    {
        std::string material;
        b2Color color;
    };
    std::vector<Entry> materials; ///< by material name; first match wins

    b2Color staticBody{0.5f, 0.9f, 0.5f, 1.0f}; ///< fixtures without a listed material, by body type
    b2Color kinematicBody{0.5f, 0.5f, 0.9f, 1.0f};
    b2Color dynamicBody{0.9f, 0.7f, 0.7f, 1.0f};
};

/// The tutorial's colours (../shared/NOTES.md): steel (the car) red, rubber (wheels) grey, concrete
/// light grey, dirt orange; other fixtures by body type as Box2D's debug draw does.
ShapePalette TutorialPalette();

/// The colour of `fixture`: its material's entry in `palette` when it has one, else its body type's.
b2Color FixtureColor(const Effects& effects, const ShapePalette& palette, const b2Fixture& fixture);

/// Which bodies DrawShapes draws.
enum class BodyKinds
{
    all,    ///< static bodies first, then the others, so moving bodies show over the ground they touch
    fixed,  ///< static bodies only
    moving, ///< kinematic and dynamic bodies only
};

/// Draws every fixture of the effects' world through `draw` (DrawSolidPolygon for polygons,
/// DrawSolidCircle for circles, DrawSegment for edges and chains), in `palette` colours; bodies that are
/// disabled, and the bodies of body-backed particles (Effects::IsParticleBody: they are drawn as
/// particles), are skipped. Nothing else of b2World::DebugDraw (joints, AABBs) is drawn.
void DrawShapes(const Effects& effects, b2Draw& draw, const ShapePalette& palette,
                BodyKinds kinds = BodyKinds::all);

} // namespace cfx
