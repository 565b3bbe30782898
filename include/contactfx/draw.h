// contactfx: particles as they should look now, the input of the drawing layer.
//
// The core library knows neither Cairo nor OpenGL. As Dear ImGui's core produces draw data that its
// backends render, contactfx turns a world and its particles into a DrawList (contactfx/draw/): shapes
// come through Box2D's own b2Draw into a ShapeRecorder, particles as ParticleSprites from
// CollectSprites. The Cairo renderer (contactfx::render) and the testbed's OpenGL renderer render lists.
#pragma once

#include "contactfx/materials.h"
#include "contactfx/particle_types.h"

#include <box2d/b2_math.h>
#include <cstdint>
#include <vector>

namespace cfx
{

class Effects;

/// How a particle type is drawn, decided from its data by LookOf.
enum class SpriteLook : std::uint8_t
{
    puff,  ///< soft edges; it billows: drawn bigger and higher as it ages (smoke)
    grain, ///< a small solid disc with a dark rim, so it reads on any ground (dirt)
    spark, ///< a hot streak with a glow, cooling white -> yellow -> red over its life (sparks)
};

/// spark when the type draws streaks (streak > 0); puff when it grows (sizeEnd > sizeStart) or does not
/// fall (gravityScale <= 0); grain otherwise.
SpriteLook LookOf(const ParticleTypeDef& type);

/// One particle as it should look now.
struct ParticleSprite
{
    b2Vec2 position{0.0f, 0.0f}; ///< m, world
    b2Vec2 velocity{0.0f, 0.0f}; ///< m/s
    Color color;                 ///< alpha already follows life
    float size = 0.05f;          ///< m, drawn diameter
    float streak = 0.0f;         ///< s: draw a line covering this much of the motion; 0 for a round point
    ParticleTypeId type;
    SpriteLook look = SpriteLook::puff; ///< a sprite with streak > 0 is drawn as a spark whatever this says
    float life = 1.0f;                  ///< [0, 1]: 1 at its type's start, 0 when it dies
    float lifetime = 1.0f;              ///< s for life to fall from 1 to 0 (its type's), > 0
};

/// The live particles of `effects` as sprites, oldest first. Reuses `out`'s storage.
void CollectSprites(const Effects& effects, std::vector<ParticleSprite>& out);

} // namespace cfx
