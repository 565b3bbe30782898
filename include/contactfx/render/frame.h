// contactfx_render: one whole picture of a simulation, drawn with Cairo.
//
// BuildFrame (contactfx/draw/frame_builder.h) makes the picture's draw list; RenderFrame renders it
// into a CairoRenderer: what the render command, the README's picture and the tests draw.
#pragma once

#include "contactfx/draw/frame_builder.h"
#include "contactfx/render/cairo_renderer.h"

namespace cfx::render
{

/// Draws `effects` (its world and particles) as seen by `camera` into `renderer`; `time` in seconds
/// is printed in the overlay. The list is built in `scratch.list`.
void RenderFrame(const Effects& effects, float time, const Camera& camera, const FrameOptions& options,
                 CairoRenderer& renderer, FrameScratch& scratch);

} // namespace cfx::render
