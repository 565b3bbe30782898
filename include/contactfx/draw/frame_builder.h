// contactfx drawing layer: one whole picture of a simulation as a DrawList.
//
// What the render command, the README's picture, the testbed and the tests show: a background gradient,
// the world's shapes in material colours (the static ground first, outlines under fills so that its
// pieces read as one surface, then what moves), the live particles over them, the debug layers asked
// for, and an overlay with the time, the particles of each type on the image and an optional scale bar. Any
// backend renders the list (contactfx::render's CairoRenderer, the testbed's OpenGL renderer).
#pragma once

#include "contactfx/draw.h"
#include "contactfx/draw/camera.h"
#include "contactfx/draw/debug_layers.h"
#include "contactfx/draw/draw_list.h"
#include "contactfx/draw/palette.h"
#include "contactfx/draw/style.h"

#include <string>
#include <vector>

namespace cfx
{

class Effects;

struct FrameOptions
{
    ShapePalette palette = TutorialPalette();
    DrawStyle style;
    bool overlay = true;   ///< time and the particles on the image by type in the top left corner
    std::string caption;   ///< shown after the time, e.g. the effects' name
    bool scaleBar = false; ///< a bar of a round length in metres in the bottom left corner
    DebugLayers debug;     ///< tuning layers over the particles (none by default)
};

/// A scale bar for `camera`: the longest of 1, 2 or 5 times a power of ten metres that is at most a fifth
/// of the image wide, at its bottom left corner, labelled "2 m" (or "50 cm", "5 mm").
ScaleBar MakeScaleBar(const Camera& camera);

/// Keeps what frames reuse (sprites, the list) so that building frame after frame does not allocate.
struct FrameScratch
{
    std::vector<ParticleSprite> sprites;
    DrawList list;
};

/// Records every enabled body's fixtures of the effects' world into `recorder`: static bodies as
/// outlines then fills, then kinematic and dynamic bodies solid. Leaves the recorder's pass `solid`.
void RecordWorldShapes(const Effects& effects, const ShapePalette& palette, ShapeRecorder& recorder);

/// The picture of `effects` (its world and particles) seen by `camera`, into `scratch.list` (returned);
/// `time` in seconds is printed in the overlay. The legend counts the particles of each type on the image.
const DrawList& BuildFrame(const Effects& effects, float time, const Camera& camera,
                           const FrameOptions& options, FrameScratch& scratch);

} // namespace cfx
