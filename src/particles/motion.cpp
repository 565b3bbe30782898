// contactfx internal: the particle step loop (see motion.h).
//
// A pool particle's step: gravity and drag change its velocity; then up to two sweeps against the static
// geometry (the second continues with what is left of the step after a bounce, so particles slide
// instead of stopping at every touch of the ground); then one sweep against moving bodies in their own
// frames from where the particle was at the start of the step to where it is now.
//
// Most particles are far from all geometry most of the time, and most of the rest are resting on it.
// Each particle carries its clearance: how far its centre can move before its disc can touch a static
// primitive (a lower bound, from the last time it was near geometry). A step that moves it less than
// that is a free flight, exactly what the sweep would have given, and costs a subtraction; so a particle
// in the air pays for a grid query only every so often instead of every step. The loop runs in blocks:
// pass 1 flies every particle of the block and lists those whose flight used up their clearance (or
// that are resting, or whose path meets a moving body's bounds); pass 2 puts the resting ones back and
// sweeps the others through the geometry, measuring their new clearance. Whether a particle is listed, or
// rests, is as good as random from one particle to the next, so both passes sort them without a branch;
// the block keeps both passes in cache.
#include "particles/motion.h"

#include <array>
#include <bit>
#include <box2d/b2_body.h>
#include <cmath>
#include <limits>

namespace cfx::particles
{

namespace
{

constexpr int kStaticSweeps = 2;
// A push's: a push along the ground may first meet where two of its pieces join (on a finely split ground
// a push of a few centimetres starts on a joint: the corner tilts it by a rounding, then the surface takes
// that tilt off), and still has its way along the ground to go.
constexpr int kPushSweeps = 4;

// Particles per block: pass 2's list lives on the stack.
constexpr std::uint32_t kBlock = 64;

// Special clearances (see PoolArrays). A resting particle's: (position, zero velocity) is a fixed point of
// the static sweep; it stays below zero however far it moves, so pass 1 lists it. Nothing to touch: the
// particle does not sweep (it does not collide, or is body-backed), or there is no static geometry.
// Clearances hold only while the static geometry stays the same; when it changes (or particles moved
// without collision), pass 1 lists every particle that sweeps.
constexpr float kResting = -std::numeric_limits<float>::infinity();
constexpr float kNothingToTouch = std::numeric_limits<float>::infinity();

// Whether a clearance (as pass 1 leaves it, a step's flight taken off) marks a particle spawned since the
// last step (kSpawnedClearance; a resting particle's -infinity is below it too).
bool SpawnedMark(float mark)
{
    return mark <= kSpawnedClearance && mark != kResting;
}

// `mask` all ones: a, else b; without a branch.
float Select(std::uint32_t mask, float a, float b)
{
    return std::bit_cast<float>((std::bit_cast<std::uint32_t>(a) & mask) |
                                (std::bit_cast<std::uint32_t>(b) & ~mask));
}

bool SameBits(b2Vec2 a, b2Vec2 b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// At least |d| and at most 1.083 |d|, without a square root: the larger component plus tan(pi / 8)
// times the smaller (a regular octagon around the circle).
float StepLengthBound(b2Vec2 d)
{
    const float x = std::abs(d.x);
    const float y = std::abs(d.y);
    return std::max(x, y) + 0.41422f * std::min(x, y);
}

SurfaceResponse Mix(const ParticleSide& side, const SurfaceMaterial& material, b2Vec2 surfaceVelocity)
{
    SurfaceResponse response;
    response.velocity = surfaceVelocity;
    response.restitution = side.restitution > material.restitution ? side.restitution : material.restitution;
    response.friction = b2MixFriction(side.friction, material.friction);
    response.restSpeed = side.restSpeed < material.restSpeed ? side.restSpeed : material.restSpeed;
    return response;
}

// What a push has met so far.
struct PushState
{
    const b2Body* notAWall; ///< the pusher, until a wall turns the push into it (then null)
    /// The pusher's surface normal (world) where the current piece of the push ends, on the particle's way
    /// with the body (`alongTheBody`); unused otherwise.
    b2Vec2 pusherNormal;
    /// The push follows the particle's way with the body, on its surface: a wall turning it away from that
    /// surface leaves the pusher no wall. Otherwise (a straight push from where the flight ended, which may
    /// cut through the pusher) any turn makes it one.
    bool alongTheBody;
    bool metMoving = false; ///< a moving body stopped it (another one, or the pusher once a wall turned it)
};

// A moving body pushes a particle from `position` (outside all static geometry) towards `target` (near the
// body's surface), from time `from` of the step (0..1; 1: from where the flight ended). The push is a
// motion like any other: it is swept through the static geometry, sliding along what it meets (up to
// kPushSweeps times, the rest of the push is dropped), so it never carries the particle into or through a
// static fixture. Another moving body stops it as a wall does, met as it moves over the rest of the step: a
// push goes through no body (a box pushing a spark into the plank it lands on, a plank rising through where a
// spark met a box). So does the pusher once a wall turned the push (a wheel on the ground: along the ground,
// not under the wheel); a push along the particle's way with the body that the wall turns away from its
// surface (a box the ground's joints tilt pushes a ball forward and a little down: along the ground ahead of
// it) is still the pusher's (PushState::alongTheBody). Returns whether the push got through: to `target`,
// or sliding along what it met (a ball the wheel carries along the ground), so that the next piece of the
// way goes on from there; false when it ran out of sweeps (wedged) with push left.
bool PushToward(const WorldGeometry& geometry, const ParticleSide& side, b2Vec2 target, float from,
                PushState& state, b2Vec2& position)
{
    b2Vec2 push = target - position;
    for (int sweep = 0; sweep < kPushSweeps && (push.x != 0.0f || push.y != 0.0f); ++sweep)
    {
        SweepResult wall;
        const bool metStatic =
            geometry.HasStatic() && geometry.SweepStatic(SweepInput{position, push, side.radius}, side, wall);
        SweepResult other;
        if (geometry.SweepMoving(position, position + push, side, from, other, state.notAWall) &&
            (!metStatic || other.touch.t < wall.touch.t))
        {
            wall.touch.t = other.touch.t;
            wall.touch.position = other.firstTouch;
            wall.touch.normal = other.touch.normal;
            state.metMoving = true;
        }
        else if (!metStatic)
        {
            position += push;
            return true;
        }
        const bool moved = !SameBits(wall.touch.position, position);
        position = wall.touch.position;
        from += wall.touch.t * (1.0f - from);
        // Slide: what is left of the push, less its part into the wall.
        const b2Vec2 rest = (1.0f - wall.touch.t) * push;
        const float into = b2Dot(rest, wall.touch.normal);
        push = into < 0.0f ? rest - into * wall.touch.normal : rest;
        if (!moved && wall.touch.t == 0.0f && into >= 0.0f)
        {
            break; // nothing changed: every sweep left would meet the same touch (a particle wedged in place)
        }
        // Turned by more than a rounding (a grain pushed along the ground touches it all the way), and into
        // the pusher's surface if the push follows the particle's way with it.
        const bool intoPusher =
            into < -kTouchSlop && (!state.alongTheBody || b2Dot(push, state.pusherNormal) < -kTouchSlop);
        state.notAWall = intoPusher ? nullptr : state.notAWall;
    }
    return false;
}

// Whether a pushed particle at `position` has a free place there. Not when it still overlaps a moving
// fixture by more than half its radius: squeezed with no free place, it is crushed. Nor when it went
// through the body: it ends more than half its radius behind `placement` (where the body put it, on its
// surface, and that surface's normal there, at the end of the step), and a moving body passed over where it
// ends (a thin plate rising fast into a ceiling leaves the particle held under the ceiling below it). A
// push to `placement` itself that no wall stops ends on it, never behind. `spawned`: the particle was put
// where it started after the bodies moved (they did not pass over anything of it).
bool PushedFree(const WorldGeometry& geometry, const ParticleSide& side, const Touch& placement, bool spawned,
                b2Vec2 position)
{
    // Pushed out of one body, it may now be in another (a pile), or still in this one (a wedge).
    if (geometry.MovingOverlapsDeeper(position, side, 0.5f * side.radius))
    {
        return false;
    }
    // Behind the surface it met: on the body's far side, or under it (caught between it and a wall).
    // Whether the body went over it, or it over the body: only the first leaves it there with no way out.
    const bool behind = b2Dot(position - placement.position, placement.normal) < -0.5f * side.radius;
    return spawned || !behind || !geometry.MovingPassesOver(position, side);
}

// Whether a disc at `position` overlaps a static shape by more than half its radius.
bool StaticOverlapsDeeper(const WorldGeometry& geometry, const ParticleSide& side, b2Vec2 position)
{
    SweepResult inside;
    return geometry.SweepStatic(SweepInput{position, b2Vec2(0.0f, 0.0f), side.radius}, side, inside) &&
           inside.touch.t == 0.0f && inside.touch.depth > 0.5f * side.radius;
}

// Where a moving body's push took a particle from, for the particle check (PoolArrays::viaX,
// PoolArrays::pushFraction).
struct PushedFrom
{
    b2Vec2 flown{0.0f, 0.0f}; ///< where its flight ended (after the static sweeps)
    float fraction = 1.0f;    ///< where along the flight the push began
    bool pushed = false;
};

// What a particle's mark says of its motion against the static geometry this step.
enum class StaticPart : std::uint8_t
{
    sweep,   ///< nothing known: sweep it
    resting, ///< trusted to rest: it stays where it is, at rest (the sweep would give the same bits)
    clear,   ///< its clearance covers the step: it flies freely (the sweep would give the same bits)
};

// The hardest touch of a particle's step so far.
struct Hardest
{
    float speed = 0.0f; ///< approach speed (m/s); 0: no touch approached the surface
    b2Vec2 point{0.0f, 0.0f};
    const b2Body* body = nullptr;
};

// The speed (m/s) at which a particle approached the surface of `hit` at the moment of the touch: the
// step's `velocity` has all of the step's gravity, but at the touch the particle had only that of the part
// of the step before it, so the gravity of the part after it (`afterTouch`, 0..1 of the step) is taken
// off. A particle resting on a surface touches it at the start of the step and approaches at 0 m/s, however
// long the step. Positive when approaching.
float TouchApproachSpeed(const SweepResult& hit, b2Vec2 velocity, float afterTouch, const TypeStep& type)
{
    const b2Vec2 atTouch = velocity - afterTouch * type.restVelocity;
    return -b2Dot(atTouch - hit.surfaceVelocity, hit.touch.normal);
}

// Keeps `hit` in `hardest` when the particle approached its surface at `speed` (see TouchApproachSpeed),
// faster than at any earlier touch of the step.
void KeepHarder(const SweepResult& hit, float speed, const TypeStep& type, Hardest& hardest)
{
    if (speed > hardest.speed)
    {
        hardest.speed = speed;
        hardest.point = hit.touch.position - type.side.radius * hit.touch.normal;
        hardest.body = hit.material->body;
    }
}

// Bounces `velocity` off the surface of `hit`, approached at `touchSpeed` (see Respond).
b2Vec2 Bounce(const SweepResult& hit, b2Vec2 velocity, float touchSpeed, const TypeStep& type)
{
    return Respond(velocity, touchSpeed, hit.touch.normal,
                   Mix(type.side, *hit.material, hit.surfaceVelocity));
}

// Sweeps a particle whose velocity has had this step's gravity and drag, from `position`. `part`: what
// its mark says; `mark`: that mark, what is left of its clearance after this step's flight. Returns its
// clearance after the step (see PoolArrays): kResting at a fixed point of the static sweep,
// kUnknownClearance after a touch. `crushed`: set when a moving body squeezed it against other geometry
// with no free place (see PushedFree), or when the static sweeps leave it more than half its radius inside a
// static shape (it started in two at once). `hardest`: its hardest touch of the step. `pushedFrom` (null
// unless the particle check is on): set when a moving body pushed it, to where its flight ended (after the
// static sweeps) and where along the flight the push began; left as it was when nothing pushed it. A
// pointer, not a value: the common path keeps nothing more alive (a value in a register cost the debris
// scene 3 %).
float Collide(const TypeStep& type, const WorldGeometry& geometry, float dt, StaticPart part, float mark,
              b2Vec2& position, b2Vec2& velocity, bool& crushed, Hardest& hardest, PushedFrom* pushedFrom)
{
    const b2Vec2 start = position;
    const b2Vec2 stepVelocity = velocity;
    // The velocity every particle at rest enters the step with: then the next step repeats this one.
    const bool fromRest = SameBits(velocity, type.restVelocity);
    float staticReach2 = 0.0f; // squared distance from start to the first static touch (0: none)
    float clearance = kUnknownClearance;
    bool fixedPoint = false;
    bool touched = false;
    // A static touch bent its path: anything but a slide from the start (a particle on the ground); and the
    // squared distance from the start to where it first bent (the path is straight up to there).
    bool bent = false;
    float bendReach2 = 0.0f;
    if (part == StaticPart::resting)
    {
        velocity.SetZero();
        fixedPoint = true;
    }
    else if (part == StaticPart::clear)
    {
        position += dt * velocity; // as pass 1 flew it
        clearance = mark;
    }
    else if (geometry.HasStatic())
    {
        float remaining = dt;
        float left = 1.0f;        // remaining / dt, without a division
        bool startedDeep = false; // a sweep began deep inside a static shape
        for (int sweep = 0; sweep < kStaticSweeps; ++sweep)
        {
            const SweepInput in{position, remaining * velocity, type.side.radius};
            if (sweep > 0 && in.d.x == 0.0f && in.d.y == 0.0f)
            {
                break; // stopped by the first touch: nothing left to sweep
            }
            SweepResult hit;
            // The first sweep also measures the clearance, should the particle fly freely.
            if (!geometry.SweepStatic(in, type.side, hit, sweep == 0 ? &clearance : nullptr))
            {
                position += in.d;
                break;
            }
            staticReach2 = touched ? staticReach2 : b2DistanceSquared(hit.touch.position, start);
            const bool bends = sweep > 0 || hit.touch.t > 0.0f;
            bendReach2 = !bent && bends ? b2DistanceSquared(hit.touch.position, start) : bendReach2;
            bent = bent || bends;
            touched = true;
            startedDeep = startedDeep || (hit.touch.t == 0.0f && hit.touch.depth > 0.5f * type.side.radius);
            position = hit.touch.position;
            left *= 1.0f - hit.touch.t; // now the part of the step after the touch
            const float touchSpeed = TouchApproachSpeed(hit, velocity, left, type);
            KeepHarder(hit, touchSpeed, type, hardest);
            velocity = Bounce(hit, velocity, touchSpeed, type);
            remaining *= 1.0f - hit.touch.t;
        }
        // Bit for bit, so that skipping the sweep of a resting particle gives exactly what it would have.
        fixedPoint = fromRest && SameBits(position, start) && SameBits(velocity, b2Vec2(0.0f, 0.0f));
        // Pushed out of one static shape it may be in another (a slab created over it, a slit between
        // two boxes), or through a thin ground (a slab created over it on an edge or a chain pushes it out
        // downwards): still deep inside after the sweeps, or across an edge, it has no free place and is
        // crushed.
        if (startedDeep && (StaticOverlapsDeeper(geometry, type.side, position) ||
                            geometry.CrossesStaticSegment(start, position, type.side)))
        {
            crushed = true;
            return kUnknownClearance;
        }
    }
    else
    {
        position += dt * velocity;
        clearance = kNothingToTouch; // until some static geometry is built
    }
    if (geometry.HasMoving())
    {
        SweepResult hit;
        const bool spawned = SpawnedMark(mark);
        if (geometry.SweepMoving(start, position, type.side, spawned ? 1.0f : 0.0f, hit))
        {
            // Where the body would put it, pushed there. First from where and when the flight met the
            // body: from the touch on the particle went with the body, so the rest of its flight (through
            // another moving body, say) never happened. That point is on the chord from the start to where
            // the static sweeps left the particle: on its path (a slide along the ground too), unless a
            // static touch bent the path before it (a ball sliding down a slope into a wheel's gap: the
            // flight ends beyond the wheel, the touch is at its start). When that push leaves it squeezed,
            // from where the flight ended (outside the static geometry: a particle flown past an edge's end
            // and pushed down beyond it goes around the end), if the flight met no other moving body after
            // the touch; failing that too (a wedge), back to where it met the body. Stopped by a moving body
            // on the way (another, or the pusher after a wall turned the push), it was squeezed: when a
            // moving body went on over where it was left (a plank turning through a spark a box had pushed
            // against it, a box sliding over a spark in the gap under it), it went through it.
            const b2Vec2 free = position;
            const bool bentBefore =
                bent && hit.touch.t * hit.touch.t * b2DistanceSquared(free, start) >= bendReach2;
            struct Attempt
            {
                b2Vec2 from;
                float time; // when in the step the push begins (0..1)
                b2Vec2 to;
            };
            const Attempt attempts[] = {{hit.firstTouch, hit.touchTime, hit.touch.position},
                                        {free, 1.0f, hit.touch.position},
                                        {free, 1.0f, hit.firstTouch}};
            const b2Body* pusher = hit.material->body;
            for (int k = bentBefore ? 1 : 0; k < 3; ++k)
            {
                const Attempt& attempt = attempts[k];
                SweepResult other;
                if (k == 1 && !bentBefore)
                {
                    if (geometry.SweepMoving(hit.firstTouch, free, type.side, attempts[0].time, other,
                                             pusher))
                    {
                        break; // crushed: the flight's end is beyond another moving body
                    }
                    if (b2DistanceSquared(free, hit.firstTouch) <= kTouchSlop * kTouchSlop)
                    {
                        // No flight after the touch: the same push again, but along a chord instead of the
                        // way with the body; across a turning wheel's rim, from a wedge it stopped in, under
                        // the wheel.
                        continue;
                    }
                }
                position = attempt.from;
                if (pushedFrom != nullptr)
                {
                    *pushedFrom = PushedFrom{free, k == 0 ? hit.touch.t : 1.0f, true};
                }
                // The push from the touch follows the particle's way with the body: an arc, in pieces, when
                // the body turns (a roller carries it around its rim, not along a chord through the next).
                const int pieces = k == 0 ? geometry.CarryPieces(hit) : 1;
                PushState state{pusher, hit.touch.normal, k == 0};
                float pieceFrom = attempt.time;
                for (int piece = 1; piece <= pieces; ++piece)
                {
                    const float f = piece == pieces
                                        ? 1.0f
                                        : attempt.time + (1.0f - attempt.time) * static_cast<float>(piece) /
                                                             static_cast<float>(pieces);
                    const WorldGeometry::CarriedDisc waypoint =
                        piece == pieces ? WorldGeometry::CarriedDisc{attempt.to, hit.touch.normal}
                                        : geometry.Carried(hit, f);
                    // The pusher's surface where this piece ends: a wheel turning 2 rad a step turns it too.
                    state.pusherNormal = waypoint.normal;
                    if (!PushToward(geometry, type.side, waypoint.position, pieceFrom, state, position))
                    {
                        break; // wedged: the rest of the way is not the body's to give
                    }
                    pieceFrom = f;
                }
                crushed = !PushedFree(geometry, type.side, hit.touch, spawned, position) ||
                          (state.metMoving && geometry.MovingPassesOver(position, type.side, attempt.time));
                if (!crushed)
                {
                    break;
                }
            }
            // Met the body before any static geometry (a long step on a particle resting on a box that
            // stands on the ground sweeps it through the box to the ground): the static touches are on the
            // far side of the body and never happened.
            if (hit.touch.t * hit.touch.t * b2DistanceSquared(free, start) < staticReach2)
            {
                velocity = stepVelocity;
                hardest = Hardest{};
            }
            const float touchSpeed = TouchApproachSpeed(hit, velocity, 1.0f - hit.touch.t, type);
            KeepHarder(hit, touchSpeed, type, hardest);
            velocity = Bounce(hit, velocity, touchSpeed, type);
            fixedPoint = false;
            touched = true;
        }
    }
    return fixedPoint ? kResting : touched ? kUnknownClearance : clearance;
}

// The particles pass 1 lists, as arrays: filled one entry per particle without a branch, and a struct
// entry would be assembled on the stack and copied (a stalled store-to-load forward every particle).
struct Listed
{
    std::array<std::uint32_t, kBlock> slot;
    std::array<float, kBlock> startX, startY; ///< where it was at the start of the step
};

// Pass 2: sweeps the listed particles through the geometry, in place, and measures their clearance.
// Pass 1 left in each slot the particle's velocity after gravity and drag and what remains of its
// clearance (kResting when it rests). With `hits`, appends the hit of each swept particle whose hardest
// touch reached its type's hitSpeed (not of one that died in the step).
void SweepListed(const PoolArrays& pool, const TypeStep* types, const WorldGeometry& geometry, float dt,
                 const StepTrust& trust, const Listed& listed, std::uint32_t count, StepCounts& counts,
                 HitSink* hits)
{
    // A particle trusted to rest stays where it started, at rest. Whether a listed particle rests is as
    // good as random, so they are put back without a branch and only the others are swept on (all of
    // them when there are moving shapes, which may still meet a resting particle).
    std::array<std::uint32_t, kBlock> toSweep;
    std::uint32_t sweepCount = 0;
    const std::uint32_t sweepResting = geometry.HasMoving() ? 1u : 0u;
    for (std::uint32_t k = 0; k < count; ++k)
    {
        const std::uint32_t slot = listed.slot[k];
        const std::uint32_t rests = (trust.resting & (pool.clearance[slot] == kResting)) ? 1u : 0u;
        const std::uint32_t mask = 0u - rests;
        pool.positionX[slot] = Select(mask, listed.startX[k], pool.positionX[slot]);
        pool.positionY[slot] = Select(mask, listed.startY[k], pool.positionY[slot]);
        pool.velocityX[slot] = Select(mask, 0.0f, pool.velocityX[slot]);
        pool.velocityY[slot] = Select(mask, 0.0f, pool.velocityY[slot]);
        toSweep[sweepCount] = k;
        sweepCount += (rests ^ 1u) | sweepResting;
    }
    for (std::uint32_t j = 0; j < sweepCount; ++j)
    {
        const std::uint32_t k = toSweep[j];
        const std::uint32_t slot = listed.slot[k];
        const TypeStep& type = types[pool.type[slot]];
        if (!type.sweeps)
        {
            // Listed only because its clearance was unknown (just spawned): it never meets anything,
            // and pass 1 moved it.
            pool.clearance[slot] = kNothingToTouch;
            continue;
        }
        // Listed for a moving body's sake only, it may still be clear of the static geometry. Spawned
        // before the bodies moved, it is swept as if it had been there all along.
        const float stored = pool.clearance[slot];
        const float mark = SpawnedMark(stored) && !trust.spawnsAfterMoving ? kUnknownClearance : stored;
        const StaticPart part = trust.resting && mark == kResting ? StaticPart::resting
                                : trust.clearance && mark >= 0.0f ? StaticPart::clear
                                                                  : StaticPart::sweep;
        b2Vec2 position(listed.startX[k], listed.startY[k]);
        b2Vec2 velocity(pool.velocityX[slot], pool.velocityY[slot]);
        bool crushed = false;
        Hardest hardest;
        const bool checking = pool.viaX != nullptr;
        PushedFrom pushedFrom;
        const float clearance = Collide(type, geometry, dt, part, mark, position, velocity, crushed, hardest,
                                        checking ? &pushedFrom : nullptr);
        if (checking)
        {
            // As Collide took it.
            pool.stepFlags[slot] = static_cast<std::uint8_t>((SpawnedMark(mark) ? kPlacedAfterFlag : 0) |
                                                             (pushedFrom.pushed ? kPushedFlag : 0));
            if (pushedFrom.pushed)
            {
                pool.viaX[slot] = pushedFrom.flown.x;
                pool.viaY[slot] = pushedFrom.flown.y;
                pool.pushFraction[slot] = pushedFrom.fraction;
            }
        }
        if (!Sane(position) || !Sane(velocity))
        {
            // A surface's numbers threw it out of the world (a restitution of 1e30): it dies where it
            // started, and the next step removes it.
            position = b2Vec2(listed.startX[k], listed.startY[k]);
            crushed = false;
            pool.life[slot] = 0.0f;
            velocity.SetZero();
            ++counts.nonFinite;
        }
        else if (hits != nullptr && !crushed && hardest.speed >= type.hitSpeed && hardest.speed > 0.0f)
        {
            hits->hits[hits->count++] =
                ParticleHit{hardest.body, hardest.speed, hardest.point.x, hardest.point.y, pool.type[slot]};
        }
        if (crushed)
        {
            // Dies where it was squeezed (outside the static geometry): life 0 draws nothing, and the
            // next step removes it.
            pool.life[slot] = 0.0f;
            velocity.SetZero();
            ++counts.crushed;
        }
        pool.positionX[slot] = position.x;
        pool.positionY[slot] = position.y;
        pool.velocityX[slot] = velocity.x;
        pool.velocityY[slot] = velocity.y;
        pool.clearance[slot] = clearance;
    }
}

// Pass 1 over `count` particles from `read` (one block): age, gravity and drag, and a free flight for
// all; those whose flight may have met geometry are listed for pass 2, which redoes their motion from
// `start`. The dead are squeezed out as the loop goes (the living are written from `write` on).
// `kCollide`: geometry is given; `kMoving`: it has moving shapes; `kDistrust`: the clearances do not hold.
template <bool kCollide, bool kMoving, bool kDistrust>
std::uint32_t FlyBlock(const PoolArrays& pool, const TypeStep* types, float dt, const b2AABB& movingBounds,
                       std::uint32_t& read, std::uint32_t& write, std::uint32_t count, Listed& listed,
                       std::uint32_t& listedCount, std::vector<b2Body*>& deadBodies, StepCounts& counts)
{
    // The dead are counted rather than the living: a counter touched every particle ends up in memory
    // when registers run short, and its load-add-store then paces the whole loop.
    std::uint32_t dead = 0;
    std::uint32_t n = 0;
    for (std::uint32_t i = 0; i < count; ++i)
    {
        const TypeStep& type = types[pool.type[read]];
        const float life = pool.life[read] - type.lifeLoss;
        const b2Vec2 start(pool.positionX[read], pool.positionY[read]);
        b2Vec2 position = start;
        b2Vec2 velocity(pool.velocityX[read], pool.velocityY[read]);
        float clearance = kNothingToTouch;
        if (type.bodyBacked)
        {
            const b2Body* body = pool.body[read];
            position = body->GetPosition();
            velocity = body->GetLinearVelocity();
        }
        else
        {
            velocity.x = (velocity.x + type.gravityDelta.x) * type.damping;
            velocity.y = (velocity.y + type.gravityDelta.y) * type.damping;
            const b2Vec2 d(dt * velocity.x, dt * velocity.y);
            position.x += d.x;
            position.y += d.y;
            if constexpr (kCollide)
            {
                // The move as the floats made it, not as meant: far from the origin rounding moves a
                // particle by up to half a float's spacing more than d, step after step (at 40 km, 1 cm
                // particles crept through a ground on their clearance).
                clearance = pool.clearance[read] - StepLengthBound(position - start);
            }
        }
        bool isNear = false;
        if constexpr (kCollide)
        {
            isNear = kDistrust ? type.sweeps : clearance < 0.0f;
            if constexpr (kMoving)
            {
                isNear = isNear | (type.sweeps &
                                   BoxesOverlap(PathBox(start, position, type.side.radius), movingBounds));
            }
        }
        const bool sane = Sane(position);
        if ((life > 0.0f) & sane)
        {
            pool.positionX[write] = position.x;
            pool.positionY[write] = position.y;
            pool.velocityX[write] = velocity.x;
            pool.velocityY[write] = velocity.y;
            pool.life[write] = life;
            pool.type[write] = pool.type[read];
            if (pool.startX != nullptr)
            {
                pool.startX[write] = start.x;
                pool.startY[write] = start.y;
                pool.viaX[write] = start.x; // a straight flight; pass 2 notes a push
                pool.viaY[write] = start.y;
                pool.stepFlags[write] = 0; // pass 2 notes a push, and a spawn taken as placed after
            }
            if (pool.body != nullptr)
            {
                pool.body[write] = pool.body[read];
            }
            if constexpr (kCollide)
            {
                // Without collision the clearances go stale (and even out of step with their particles
                // as the dead are squeezed out); the next step distrusts them all.
                pool.clearance[write] = clearance;
                listed.slot[n] = write;
                listed.startX[n] = start.x;
                listed.startY[n] = start.y;
                n += isNear ? 1 : 0;
            }
            write = write + 1 == pool.capacity ? 0 : write + 1;
        }
        else
        {
            ++dead;
            counts.nonFinite += life > 0.0f ? 1u : 0u; // alive, but not anywhere a simulation can be
            if (type.bodyBacked)
            {
                deadBodies.push_back(pool.body[read]);
            }
        }
        read = read + 1 == pool.capacity ? 0 : read + 1;
    }
    listedCount = n;
    return count - dead;
}

template <bool kCollide, bool kMoving, bool kDistrust>
std::uint32_t Advance(const PoolArrays& arrays, const TypeStep* types, const WorldGeometry* geometry,
                      float dt, const StepTrust& trust, std::uint32_t begin, std::uint32_t end,
                      std::vector<b2Body*>& dead, StepCounts& counts, HitSink* hits)
{
    // A local copy: the stores below cannot alias it, so its pointers stay in registers.
    const PoolArrays pool = arrays;
    const b2AABB movingBounds = kMoving ? geometry->MovingBounds() : b2AABB{};
    Listed listed;
    std::uint32_t read = pool.Slot(begin);
    std::uint32_t write = read;
    std::uint32_t kept = 0;
    for (std::uint32_t first = begin; first < end; first += kBlock)
    {
        const std::uint32_t count = std::min(kBlock, end - first);
        std::uint32_t listedCount = 0;
        kept += FlyBlock<kCollide, kMoving, kDistrust>(pool, types, dt, movingBounds, read, write, count,
                                                       listed, listedCount, dead, counts);
        if constexpr (kCollide)
        {
            SweepListed(pool, types, *geometry, dt, trust, listed, listedCount, counts, hits);
        }
    }
    return kept;
}

} // namespace

std::uint32_t AdvanceRange(const PoolArrays& pool, const TypeStep* types, const WorldGeometry* geometry,
                           float dt, const StepTrust& trust, std::uint32_t begin, std::uint32_t end,
                           std::vector<b2Body*>& dead, StepCounts& counts, HitSink* hits)
{
    if (geometry == nullptr)
    {
        return Advance<false, false, false>(pool, types, nullptr, dt, trust, begin, end, dead, counts,
                                            nullptr);
    }
    if (!trust.clearance)
    {
        return Advance<true, false, true>(pool, types, geometry, dt, trust, begin, end, dead, counts, hits);
    }
    if (geometry->HasMoving())
    {
        return Advance<true, true, false>(pool, types, geometry, dt, trust, begin, end, dead, counts, hits);
    }
    return Advance<true, false, false>(pool, types, geometry, dt, trust, begin, end, dead, counts, hits);
}

void MoveParticles(const PoolArrays& pool, std::uint32_t from, std::uint32_t to, std::uint32_t count)
{
    std::uint32_t read = pool.Slot(from);
    std::uint32_t write = pool.Slot(to);
    for (std::uint32_t i = 0; i < count; ++i)
    {
        pool.positionX[write] = pool.positionX[read];
        pool.positionY[write] = pool.positionY[read];
        pool.velocityX[write] = pool.velocityX[read];
        pool.velocityY[write] = pool.velocityY[read];
        pool.life[write] = pool.life[read];
        pool.type[write] = pool.type[read];
        pool.clearance[write] = pool.clearance[read];
        if (pool.startX != nullptr)
        {
            pool.startX[write] = pool.startX[read];
            pool.startY[write] = pool.startY[read];
            pool.viaX[write] = pool.viaX[read];
            pool.viaY[write] = pool.viaY[read];
            pool.pushFraction[write] = pool.pushFraction[read];
            pool.stepFlags[write] = pool.stepFlags[read];
        }
        if (pool.body != nullptr)
        {
            pool.body[write] = pool.body[read];
        }
        write = write + 1 == pool.capacity ? 0 : write + 1;
        read = read + 1 == pool.capacity ? 0 : read + 1;
    }
}

} // namespace cfx::particles
