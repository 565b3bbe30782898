// contactfx_render: one whole picture of a simulation.
//
// What the render command, the README's picture and the tests draw: the world's shapes in material
// colours, the live particles, and a small overlay with the time and the live particles of each type.
#pragma once

#include "contactfx/draw.h"
#include "contactfx/render/cairo_renderer.h"
#include "contactfx/render/palette.h"

#include <string>
#include <vector>

namespace cfx
{
class Effects;
}

namespace cfx::render
{

struct FrameOptions
{
    ShapePalette palette = TutorialPalette();
    bool overlay = true; ///< time and live particles by type in the top left corner
    std::string caption; ///< shown after the time, e.g. the effects' name
};

/// Keeps what frames reuse (sprites, legend) so that drawing frame after frame does not allocate.
struct FrameScratch
{
    std::vector<ParticleSprite> sprites;
    std::vector<LegendEntry> legend;
};

/// Draws `effects` (its world and particles) as seen by `camera` into `renderer`; `time` in seconds
/// is printed in the overlay.
void RenderFrame(const Effects& effects, float time, const Camera& camera, const FrameOptions& options,
                 CairoRenderer& renderer, FrameScratch& scratch);

} // namespace cfx::render
