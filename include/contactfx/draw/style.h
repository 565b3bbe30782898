// contactfx drawing layer: how things look beyond their own colours.
//
// The style is read when a DrawList is built (background gradient, fill shade, outline widths, smallest
// sprite, how sparks glow, puffs billow and grains stand out, text size), so every backend that renders
// the list shows the same look; backends have no style of their own.
#pragma once

#include "contactfx/particle_types.h"

namespace cfx
{

struct DrawStyle
{
    Color background{0.06f, 0.07f, 0.10f, 1.0f};       ///< top of the image; dark, so sparks and smoke read
    Color backgroundBottom{0.13f, 0.15f, 0.20f, 1.0f}; ///< bottom of the image: a vertical gradient
    float fillShade = 0.38f;                           ///< shapes are filled with colour * fillShade, [0, 1]
    float outlineWidth = 1.5f;                         ///< px, outline of shapes in their full colour, >= 0
    float minSpriteSize = 2.0f;                        ///< px: smaller particles are drawn this big
    float textSize = 0.0f;                             ///< px of the overlay's text; 0: from the image height

    // Particle looks (SpriteLook).
    float glowSize = 5.0f;     ///< a spark's glow, diameter in streak thicknesses, >= 0; 0: no glow
    float glowOpacity = 0.3f;  ///< [0, 1]: the glow's opacity at its middle, times the spark's
    float puffGrowth = 1.0f;   ///< >= 0: a puff is drawn (1 + puffGrowth * (1 - life)) times its size
    float puffRise = 0.5f;     ///< m/s, >= 0: a puff is drawn this fast times its age above where it is
    float minGrainSize = 4.0f; ///< px: grains are drawn at least this big (rim included)
    float grainRim = 1.0f;     ///< px, >= 0: the dark rim around a grain
    float grainLift = 0.25f;   ///< [0, 1]: a grain's colour is moved this far towards white
};

} // namespace cfx
