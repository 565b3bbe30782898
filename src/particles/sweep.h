// contactfx internal: where a moving disc first touches a shape.
//
// A pool particle is a disc of radius r moving in a straight line from p to p + d during one step. It
// touches a shape where its centre meets the shape grown by r, so every test here is a ray cast against
// the grown shape: a segment becomes a capsule, a circle a larger circle, a convex polygon a rounded
// polygon. A disc that already overlaps a shape at p gets a touch at t = 0 that pushes it out along the
// shortest way, so nothing stays inside. One-sided segments (Box2D 2.4 chains, one-sided edges) are only
// solid for a disc that starts in front of them (on the side their normal points to), as in Box2D.
//
// Shapes are given in the frame of p and d (world for static geometry, body-local for moving bodies).
// Polygons are their core (Box2D's skin radius is not added), so a particle rests exactly r above it.
// Pure functions of their arguments: safe from any thread, and the same inputs give the same bits.
#pragma once

#include <box2d/b2_math.h>

namespace cfx::particles
{

/// A disc this close inside a surface (m) counts as touching it, not overlapping: a particle resting or
/// sliding at exactly its radius from a surface must not be pushed out (and stopped) by rounding.
inline constexpr float kTouchSlop = 1.0e-4f;

/// The motion of one disc over one step.
struct SweepInput
{
    b2Vec2 p;     ///< start of the centre
    b2Vec2 d;     ///< motion of the centre over the step (m)
    float radius; ///< > 0
};

/// The best touch found so far. A touch is better when it comes earlier; among overlaps at t = 0, the
/// deeper one wins. `t` starts above 1: nothing touched yet.
struct Touch
{
    float t = 2.0f;              ///< fraction of d at first touch, [0, 1]; 0 when overlapping at p
    float depth = 0.0f;          ///< overlap only: how far the disc is pushed out (m)
    b2Vec2 normal{0.0f, 0.0f};   ///< unit, from the surface towards the disc's centre
    b2Vec2 position{0.0f, 0.0f}; ///< the centre at the touch (pushed out when overlapping)

    bool Found() const { return t <= 1.0f; }
};

/// A segment from v1 to v2. `normal` is the unit right-hand normal of v1 -> v2 (Box2D's convention);
/// `invLengthSq` is 1 / |v2 - v1|^2. A one-sided segment is solid only from the side `normal` points to.
struct Segment
{
    b2Vec2 v1, v2, normal;
    float invLengthSq;
    bool oneSided;
};

/// Makes a segment from its two ends (they must differ).
Segment MakeSegment(b2Vec2 v1, b2Vec2 v2, bool oneSided);

/// Each updates `best` when the disc touches the shape earlier (or deeper) than `best`; returns whether
/// it did.
bool SweepSegment(const SweepInput& in, const Segment& segment, Touch& best);
bool SweepCircle(const SweepInput& in, b2Vec2 center, float radius, Touch& best);
/// A convex polygon, counter-clockwise, with Box2D's outward unit edge normals (normals[i] belongs to
/// the edge vertices[i] -> vertices[i + 1]).
bool SweepPolygon(const SweepInput& in, const b2Vec2* vertices, const b2Vec2* normals, int count,
                  Touch& best);

/// The surface a disc touched, for the bounce.
struct SurfaceResponse
{
    b2Vec2 velocity{0.0f, 0.0f}; ///< of the surface at the touch point (m/s)
    float restitution = 0.0f;    ///< mixed: max of particle and fixture (Box2D's b2MixRestitution)
    float friction = 0.0f;       ///< mixed: sqrt of the product (Box2D's b2MixFriction)
    float restSpeed = 0.0f;      ///< below this approach speed (m/s) nothing bounces
};

/// Coulomb friction on a slide of length `slide` (>= 0; m, or m/s) that takes up to `held` (>= 0) of it,
/// never reversing it: the part of the slide that is left, 0..1.
inline float SlideLeft(float slide, float held)
{
    return slide > held ? (slide - held) / slide : 0.0f;
}

/// The velocity after touching. `velocity` is the step's (all of its gravity); `touchSpeed` (m/s) is the
/// speed at which the particle approached the surface at the moment of the touch, before the gravity of
/// the rest of the step (see TouchApproachSpeed). Relative to the surface, the approaching normal part is
/// removed and replaced by a bounce of restitution times `touchSpeed`, or none when `touchSpeed` is at
/// most the rest speed; the tangential part loses Coulomb friction times the whole normal change (the
/// surface also holds the particle against the gravity after the touch), never reversing. A velocity
/// leaving the surface is kept. With `touchSpeed` equal to the step velocity's own approach speed this is
/// the plain reflection.
b2Vec2 Respond(b2Vec2 velocity, float touchSpeed, b2Vec2 normal, const SurfaceResponse& surface);

} // namespace cfx::particles
