// One frame: shapes, then particles over them, then the overlay over everything.
#include "contactfx/draw/frame_builder.h"

#include "contactfx/effects.h"

#include <cmath>
#include <cstdio>

namespace cfx
{

void RecordWorldShapes(const Effects& effects, const ShapePalette& palette, ShapeRecorder& recorder)
{
    // Static ground first, outlines under fills so that its pieces read as one surface; then what moves.
    recorder.SetPass(ShapePass::outlines);
    DrawShapes(effects, recorder, palette, BodyKinds::fixed);
    recorder.SetPass(ShapePass::fills);
    DrawShapes(effects, recorder, palette, BodyKinds::fixed);
    recorder.SetPass(ShapePass::solid);
    DrawShapes(effects, recorder, palette, BodyKinds::moving);
}

ScaleBar MakeScaleBar(const Camera& camera)
{
    ScaleBar bar;
    const float widest = 0.2f * static_cast<float>(camera.width) / camera.pixelsPerMetre; // m
    if (!(widest > 0.0f) || !std::isfinite(widest))
    {
        return bar;
    }
    const float decade = std::pow(10.0f, std::floor(std::log10(widest)));
    float metres = decade;
    for (const float step : {2.0f, 5.0f})
    {
        if (step * decade <= widest)
        {
            metres = step * decade;
        }
    }
    bar.shown = true;
    bar.metres = metres;
    bar.pixels = metres * camera.pixelsPerMetre;
    const float margin = std::max(12.0f, 0.03f * static_cast<float>(camera.height));
    bar.from = b2Vec2(margin, static_cast<float>(camera.height) - margin);
    char label[32];
    if (metres >= 1.0f)
    {
        std::snprintf(label, sizeof label, "%g m", static_cast<double>(metres));
    }
    else if (metres >= 0.01f)
    {
        std::snprintf(label, sizeof label, "%g cm", std::round(static_cast<double>(metres) * 1000.0) / 10.0);
    }
    else if (metres >= 0.001f)
    {
        std::snprintf(label, sizeof label, "%g mm", std::round(static_cast<double>(metres) * 1e6) / 1000.0);
    }
    else // below a millimetre (--view down to 1e-6 m): in metres, with an exponent
    {
        std::snprintf(label, sizeof label, "%.0e m", static_cast<double>(metres));
    }
    bar.label = label;
    return bar;
}

const DrawList& BuildFrame(const Effects& effects, float time, const Camera& camera,
                           const FrameOptions& options, FrameScratch& scratch)
{
    DrawList& list = scratch.list;
    list.Begin(camera, options.style.background);
    list.backgroundBottom = options.style.backgroundBottom;
    ShapeRecorder recorder(list, options.style);
    RecordWorldShapes(effects, options.palette, recorder);
    CollectSprites(effects, scratch.sprites);
    AddParticles(list, scratch.sprites, options.style);
    list.shapesUnderSprites = list.shapes.size(); // the debug layers show over the particles
    AddDebugLayers(list, effects, scratch.sprites, options.debug, options.style);
    Overlay& overlay = list.overlay;
    if (options.scaleBar)
    {
        overlay.scaleBar = MakeScaleBar(camera);
    }
    if (!options.overlay)
    {
        return list;
    }
    overlay.shown = true;
    overlay.textSize = options.style.textSize;
    const std::vector<ParticleTypeDef>& types = effects.Config().particleTypes;
    overlay.legend.resize(types.size());
    for (std::size_t i = 0; i < types.size(); ++i)
    {
        overlay.legend[i].name = types[i].name;
        overlay.legend[i].color = types[i].colorStart;
        overlay.legend[i].count = 0;
    }
    for (const SpriteCommand& sprite : list.sprites) // on the image; glows have no type
    {
        if (sprite.type.IsValid() && sprite.type.index < overlay.legend.size())
        {
            ++overlay.legend[sprite.type.index].count;
        }
    }
    char title[64];
    std::snprintf(title, sizeof title, "t = %.2f s", static_cast<double>(time));
    overlay.title = options.caption.empty() ? std::string(title) : title + ("   " + options.caption);
    return list;
}

} // namespace cfx
