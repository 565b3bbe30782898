// contactfx internal: the world's fixtures as pool particles see them.
//
// Static geometry is copied once into flat world-space primitives (segments, circles, convex polygons)
// listed in a uniform grid (each in its neighbourhood, see grid.h), and copied again only when it changes.
// Box2D 2.4 tells nobody when a fixture is created, so by default (StaticWatch::everyStep) every step walks
// the world's body list once and folds what defines the static geometry (each enabled static body's
// address and pose; each fixture's address, type, sensor flag, filter, friction, restitution and threshold,
// and its shape's own geometry) into a 64-bit signature; a different signature rebuilds the cache. This
// catches created, destroyed, moved, enabled, disabled, re-filtered and edited static fixtures, including a
// new fixture at a freed fixture's address. With StaticWatch::onRequest the walk passes static bodies over,
// and the cache is rebuilt only after Invalidate().
//
// Moving geometry (dynamic and kinematic bodies, awake or asleep) is gathered during the same walk into
// a per-step list and its own grid, keyed by the box each child swept during the step (tighter than
// Box2D's fattened broad-phase box): for a body that did not turn, its boxes at the start and the end of
// the step; for one that did, the box of the capsule its centre's path traces at the child's reach. Moving
// shapes are tested in the body's own frame: the particle's start is taken into the body's frame at the start
// of the step (reconstructed as position - velocity * dt, which is how Box2D integrated it) and its end into
// the frame at the end, so a body sweeping into a resting particle meets it like a particle flying into a
// resting body, and a touch puts the particle on the body's surface where the body is now: carried along or
// pushed away, never left inside.
//
// Threading: Scan runs on one thread; SweepStatic and SweepMoving are const and run from several.
// Allocation: none once the vectors have grown to the world's size.
#pragma once

#include "particles/collision_filter.h"
#include "particles/grid.h"
#include "particles/sweep.h"

#include <algorithm>
#include <box2d/b2_contact.h> // b2MixFriction: particles mix friction as Box2D does
#include <box2d/b2_math.h>
#include <cmath>
#include <cstdint>
#include <vector>

class b2World;
class b2Body;
class b2Shape;

namespace cfx
{
struct BodyFilter;
}

namespace cfx::particles
{

/// What the particle meets: the fixture's collision filter and response.
struct SurfaceMaterial
{
    float friction = 0.0f;
    float restitution = 0.0f;
    float restSpeed = 0.0f; ///< the fixture's restitution threshold (m/s)
    /// The fixture's body, to name what a particle hit (ParticleHit); compared, never ordered by address.
    const b2Body* body = nullptr;
};

/// A particle type's side of a touch.
struct ParticleSide
{
    float radius;
    float restitution;
    float friction;
    float restSpeed;
    std::uint16_t categoryBits;
    std::uint16_t maskBits;

    /// Whether the particle collides with a fixture of this filter (Box2D's category and mask test).
    bool Accepts(std::uint16_t fixtureCategoryBits, std::uint16_t fixtureMaskBits) const
    {
        return FilterAccepts(categoryBits, maskBits, fixtureCategoryBits, fixtureMaskBits);
    }
};

/// Where a particle ends up after meeting geometry.
struct SweepResult
{
    Touch touch; ///< in world space
    b2Vec2 surfaceVelocity{0.0f, 0.0f};
    const SurfaceMaterial* material = nullptr; ///< valid until the next Scan
    /// Moving sweeps only: where (world) the disc was when it first touched the body.
    b2Vec2 firstTouch{0.0f, 0.0f};
    /// Moving sweeps only: the body met (an index into the step's moving bodies), when in the step (0..1),
    /// and the disc's way with it from then on, in its frame: from `carryFrom` at the touch to `carryTo`
    /// (where `touch.position` is) at the end of the step (WorldGeometry::Carried).
    std::uint32_t movingBody = 0;
    float touchTime = 1.0f;
    b2Vec2 carryFrom{0.0f, 0.0f};
    b2Vec2 carryTo{0.0f, 0.0f};
};

/// The box a disc of radius `radius` covers moving from `start` to `end`.
inline b2AABB PathBox(b2Vec2 start, b2Vec2 end, float radius)
{
    const b2Vec2 grow(radius, radius);
    b2AABB box;
    box.lowerBound = b2Min(start, end) - grow;
    box.upperBound = b2Max(start, end) + grow;
    return box;
}

/// Whether two boxes overlap, with non-short-circuit ands: no branch of its own, for loops where the
/// answer is as good as random from one call to the next.
inline bool BoxesOverlap(const b2AABB& a, const b2AABB& b)
{
    return (a.upperBound.x >= b.lowerBound.x) & (a.upperBound.y >= b.lowerBound.y) &
           (a.lowerBound.x <= b.upperBound.x) & (a.lowerBound.y <= b.upperBound.y);
}

/// The largest coordinate (m), velocity component (m/s) or angular velocity (rad/s) the particle system
/// simulates with: a particle that leaves it dies, and a body beyond it is skipped (both counted). Beyond
/// it a float's spacing is a metre or more.
inline constexpr float kMaxCoordinate = 1.0e7f;

/// Whether both components are finite and within kMaxCoordinate; not-a-number fails. No branch.
inline bool Sane(b2Vec2 v)
{
    const bool x = std::abs(v.x) <= kMaxCoordinate; // locals: `&` of two calls reads as a slip of `&&`
    const bool y = std::abs(v.y) <= kMaxCoordinate;
    return x & y;
}

/// What a bound on moving geometry is grown by (m) so that rounding in the body-frame sweeps, whose
/// coordinates are up to `magnitude` (m) in size, never lets the bound reject a touch the sweep would
/// find: 1 mm plus a millionth of the magnitude (float rounding is 6e-8 of it per operation).
inline float MovingSlop(float magnitude)
{
    return 1.0e-3f + 1.0e-6f * magnitude;
}
inline float MovingSlop(const b2AABB& box)
{
    return MovingSlop(std::max(std::max(std::abs(box.lowerBound.x), std::abs(box.lowerBound.y)),
                               std::max(std::abs(box.upperBound.x), std::abs(box.upperBound.y))));
}

/// When the static cache looks for changes (ParticleSystemOptions::watchStaticGeometry).
enum class StaticWatch : std::uint8_t
{
    everyStep, ///< every Scan hashes every static fixture and rebuilds on any change
    onRequest, ///< built once; again only after Invalidate (the application says when it changed)
};

/// Whether a moving sweep counts a touch that moves the disc nowhere: it starts touching the shape (or in
/// it) and leaves it or slides along it, or it grazes the surface later and stays on it (within
/// kTouchSlop), so the body puts it where its own path ends (WorldGeometry::SweepMoving).
enum class LeavingTouch : std::uint8_t
{
    ignored, ///< not a touch: it moves nothing, and a later touch of another body decides
    counts,  ///< a touch (the body was over the disc at the start of the step)
};

class WorldGeometry
{
public:
    /// Walks the world once: rebuilds the static cache if it is stale (see StaticWatch), gathers moving
    /// shapes. Bodies `ignore` ignores (body-backed particles) are skipped. `dt` (s) reconstructs where
    /// moving bodies were at the start of the step. With StaticWatch::onRequest, static bodies are passed
    /// over (their fixtures are not visited).
    void Scan(b2World& world, const BodyFilter* ignore, float dt, StaticWatch watch = StaticWatch::everyStep);
    /// Builds the static cache now if it is stale, as Scan would; returns whether it built.
    bool UpdateStatic(b2World& world, StaticWatch watch);
    /// Forces a static rebuild at the next Scan.
    void Invalidate() { m_signature = 0; }

    /// Earliest touch of the disc moving from in.p by in.d with static fixtures the particle's filter
    /// accepts; updates `result` (world space) and returns whether it found one earlier than result's.
    ///
    /// With `clearance`, also measures it at the end of the motion when nothing is touched: a lower
    /// bound (m, >= 0) on how far the disc's centre can then move in any direction before the disc can
    /// touch a static fixture the filter accepts. A motion shorter than a grid cell less the radius (most
    /// of them) is answered from the list of the cell `end` lies in, which holds everything within a cell
    /// of it: the clearance looks a cell around. A longer one queries the cells its path covers and
    /// looks at least 4 times the motion's length (at least 5 cm) around `end`, as far as the cells
    /// visited reach. Beyond the static geometry's bounds it is at least the distance to them. 0 when
    /// something was touched.
    bool SweepStatic(const SweepInput& in, const ParticleSide& side, SweepResult& result,
                     float* clearance = nullptr) const;
    /// Whether the straight path `from` -> `to` crosses a static edge or chain segment the particle's filter
    /// accepts (particles::PathCrossesEdge: a one-sided segment only from its front). A disc pushed out of a
    /// static shape it was deep inside of (one created over it) must not leave through a thin ground.
    bool CrossesStaticSegment(b2Vec2 from, b2Vec2 to, const ParticleSide& side) const;
    /// Earliest touch with moving fixtures of a disc that was at `start` at time `from` of the step (0: its
    /// start, 1: its end; 0..1) and is at `end` (world) at its end. The disc's path is followed in each
    /// body's own frame, from the body's pose at `from` to its end pose, in pieces short enough that a
    /// turning body's arc is followed too (at most kMaxTurn of turn a piece), so a spinning wheel meets
    /// what its rim reaches and not what a chord through it would. After the touch the disc keeps the
    /// rest of its motion relative to the body, less the part into the surface (it slides along it), and
    /// ends outside the body where the body is at the end of the step: pushed or carried, never left
    /// inside. `result`: that end position (world), the surface's normal and velocity there, and the
    /// touch's fraction of the path (`touch.t`). `from` 1: the disc was put at `start` after the bodies
    /// moved (spawned since the last step, or pushed from where its flight ended): for it the bodies stand
    /// still at their end poses. `except`: a body not to meet (null: none). `leaving`: whether a touch that
    /// moves the disc nowhere (LeavingTouch) is a touch; ignored, it cannot hide a later one of another body
    /// (a spark under a box falling onto a rising plank: the plank's, not the box's) nor stop a push.
    bool SweepMoving(b2Vec2 start, b2Vec2 end, const ParticleSide& side, float from, SweepResult& result,
                     const b2Body* except = nullptr, LeavingTouch leaving = LeavingTouch::ignored) const;

    /// A disc a moving body carries, at some time of the step (world).
    struct CarriedDisc
    {
        b2Vec2 position;
        b2Vec2 normal; ///< the body's surface normal where it puts the disc, turned with the body to then
    };
    /// Where a disc a moving sweep's `hit` touched is at time `f` of the step (hit.touchTime .. 1) as the
    /// body carries it: along its way in the body's frame, at the body's pose then. A straight line for a
    /// body that does not turn; an arc for one that does.
    CarriedDisc Carried(const SweepResult& hit, float f) const;
    /// In how many pieces to follow a disc the body of `hit` carries, each turning at most kMaxTurn.
    int CarryPieces(const SweepResult& hit) const;

    /// The most a moving body turns (rad) within one piece of a moving sweep.
    static constexpr float kMaxTurn = 0.1f;
    /// Pieces a moving sweep is cut into at most (a turn of 6.4 rad a step: 60 rad/s at 10 Hz).
    static constexpr int kMaxPieces = 64;
    /// Whether the disc at `point` overlaps a moving fixture its filter accepts, where they are at the end
    /// of the step, by more than `depth` (m, >= 0): the deepest overlap (as the sweeps measure it, from
    /// polygons' cores) exceeds it. A polygon with `point` clearly more than r - depth in front of one of
    /// its edges' lines is passed over without measuring (most pushed particles sit on a surface).
    bool MovingOverlapsDeeper(b2Vec2 point, const ParticleSide& side, float depth) const;
    /// Whether a moving fixture its filter accepts passes over `point` from time `from` of the step (0..1)
    /// to its end: it comes within a quarter of the disc's radius of it at some time (it covers more than
    /// three quarters of a disc at rest there). A particle held there (pushed into static geometry, or
    /// stopped by a moving body) was run over by that body: it went through it, not around it.
    bool MovingPassesOver(b2Vec2 point, const ParticleSide& side, float from = 0.0f) const;

    /// A box holding all moving geometry (an empty box when there is none): a disc whose path box
    /// misses it meets no moving shape, and SweepMoving would find nothing.
    b2AABB MovingBounds() const { return m_movingGrid.Bounds(); }

    bool HasStatic() const { return !m_staticGrid.Empty(); }
    bool HasMoving() const { return !m_movingShapes.empty(); }
    /// Body steps skipped since creation: a scan (or a static build) met a body whose transform, centre
    /// or velocities were not Sane (set to not-a-number or something absurd by the application).
    std::uint64_t SkippedBodies() const { return m_skippedBodies; }
    /// Times the static cache was built (for tests).
    std::uint64_t StaticBuilds() const { return m_builds; }
    /// Slots the last build's duplicate search looked at beyond the first of each primitive (for tests: a
    /// hash that spreads the primitives keeps it near zero).
    std::uint64_t DedupProbes() const { return m_dedupProbes; }
    std::size_t StaticPrimitives() const { return m_primitives.size(); }
    /// The static grid's cell size (m): the primitives' median extent, or finer for few long ones.
    float StaticCellSize() const { return m_staticGrid.CellSize(); }
    /// Heap bytes held.
    std::size_t Bytes() const;

    enum class Kind : std::uint8_t
    {
        segment,
        circle,
        polygon,
    };

    /// One static shape in world space. Segment: v1 = a, v2 = b, normal, scalar = 1 / length^2.
    /// Circle: centre a, scalar = radius. Polygon: `count` vertices and normals from `first` in the
    /// polygon pools.
    struct Primitive
    {
        // Zeroed: Box2D's b2Vec2() leaves its floats unset, and DropDuplicatePrimitives hashes and compares
        // all three, also where a kind does not use them.
        b2Vec2 a{0.0f, 0.0f}, b{0.0f, 0.0f}, normal{0.0f, 0.0f};
        float scalar;
        std::uint32_t first;
        std::uint32_t material;
        std::uint16_t categoryBits, maskBits;
        Kind kind;
        std::uint8_t count;
        bool oneSided;
    };
    static_assert(sizeof(Primitive) <= 48, "a static primitive fits in 48 bytes");

private:
    struct MovingBody
    {
        b2Transform before, after;
        b2Vec2 centerBefore; ///< world centre of mass at the start of the step
        b2Vec2 center;       ///< world centre of mass at the end of the step
        b2Vec2 velocity;
        float angularVelocity;
        b2Vec2 localCenter; ///< centre of mass in the body's frame
        float angleBefore;  ///< rad, at the start of the step
        float turn;         ///< rad turned in the step
        int pieces;         ///< the step is swept in this many pieces, each turning at most kMaxTurn

        /// The body's frame at fraction `f` of the step (f = 0: before, f = 1: after), as Box2D moves
        /// it: the centre of mass along a line, the angle at a constant rate.
        b2Transform At(float f) const;
        /// Its centre of mass at fraction `f` of the step, as At.
        b2Vec2 CenterAt(float f) const;
        /// In how many pieces to follow it from fraction `from` of the step to its end, each turning at most
        /// kMaxTurn (`pieces` from the start, 1 from the end).
        int PiecesFrom(float from) const;
    };
    struct MovingShape
    {
        const b2Shape* shape;
        std::int32_t child;
        std::uint32_t body;
        std::uint32_t material;
        std::uint16_t categoryBits, maskBits;
        /// How far (m) the shape reaches from the body's centre of mass, in any pose: during the step it
        /// stays within this of the centre, which moves in a straight line.
        float reach;
    };

    /// Whether a disc of radius `r` moving in a straight line from `start` to `end` during the step can
    /// meet a shape of `body` that reaches `reach` from its centre, which moves in a straight line from
    /// `centreAtStart` to body.center (false only when it cannot).
    static bool MayMeet(const MovingBody& body, b2Vec2 centreAtStart, float reach, b2Vec2 start, b2Vec2 end,
                        float r);
    /// The box the child covers during the step (see the file comment), grown by a little for rounding.
    static b2AABB SweptBox(const MovingBody& body, const b2Shape& shape, int child, float reach);
    void BuildStatic(b2World& world);
    /// Builds when `signature` (of the static bodies, when watched) says the cache is stale.
    void BuildStaticIfStale(b2World& world, StaticWatch watch, std::uint64_t signature);
    /// m_signature of a cache built without watching (any value but 0).
    static constexpr std::uint64_t kBuiltUnwatched = 1;
    /// Keeps one of each set of identical primitives (same shape, filter and material: a fixture
    /// duplicated by the application or an editor), so that their number does not multiply every sweep.
    void DropDuplicatePrimitives();
    /// Grid::Touches for the static primitives (`context`: this).
    static bool PrimitiveTouches(const void* context, std::uint32_t index, const b2AABB& region);
    class Nearest;

    std::uint64_t m_signature = 0;
    std::uint64_t m_builds = 0;
    std::uint64_t m_dedupProbes = 0;
    std::uint64_t m_skippedBodies = 0;
    std::vector<SurfaceMaterial> m_materials;       ///< of static fixtures
    std::vector<SurfaceMaterial> m_movingMaterials; ///< of this step's moving fixtures
    std::vector<Primitive> m_primitives;
    std::vector<b2AABB> m_primitiveBoxes;
    std::vector<b2Vec2> m_polygonVertices, m_polygonNormals;
    std::vector<std::uint32_t> m_dedupTable;  ///< DropDuplicatePrimitives' hash table, kept between builds
    std::vector<std::uint64_t> m_dedupHashes; ///< by kept primitive: its contents' hash
    Grid m_staticGrid;

    std::vector<MovingBody> m_movingBodies;
    std::vector<MovingShape> m_movingShapes;
    std::vector<b2AABB> m_movingBoxes;
    Grid m_movingGrid;
};

} // namespace cfx::particles
