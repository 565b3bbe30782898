#include "spawn_point.h"

#include "child_edge.h"
#include "world_query.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>

namespace cfx
{

namespace
{

// Whether a start's disc test looks at `fixture`: one of `solids`, or a non-sensor fixture of `passable`
// (the other body of the contact, null for none) whatever the particle's filter says, unless `solids` wants
// it filtered as any other (Solids::otherBodyWhateverFilter).
bool Looked(const Solids& solids, const b2Body* passable, const b2Fixture& fixture)
{
    return (solids.otherBodyWhateverFilter && fixture.GetBody() == passable && !fixture.IsSensor()) ||
           solids.Include(fixture);
}

// Whether a disc is inside any solid fixture: it overlaps one (skins of polygons and edges included), or
// its centre is behind the one-sided edge or chain nearest to it. One-sided edges and chains collide on
// their front (right) side only, so whatever is behind them is inside the solid they bound. Near a vertex
// shared by two edges the sum of their normals decides (the side that matters at a convex corner is the
// intersection of the two back half-planes, at a concave one their union; the summed normal gives both).
class DiscQuery
{
public:
    /// `passable`: a body whose overlap is noted (overlapsPassable) but does not end the query; may be null.
    DiscQuery(b2Vec2 center, float radius, const Solids& solids, const b2Body* passable = nullptr)
        : m_solids(solids), m_passable(passable), m_center(center), m_radius(radius),
          m_behindReach(radius + kBehindReach)
    {
        m_box.lowerBound = center - b2Vec2(radius, radius);
        m_box.upperBound = center + b2Vec2(radius, radius);
        m_reachBox.lowerBound = center - b2Vec2(m_behindReach, m_behindReach);
        m_reachBox.upperBound = center + b2Vec2(m_behindReach, m_behindReach);
    }

    /// One child of a fixture the query box meets, with its broad-phase box (QueryProxies); false: the
    /// answer is known, stop.
    bool operator()(const b2Fixture* fixture, int child, const b2AABB& fatBox)
    {
        return !Looked(m_solids, m_passable, *fixture) || Solid(fixture, child, fatBox);
    }

    /// As operator(), for a child known to be looked at (Looked, with this query's solids and passable body).
    /// `box` holds the child: the broad phase's fattened box, which b2World::ShiftOrigin moves with the world
    /// (the fixture's own GetAABB is not moved until its body next moves, never for a static one).
    bool Solid(const b2Fixture* fixture, int child, const b2AABB& box)
    {
        if (!b2TestOverlap(box, m_reachBox))
        {
            return true;
        }
        const b2Shape* shape = fixture->GetShape();
        const b2Transform& transform = fixture->GetBody()->GetTransform();
        if (b2TestOverlap(box, m_box) && Overlaps(shape, child, transform))
        {
            if (fixture->GetBody() == m_passable)
            {
                overlapsPassable = true;
                return true;
            }
            overlaps = true;
            return false;
        }
        if (shape->GetType() == b2Shape::e_edge || shape->GetType() == b2Shape::e_chain)
        {
            b2EdgeShape edge;
            if (detail::ChildEdge(*shape, child, edge) && edge.m_oneSided)
            {
                NoteOneSided(edge, transform);
            }
        }
        return true;
    }

    const b2AABB& Box() const { return m_reachBox; }
    /// After the query: inside something other than the passable body: overlapping it, or behind the
    /// nearest one-sided edge.
    bool Closed() const
    {
        return overlaps ||
               (m_nearest <= m_behindReach && b2Dot(m_center - m_nearestPoint, NormalSum()) < 0.0f);
    }
    /// After the query: inside anything.
    bool Inside() const { return overlapsPassable || Closed(); }

    bool overlaps = false;         ///< overlaps a fixture of a body other than the passable one
    bool overlapsPassable = false; ///< overlaps a fixture of the passable body

private:
    // m beyond the disc within which one-sided edges are looked at: a start point is never farther than
    // this from the surface it was lifted off, so an edge it could be behind is always this close.
    static constexpr float kBehindReach = 0.1f;

    // Whether the disc overlaps the child as b2Distance decides it: the distance GJK finds between the
    // child's core (polygon, segment or point, without its skin) and the disc's centre is not above the
    // sum of the radii, or is below b2_epsilon. The distance is measured here directly (a fraction of GJK's
    // cost: the debris scene's placement took 2.8 times the instructions with GJK for every child); GJK is
    // asked only when the two could decide differently, the distance within Margin of the sum (0.06 % of
    // the children there), so the answer is always GJK's.
    bool Overlaps(const b2Shape* shape, int child, const b2Transform& transform) const
    {
        const float reach = shape->m_radius + m_radius;
        float magnitude = 0.0f;
        const float distance = CoreDistance(*shape, child, transform, reach, &magnitude);
        const float margin = Margin(magnitude);
        if (distance > reach + margin && distance > b2_epsilon + margin)
        {
            return false;
        }
        if (distance < reach - margin)
        {
            return true;
        }
        return GjkOverlaps(shape, child, transform); // near the sum, or not measured (NaN)
    }

    // How far (m) the distance measured here and GJK's can differ by rounding, with coordinates up to
    // `magnitude` (m): each computes it from the same points in a few dozen float operations, each off by
    // at most 6e-8 of the magnitude. 1e-5 of it is about a hundred times what they were seen to differ by
    // (the registered scenes, the RUBE samples and the debris scene: at most 1.1 % of the margin).
    static float Margin(float magnitude) { return 1.0e-5f * (1.0f + magnitude); }

    // The distance from the disc's centre to the child's core, 0 inside a polygon's (convex, its normals
    // those of its edges, as b2PolygonShape::Set makes them); when that distance is plainly above `reach`,
    // possibly a smaller one still above reach + Margin (a polygon's largest separation, a lower bound). NaN
    // (not measured) for a polygon of fewer than 3 vertices or an unknown shape. `magnitude`: the largest
    // coordinate the measure and GJK meet (world and shape frame), for Margin.
    float CoreDistance(const b2Shape& shape, int child, const b2Transform& transform, float reach,
                       float* magnitude) const
    {
        const float placed = std::max(std::abs(m_center.x), std::abs(m_center.y)) +
                             std::max(std::abs(transform.p.x), std::abs(transform.p.y));
        const b2Vec2 p = b2MulT(transform, m_center); // in the shape's frame
        if (shape.GetType() == b2Shape::e_circle)
        {
            const b2Vec2 centre = static_cast<const b2CircleShape&>(shape).m_p;
            *magnitude = placed + std::max(std::abs(centre.x), std::abs(centre.y));
            return b2Distance(p, centre);
        }
        if (shape.GetType() == b2Shape::e_polygon)
        {
            const auto& polygon = static_cast<const b2PolygonShape&>(shape);
            const int count = polygon.m_count;
            float extent = 0.0f;
            float separation = -b2_maxFloat;
            for (int i = 0; i < count; ++i)
            {
                const b2Vec2 v = polygon.m_vertices[i];
                extent = std::max(extent, std::max(std::abs(v.x), std::abs(v.y)));
                separation = std::max(separation, b2Dot(polygon.m_normals[i], p - v));
            }
            *magnitude = placed + extent;
            if (count < 3)
            {
                return std::numeric_limits<float>::quiet_NaN();
            }
            if (separation <= 0.0f)
            {
                return 0.0f; // inside the core
            }
            if (separation > reach + Margin(*magnitude) + b2_epsilon)
            {
                return separation;
            }
            // Outside: the nearest point is on an edge the centre is in front of.
            float nearest = b2_maxFloat;
            for (int i = 0; i < count; ++i)
            {
                const b2Vec2 v1 = polygon.m_vertices[i];
                if (b2Dot(polygon.m_normals[i], p - v1) > 0.0f)
                {
                    nearest = std::min(nearest,
                                       SegmentDistance(p, v1, polygon.m_vertices[i + 1 < count ? i + 1 : 0]));
                }
            }
            return nearest;
        }
        b2EdgeShape edge;
        if (!detail::ChildEdge(shape, child, edge))
        {
            return std::numeric_limits<float>::quiet_NaN();
        }
        *magnitude = placed + std::max(std::max(std::abs(edge.m_vertex1.x), std::abs(edge.m_vertex1.y)),
                                       std::max(std::abs(edge.m_vertex2.x), std::abs(edge.m_vertex2.y)));
        return SegmentDistance(p, edge.m_vertex1, edge.m_vertex2);
    }

    static float SegmentDistance(b2Vec2 p, b2Vec2 a, b2Vec2 b)
    {
        const b2Vec2 along = b - a;
        const float squared = b2Dot(along, along);
        const float t = squared > 0.0f ? b2Clamp(b2Dot(p - a, along) / squared, 0.0f, 1.0f) : 0.0f;
        return b2Distance(p, a + t * along);
    }

    bool GjkOverlaps(const b2Shape* shape, int child, const b2Transform& transform) const
    {
        b2CircleShape disc;
        disc.m_radius = m_radius;
        disc.m_p = m_center;
        b2DistanceInput input;
        input.proxyA.Set(shape, child);
        input.proxyB.Set(&disc, 0);
        input.transformA = transform;
        input.transformB.SetIdentity();
        input.useRadii = true;
        b2SimplexCache cache;
        cache.count = 0;
        b2DistanceOutput output;
        b2Distance(&output, &cache, &input);
        return output.distance <= 0.0f;
    }

    void NoteOneSided(const b2EdgeShape& edge, const b2Transform& transform)
    {
        const b2Vec2 v1 = b2Mul(transform, edge.m_vertex1);
        const b2Vec2 v2 = b2Mul(transform, edge.m_vertex2);
        const b2Vec2 along = v2 - v1;
        const float length = along.Length();
        if (length <= b2_epsilon)
        {
            return;
        }
        const float t = b2Clamp(b2Dot(m_center - v1, along) / (length * length), 0.0f, 1.0f);
        const b2Vec2 closest = v1 + t * along;
        const float distance = b2Distance(m_center, closest);
        const b2Vec2 front(along.y / length, -along.x / length); // Box2D: the right side collides
        if (distance < m_nearest - kSame)
        {
            m_nearest = distance;
            m_nearestPoint = closest;
            m_normals[0] = front;
            m_normalCount = 1;
        }
        else if (distance <= m_nearest + kSame && b2DistanceSquared(closest, m_nearestPoint) <= kSame * kSame)
        {
            // The same vertex reached from another edge. One of a direction seen before (the same edge
            // twice: a fixture duplicated by an editor) adds nothing.
            for (int i = 0; i < m_normalCount; ++i)
            {
                if (m_normals[i].x == front.x && m_normals[i].y == front.y)
                {
                    return;
                }
            }
            if (m_normalCount < kMaxNormals)
            {
                m_normals[m_normalCount++] = front;
            }
        }
    }

    b2Vec2 NormalSum() const
    {
        b2Vec2 sum(0.0f, 0.0f);
        for (int i = 0; i < m_normalCount; ++i)
        {
            sum += m_normals[i];
        }
        return sum;
    }

    static constexpr float kSame = 1e-6f; // m: the same distance, the same vertex
    static constexpr int kMaxNormals = 4;

    Solids m_solids;
    const b2Body* m_passable;
    b2Vec2 m_center;
    float m_radius;
    float m_behindReach;
    b2AABB m_box;
    b2AABB m_reachBox;
    float m_nearest = b2_maxFloat;
    b2Vec2 m_nearestPoint{0.0f, 0.0f};
    b2Vec2 m_normals[kMaxNormals] = {};
    int m_normalCount = 0;
};

class HighestStatic final : public b2RayCastCallback
{
public:
    float ReportFixture(b2Fixture* fixture, const b2Vec2& point, const b2Vec2&, float fraction) override
    {
        if (fixture->GetBody()->GetType() != b2_staticBody || fixture->IsSensor())
        {
            return -1.0f; // ignore and go on
        }
        hit = true;
        y = point.y;
        return fraction; // clip: the closest hit from above wins
    }

    bool hit = false;
    float y = 0.0f;
};

// Projects `point` onto the boundary of the surface fixture along -normal, from the outside.
bool ProjectOntoSurface(const SpawnQuery& query, b2Vec2 point, float reach, b2Vec2* surfacePoint,
                        b2Vec2* surfaceNormal)
{
    b2RayCastInput input;
    input.p1 = point + reach * query.normal;
    input.p2 = point - reach * query.normal;
    input.maxFraction = 1.0f;
    b2RayCastOutput output;
    if (!query.surface->RayCast(&output, input, query.surfaceChild))
    {
        return false;
    }
    *surfacePoint = input.p1 + output.fraction * (input.p2 - input.p1);
    *surfaceNormal = output.normal;
    return true;
}

// Whether the straight way from one start to the next crosses a solid fixture other than the surface's
// (the walk hugs that one) and the passable body's (the walk goes under it). Projected onto the surface,
// a start can land on a face that is hidden under another fixture (a box's side under a slab laid over it):
// the start is free, but not reachable from the contact.
class WayBlocked final : public b2RayCastCallback
{
public:
    WayBlocked(const b2Fixture* surface, const b2Body* passable, const Solids& solids)
        : m_surface(surface), m_passable(passable), m_solids(solids)
    {
    }

    float ReportFixture(b2Fixture* fixture, const b2Vec2&, const b2Vec2&, float) override
    {
        if (fixture == m_surface || fixture->GetBody() == m_passable || !m_solids.Include(*fixture))
        {
            return -1.0f; // ignore and go on
        }
        blocked = true;
        return 0.0f; // one is enough
    }

    bool blocked = false;

private:
    const b2Fixture* m_surface;
    const b2Body* m_passable;
    Solids m_solids;
};

// Two surface normals this close (cosine; 0.8 degrees) are one face's: the way between starts on it is
// not cast.
constexpr float kSameFace = 0.9999f;

// What a start tried along the surface is.
enum class Start : std::uint8_t
{
    clear,    ///< outside every solid: taken
    passable, ///< inside the body that makes the contact only (under a sliding block): walk on
    closed,   ///< inside something else (a wall, the floor below a wall's end, a neighbour in a pile)
};

// Tries offsets along a line from the contact: 0, then on `firstSide` 1 .. 8 steps, then growing by half
// each time, the last one `searchDistance` itself; then the same on the other side. Returns the first start
// `attempt` finds clear. A side ends at a closed start: what lies beyond it (under the floor a wall
// stands on, past a neighbour in a pile) is not reached from the contact. The whole first side comes
// first: a start just across the contact (ahead of a sliding block's front corner) would have its
// particles run over.
template <class Attempt> SpawnPoint Walk(float firstSide, float step, float searchDistance, Attempt&& attempt)
{
    SpawnPoint found;
    for (float side : {firstSide, -firstSide})
    {
        float offset = side == firstSide ? 0.0f : step;
        for (int k = side == firstSide ? 0 : 1; offset <= searchDistance; ++k)
        {
            const Start start = attempt(side * offset, found);
            if (start == Start::clear)
            {
                found.outside = true;
                return found;
            }
            if (start == Start::closed && offset > 0.0f)
            {
                break;
            }
            const float next = k < 8 ? offset + step : offset * 1.5f;
            offset = offset < searchDistance && next > searchDistance ? searchDistance : next;
        }
    }
    found.outside = false;
    return found;
}

// The fixture children a start's disc test looks at (Looked) near the starts of one walk, from few
// broad-phase queries: a query covers a start's box grown by `grow` on each side (the next starts are a few
// steps away), and is made again when a start's box leaves the box covered. A start's disc query visits the
// children whose broad-phase box meets its own box, which are the children looked at that a query of the
// world with that box reports, in the same order (QueryProxies): each start sees exactly what it would see
// asking the world. Holds at most kCapacity children; when a query finds more, each start from then on asks
// the world. Valid while the world's fixtures stay as they are (the walk only reads the world).
class NearbyChildren
{
public:
    NearbyChildren(const b2World& world, const Solids& solids, const b2Body* passable, float grow)
        : m_world(world), m_solids(solids), m_passable(passable), m_grow(grow)
    {
    }

    /// Visits the children `query` needs (its Box()), as detail::QueryProxies(world, query.Box(), query).
    void Visit(DiscQuery& query)
    {
        const b2AABB& box = query.Box();
        if (!m_tooMany && !Covers(box))
        {
            Fill(box);
        }
        if (m_tooMany)
        {
            detail::QueryProxies(m_world, box, query);
            return;
        }
        for (int i = 0; i < m_count; ++i)
        {
            const Child& child = m_children[i];
            if (b2TestOverlap(child.fatBox, box) && !query.Solid(child.fixture, child.index, child.fatBox))
            {
                return;
            }
        }
    }

private:
    static constexpr int kCapacity = 32;

    struct Child
    {
        b2AABB fatBox; ///< the broad phase's, which its query tests
        const b2Fixture* fixture;
        int index;
    };

    bool Covers(const b2AABB& box) const
    {
        return box.lowerBound.x >= m_covered.lowerBound.x && box.lowerBound.y >= m_covered.lowerBound.y &&
               box.upperBound.x <= m_covered.upperBound.x && box.upperBound.y <= m_covered.upperBound.y;
    }

    void Fill(const b2AABB& box)
    {
        const b2Vec2 grow(m_grow, m_grow);
        m_covered.lowerBound = box.lowerBound - grow;
        m_covered.upperBound = box.upperBound + grow;
        m_count = 0;
        detail::QueryProxies(m_world, m_covered,
                             [this](const b2Fixture* fixture, int child, const b2AABB& fatBox)
                             {
                                 if (!Looked(m_solids, m_passable, *fixture))
                                 {
                                     return true;
                                 }
                                 if (m_count == kCapacity)
                                 {
                                     m_tooMany = true;
                                     return false;
                                 }
                                 m_children[m_count++] = Child{fatBox, fixture, child};
                                 return true;
                             });
    }

    const b2World& m_world;
    Solids m_solids;
    const b2Body* m_passable;
    float m_grow;
    // Covers no box until the first query (a box's lower bound is never above its upper).
    b2AABB m_covered{b2Vec2(b2_maxFloat, b2_maxFloat), b2Vec2(-b2_maxFloat, -b2_maxFloat)};
    Child m_children[kCapacity];
    int m_count = 0;
    bool m_tooMany = false;
};

// How far a query of NearbyChildren reaches beyond the start that made it, in steps of the walk: the first
// side's 8 equal steps and the next one (12), and as far on the other side, so that most walks query once
// (the debris scene of docs/benchmarks.md: 1.0 queries a walk; with 8 steps 1.7, and 7 % more instructions).
constexpr float kCoveredSteps = 16.0f;

// Whether a start at `center` is clear, inside `passable` only, or closed (see Start).
Start StartAt(NearbyChildren& nearby, b2Vec2 center, float radius, const Solids& solids,
              const b2Body* passable)
{
    DiscQuery query(center, radius, solids, passable);
    nearby.Visit(query);
    return query.Closed() ? Start::closed : query.overlapsPassable ? Start::passable : Start::clear;
}

} // namespace

bool DiscIsClear(const b2World& world, b2Vec2 center, float radius, const Solids& solids)
{
    DiscQuery query(center, radius, solids);
    detail::QueryProxies(world, query.Box(), query);
    return !query.Inside();
}

bool DiscOverlapsSolid(const b2World& world, b2Vec2 center, float radius, const Solids& solids)
{
    static constexpr float kTouching = 1.0e-5f; // m
    class Overlaps
    {
    public:
        Overlaps(b2Vec2 center, float radius, const Solids& solids) : m_solids(solids)
        {
            // b2TestOverlap counts a distance under 10 * b2_epsilon (1.2e-6 m) as overlap: a disc just
            // touching a surface would be inside. Overlap means deeper than kTouching.
            m_disc.m_p = center;
            m_disc.m_radius = radius - std::min(kTouching, 0.5f * radius);
            box.lowerBound = center - b2Vec2(radius, radius);
            box.upperBound = center + b2Vec2(radius, radius);
        }
        bool operator()(const b2Fixture* fixture, int child, const b2AABB& fatBox)
        {
            // The broad phase's box: b2World::ShiftOrigin moves it, not the fixture's own (GetAABB).
            found = m_solids.Include(*fixture) && b2TestOverlap(fatBox, box) &&
                    b2TestOverlap(fixture->GetShape(), child, &m_disc, 0, fixture->GetBody()->GetTransform(),
                                  m_identity);
            return !found;
        }
        b2AABB box;
        bool found = false;

    private:
        Solids m_solids;
        b2CircleShape m_disc;
        b2Transform m_identity{b2Vec2(0.0f, 0.0f), b2Rot(0.0f)};
    };
    Overlaps query(center, radius, solids);
    detail::QueryProxies(world, query.box, query);
    return query.found;
}

SpawnPoint FindSpawnPoint(const b2World& world, const SpawnQuery& query, const Solids& solids)
{
    b2Vec2 tangent(-query.normal.y, query.normal.x);
    const float firstSide = b2Dot(query.leaving, tangent) < 0.0f ? -1.0f : 1.0f;
    // Ray casts find the core shape; polygons and edges carry a skin of b2_polygonRadius beyond it.
    const b2Shape* shape = query.surface->GetShape();
    const float skin = shape->GetType() == b2Shape::e_circle ? 0.0f : shape->m_radius;
    const float clearance = query.radius + skin + b2_linearSlop;
    float step = std::max(clearance, 0.01f);
    float reach = std::max(4.0f * clearance, 0.25f);

    // The start each one is walked to from, and the surface normal there: the one at the contact (offset
    // 0), then the last one tried.
    const b2Vec2 lifted = query.point + clearance * query.normal;
    SpawnPoint atContact{lifted, query.normal, false};
    NearbyChildren nearby(world, solids, query.otherBody, kCoveredSteps * step);
    SpawnPoint previous = atContact;
    float previousSide = 0.0f;
    SpawnPoint found = Walk(firstSide, step, query.searchDistance,
                            [&](float offset, SpawnPoint& start)
                            {
                                const b2Vec2 along = query.point + offset * tangent;
                                b2Vec2 surfacePoint = along;
                                b2Vec2 surfaceNormal = query.normal;
                                if (!ProjectOntoSurface(query, along, reach, &surfacePoint, &surfaceNormal))
                                {
                                    // Past the end of the surface (or not facing us): keep the contact plane.
                                    surfacePoint = along;
                                    surfaceNormal = query.normal;
                                }
                                start.position = surfacePoint + clearance * surfaceNormal;
                                start.normal = surfaceNormal;
                                const float side = offset > 0.0f ? 1.0f : offset < 0.0f ? -1.0f : 0.0f;
                                if (side == 0.0f)
                                {
                                    atContact = start;
                                }
                                else if (side != previousSide)
                                {
                                    previous = atContact; // the other side is walked from the contact too
                                }
                                previousSide = side;
                                const SpawnPoint from = previous;
                                previous = start;
                                // Along one face the way runs parallel to it, a start's height above it;
                                // a start on another face (around a corner) may be behind something.
                                if (b2Dot(from.normal, start.normal) < kSameFace &&
                                    b2DistanceSquared(from.position, start.position) > 0.0f)
                                {
                                    WayBlocked way(query.surface, query.otherBody, solids);
                                    world.RayCast(&way, from.position, start.position);
                                    if (way.blocked)
                                    {
                                        return Start::closed;
                                    }
                                }
                                return StartAt(nearby, start.position, query.radius, solids, query.otherBody);
                            });
    if (!found.outside)
    {
        found.position = lifted;
        found.normal = query.normal;
    }
    return found;
}

SpawnPoint FindTutorialDropPoint(const b2World& world, const SpawnQuery& query, const Solids& solids)
{
    // Along x, the side the particles leave to first, as FindSpawnPoint walks along the surface.
    const float firstSide = query.leaving.x < 0.0f ? -1.0f : 1.0f;
    const float step = std::max(query.radius + b2_polygonRadius + b2_linearSlop, 0.01f);
    NearbyChildren nearby(world, solids, query.otherBody, kCoveredSteps * step);
    SpawnPoint found =
        Walk(firstSide, step, query.searchDistance,
             [&](float offset, SpawnPoint& start)
             {
                 start = TutorialDropPoint(world, query.point + b2Vec2(offset, 0.0f));
                 return start.outside ? StartAt(nearby, start.position, query.radius, solids, query.otherBody)
                                      : Start::passable; // nothing static below: look further
             });
    if (!found.outside)
    {
        found = TutorialDropPoint(world, query.point);
        found.outside = false;
    }
    return found;
}

SpawnPoint TutorialDropPoint(const b2World& world, b2Vec2 point)
{
    HighestStatic callback;
    world.RayCast(&callback, b2Vec2(point.x, 1000.0f), b2Vec2(point.x, -1000.0f));
    if (!callback.hit)
    {
        return SpawnPoint{point, b2Vec2(0.0f, 1.0f), false};
    }
    return SpawnPoint{b2Vec2(point.x, callback.y + 0.05f), b2Vec2(0.0f, 1.0f), true};
}

} // namespace cfx
