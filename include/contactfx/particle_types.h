// contactfx: particle types are data.
//
// A particle type says how a particle starts (life, velocity from the two bodies plus spread), how it
// moves (gravity scale, drag), how it meets the world (radius, restitution, friction, collision filter),
// how it looks over its life (colour and size), and whether it is a light pool particle or a Box2D body
// (the tutorial's way, for particles that must push things). The smoke, sparks and dirt of the tutorial
// are three values of this struct (see presets.h).
#pragma once

#include <cstdint>
#include <string>

namespace cfx
{

/// Linear RGBA colour, each channel in [0, 1].
struct Color
{
    float r = 1.0f, g = 1.0f, b = 1.0f, a = 1.0f;
    bool operator==(const Color&) const = default;
};

/// How particles of a type are simulated.
enum class ParticleBackend : std::uint8_t
{
    pool, ///< a row in the particle pool, collides with the world by ray casts (default, fast)
    body, ///< a Box2D body with a circle fixture (the tutorial's way): pushes what it hits, costs more
};

/// What a particle's inherited and slip velocities are measured against (ParticleTypeDef::velocityFrame).
enum class VelocityFrame : std::uint8_t
{
    /// The surface's: start velocity = surface velocity + inheritA * (vA - surface velocity) + inheritB *
    /// (vB - surface velocity) + slipFactor * slip. What a body does over a moving surface (a conveyor, a
    /// grinding wheel, a truck's bed) looks as it does over a still one; over a still surface it is the
    /// same as `world`. The surface is the static or kinematic body's fixture, else the heavier body's, and
    /// the slip is the other's over it: a spinning wheel lighter than what it grinds throws along its rim
    /// at (1 - slipFactor) of the rim's speed instead of slipFactor (docs/design.md).
    surface,
    /// The world's, the tutorial's: start velocity = inheritA * vA + inheritB * vB + slipFactor * slip.
    world,
};

/// One particle type. Units: metres, seconds, kilograms. Validated when an Effects object is created; the
/// ranges keep the simulation finite and its cost bounded (docs/effects-config.md).
struct ParticleTypeDef
{
    std::string name; ///< unique, non-empty, no control characters

    // Life: 1 at birth at most, the particle dies at 0.
    /// Start life = clamp(lifeBase + lifeFromIntensity * intensity, 0, 1). The tutorial: 0 + 0.3 * I.
    float lifeBase = 1.0f;          ///< [0, 1]
    float lifeFromIntensity = 0.0f; ///< [0, 1000], per unit of intensity
    /// Seconds for life to fall from 1 to 0 (a particle starting at life 0.5 lives half of it). (0, 3600].
    float lifetime = 1.0f;

    // Start velocity = surface velocity + inheritA * (vA - surface velocity) + inheritB * (vB - surface
    // velocity) + slipFactor * (relative tangential velocity of the other body over the surface) +
    // normalSpeed * surface normal + U(-spread, spread) per axis (velocityFrame: world drops the surface
    // velocity terms). A and B are the bodies whose materials are the rule's materialA and materialB, all
    // velocities at the contact point; the surface is the static or kinematic body of the contact, else the
    // heavier one (docs/design.md).
    float inheritA = 0.0f;    ///< [-10, 10]: fraction of body A's velocity at the contact point
    float inheritB = 0.0f;    ///< [-10, 10]: fraction of body B's velocity at the contact point
    float slipFactor = 0.0f;  ///< [-10, 10]: fraction of the slip velocity (sparks along the scrape)
    float normalSpeed = 0.0f; ///< m/s away from the surface, [-1000, 1000]
    float spread = 0.0f;      ///< m/s, [0, 1000]: uniform random per axis in [-spread, spread]
    VelocityFrame velocityFrame = VelocityFrame::surface;

    // Motion.
    float gravityScale = 1.0f; ///< [-100, 100]: times the world's gravity; negative floats up
    float drag = 0.0f;         ///< 1/s, [0, 1000]: Box2D's linear damping, v *= 1 / (1 + dt * drag)

    // Collision with the world's fixtures (never with other particles).
    bool collide = true;
    float radius = 0.02f;     ///< m, [0.001, 10]
    float restitution = 0.3f; ///< [0, 1]: bounce
    /// m/s, [0, 1000]: a hit approaching the surface slower than this does not bounce (the particle comes to
    /// rest instead of jittering). Mixed with the fixture's restitution threshold by taking the smaller, as
    /// Box2D mixes two fixtures' (the body backend sets it as its fixtures' restitutionThreshold). At 0 every
    /// hit bounces: pool particles still come to rest (a touch within 0.1 mm is not a hit), Box2D bodies
    /// keep hopping by millimetres.
    float restSpeed = 0.5f;
    float friction = 0.5f;               ///< [0, 1000]: Coulomb friction on each hit
    std::uint16_t categoryBits = 0x0002; ///< like b2Filter: a fixture is hit when its maskBits has these
    std::uint16_t maskBits = 0x0001;     ///< ... and its categoryBits are in these
    /// m/s, [0, 1000]: a pool particle's touch counts as a hit (ParticleSystem::Hits, particle_hits
    /// events) when it approaches the surface at least this fast. The default leaves out resting particles
    /// (gravity alone brings them in at 0.16 to 0.33 m/s a step at 30 to 60 Hz).
    float hitSpeed = 1.0f;

    // Backend.
    ParticleBackend backend = ParticleBackend::pool;
    float density = 1.0f; ///< kg/m^2, (0, 1e6]; body backend only

    // Looks over life (life 1 -> start, life 0 -> end); the drawn opacity is colour alpha * life.
    Color colorStart{1.0f, 1.0f, 1.0f, 1.0f};
    Color colorEnd{1.0f, 1.0f, 1.0f, 1.0f};
    float sizeStart = 0.05f; ///< m, drawn diameter at birth, (0, 100]
    float sizeEnd = 0.05f;   ///< m, drawn diameter at death, (0, 100]
    /// s, [0, 10]: drawn as a line along the velocity covering this much of the motion (sparks); 0 draws
    /// a soft round point.
    float streak = 0.0f;

    bool operator==(const ParticleTypeDef&) const = default;
};

/// What a particle of `type` looks like at `life` in [0, 1].
struct ParticleLook
{
    Color color; ///< alpha already multiplied by life
    float size;  ///< m, drawn diameter
};
ParticleLook LookAt(const ParticleTypeDef& type, float life);

} // namespace cfx
