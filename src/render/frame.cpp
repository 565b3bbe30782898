// One frame: shapes, then particles over them, then the overlay over everything.
#include "contactfx/render/frame.h"

#include "contactfx/effects.h"

#include <cstdio>

namespace cfx::render
{

void RenderFrame(const Effects& effects, float time, const Camera& camera, const FrameOptions& options,
                 CairoRenderer& renderer, FrameScratch& scratch)
{
    renderer.Begin(camera);
    // Static ground first, outlines under fills so that its pieces read as one surface; then what moves.
    renderer.SetShapePass(ShapePass::outlines);
    DrawShapes(effects, renderer, options.palette, BodyKinds::fixed);
    renderer.SetShapePass(ShapePass::fills);
    DrawShapes(effects, renderer, options.palette, BodyKinds::fixed);
    renderer.SetShapePass(ShapePass::solid);
    DrawShapes(effects, renderer, options.palette, BodyKinds::moving);
    CollectSprites(effects, scratch.sprites);
    renderer.DrawParticles(scratch.sprites);
    if (!options.overlay)
    {
        return;
    }
    const std::vector<ParticleTypeDef>& types = effects.Config().particleTypes;
    scratch.legend.resize(types.size());
    for (std::size_t i = 0; i < types.size(); ++i)
    {
        scratch.legend[i].name = types[i].name;
        scratch.legend[i].color = types[i].colorStart;
        scratch.legend[i].count = 0;
    }
    for (const ParticleSprite& sprite : scratch.sprites)
    {
        if (sprite.type.IsValid() && sprite.type.index < scratch.legend.size())
        {
            ++scratch.legend[sprite.type.index].count;
        }
    }
    char title[64];
    std::snprintf(title, sizeof title, "t = %.2f s", static_cast<double>(time));
    renderer.DrawOverlay(options.caption.empty() ? std::string(title) : title + ("   " + options.caption),
                         scratch.legend);
}

} // namespace cfx::render
