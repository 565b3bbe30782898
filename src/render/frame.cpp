#include "contactfx/render/frame.h"

namespace cfx::render
{

void RenderFrame(const Effects& effects, float time, const Camera& camera, const FrameOptions& options,
                 CairoRenderer& renderer, FrameScratch& scratch)
{
    renderer.Render(BuildFrame(effects, time, camera, options, scratch));
}

} // namespace cfx::render
