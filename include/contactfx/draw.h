// contactfx: the one drawing interface between simulation and pictures.
//
// Shapes, joints and the like come through Box2D's own b2Draw (b2World::DebugDraw); particles come
// through ParticleDraw as one batch per frame. The core library knows neither Cairo nor OpenGL: the
// Cairo renderer (contactfx::render) and the testbed's OpenGL renderer implement these, as Dear ImGui's
// core produces draw data that its backends render.
#pragma once

#include "contactfx/materials.h"
#include "contactfx/particle_types.h"

#include <box2d/b2_math.h>
#include <span>
#include <vector>

namespace cfx
{

class Effects;

/// One particle as it should look now.
struct ParticleSprite
{
    b2Vec2 position{0.0f, 0.0f}; ///< m, world
    b2Vec2 velocity{0.0f, 0.0f}; ///< m/s
    Color color;                 ///< alpha already follows life
    float size = 0.05f;          ///< m, drawn diameter
    float streak = 0.0f;         ///< s: draw a line covering this much of the motion; 0 for a round point
    ParticleTypeId type;
};

/// Implemented by renderers.
class ParticleDraw
{
public:
    virtual ~ParticleDraw() = default;
    /// Draws every sprite of a frame, oldest first. Called once per frame.
    virtual void DrawParticles(std::span<const ParticleSprite> sprites) = 0;
};

/// The live particles of `effects` as sprites, oldest first. Reuses `out`'s storage.
void CollectSprites(const Effects& effects, std::vector<ParticleSprite>& out);

} // namespace cfx
