// contactfx internal: the static cache and the per-step walk of the world (see world_geometry.h).
#include "particles/world_geometry.h"

#include "child_edge.h"
#include "particles/crossing.h"
#include "spawn_point.h"

#include <algorithm>
#include <bit>
#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>
#include <cmath>
#include <limits>

namespace cfx::particles
{

namespace
{

constexpr std::uint64_t kFnvBasis = 0xcbf29ce484222325ULL;
constexpr std::uint64_t kFnvPrime = 0x100000001b3ULL;

std::uint64_t Word(b2Vec2 value)
{
    return (static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(value.x)) << 32u) |
           std::bit_cast<std::uint32_t>(value.y);
}

// Spreads every bit of `hash` over all the others (MurmurHash3's 64-bit finalizer). FNV's multiplications
// carry bits only upwards, so a word's high half (a point's x) never reaches the low bits that pick a
// hash table's slot: without this, the tiles of a row all probed the same slots.
std::uint64_t Scramble(std::uint64_t hash)
{
    hash ^= hash >> 33u;
    hash *= 0xff51afd7ed558ccdULL;
    hash ^= hash >> 33u;
    hash *= 0xc4ceb9fe1a85ec53ULL;
    hash ^= hash >> 33u;
    return hash;
}

// Whether a particle bounces off two materials alike: friction, restitution and threshold, bit for bit.
// Not the body: the same fixture duplicated on another body is still met once (its hits name the first).
bool SameResponse(const SurfaceMaterial& x, const SurfaceMaterial& y)
{
    return std::bit_cast<std::uint32_t>(x.friction) == std::bit_cast<std::uint32_t>(y.friction) &&
           std::bit_cast<std::uint32_t>(x.restitution) == std::bit_cast<std::uint32_t>(y.restitution) &&
           std::bit_cast<std::uint32_t>(x.restSpeed) == std::bit_cast<std::uint32_t>(y.restSpeed);
}

// FNV-1a over 64-bit words, dealt in turn to four chains that run side by side: one chain waits a
// multiplication's latency per word, and the signature hashes every static fixture every step.
class Signature
{
    static constexpr std::uint64_t kLanes = 4;

public:
    void Add(std::uint64_t word)
    {
        std::uint64_t& lane = m_lanes[m_words++ % kLanes];
        lane = (lane ^ word) * kFnvPrime;
    }
    void Add(const void* pointer)
    {
        Add(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(pointer)));
    }
    void Add(float value) { Add(static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(value))); }
    void Add(b2Vec2 value) { Add(Word(value)); }
    /// `count` points: a chain has hundreds, hashed in four chains of their own kept in registers (the
    /// lanes above live in memory), then added with the count.
    void Add(const b2Vec2* points, int count)
    {
        std::uint64_t lanes[kLanes] = {kFnvBasis, kFnvBasis + 1, kFnvBasis + 2, kFnvBasis + 3};
        int point = 0;
        for (; point + 4 <= count; point += 4)
        {
            for (std::uint64_t lane = 0; lane < kLanes; ++lane)
            {
                lanes[lane] = (lanes[lane] ^ Word(points[point + static_cast<int>(lane)])) * kFnvPrime;
            }
        }
        for (; point < count; ++point)
        {
            lanes[0] = (lanes[0] ^ Word(points[point])) * kFnvPrime;
        }
        Add(static_cast<std::uint64_t>(count));
        for (const std::uint64_t lane : lanes)
        {
            Add(lane);
        }
    }
    /// A shape's own geometry, in its body's frame: what the cache is built from.
    void Add(const b2Shape& shape)
    {
        Add((static_cast<std::uint64_t>(shape.GetType()) << 32u) |
            std::bit_cast<std::uint32_t>(shape.m_radius));
        switch (shape.GetType())
        {
        case b2Shape::e_circle:
            Add(static_cast<const b2CircleShape&>(shape).m_p);
            break;
        case b2Shape::e_edge:
        {
            const auto& edge = static_cast<const b2EdgeShape&>(shape);
            const b2Vec2 points[4] = {edge.m_vertex0, edge.m_vertex1, edge.m_vertex2, edge.m_vertex3};
            Add(points, 4);
            Add(static_cast<std::uint64_t>(edge.m_oneSided));
            break;
        }
        case b2Shape::e_polygon:
        {
            const auto& polygon = static_cast<const b2PolygonShape&>(shape);
            Add(polygon.m_vertices, polygon.m_count);
            break;
        }
        case b2Shape::e_chain:
        {
            const auto& chain = static_cast<const b2ChainShape&>(shape);
            Add(chain.m_vertices, chain.m_count);
            Add(chain.m_prevVertex);
            Add(chain.m_nextVertex);
            break;
        }
        default:
            break;
        }
    }
    /// Never 0, so that 0 can mean "invalid".
    std::uint64_t Value() const
    {
        std::uint64_t hash = kFnvBasis;
        for (const std::uint64_t lane : m_lanes)
        {
            hash = (hash ^ lane) * kFnvPrime;
        }
        hash = (hash ^ m_words) * kFnvPrime;
        return hash == 0 ? 1 : hash;
    }

private:
    std::uint64_t m_lanes[kLanes] = {kFnvBasis, kFnvBasis + 1, kFnvBasis + 2, kFnvBasis + 3};
    std::uint64_t m_words = 0;
};

// Whether a body's state is one to simulate with (see kMaxCoordinate): its position, rotation, centre and
// velocities.
bool IsSane(const b2Body& body)
{
    const b2Transform& xf = body.GetTransform();
    const bool pose = Sane(xf.p) && Sane(b2Vec2(xf.q.c, xf.q.s)) && Sane(body.GetWorldCenter());
    return pose && Sane(body.GetLinearVelocity()) && Sane(b2Vec2(body.GetAngularVelocity(), 0.0f));
}

// Adds what the static cache builds from `body` (static, enabled) to `signature`. Returns false for a body
// whose pose is not Sane: it is left out of the cache, and only its address is added, so that becoming sane
// again rebuilds the cache.
bool AddStaticBody(Signature& signature, const b2Body& body)
{
    signature.Add(&body);
    if (!IsSane(body))
    {
        return false;
    }
    signature.Add(body.GetPosition());
    signature.Add(body.GetAngle());
    for (const b2Fixture* fixture = body.GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        signature.Add(fixture);
        const b2Filter& filter = fixture->GetFilterData();
        signature.Add((static_cast<std::uint64_t>(fixture->GetType()) << 48u) |
                      (static_cast<std::uint64_t>(fixture->IsSensor()) << 40u) |
                      (static_cast<std::uint64_t>(filter.categoryBits) << 16u) | filter.maskBits);
        signature.Add(fixture->GetFriction());
        signature.Add(fixture->GetRestitution());
        signature.Add(fixture->GetRestitutionThreshold());
        signature.Add(*fixture->GetShape());
    }
    return true;
}

constexpr std::uint32_t kRecent = 8;

// How far around the end of a long motion its clearance is measured, in lengths of the motion (a step's,
// for a particle's first sweep), and at least (m): far enough to skip several steps, near enough to keep
// the query small.
constexpr float kReachSteps = 4.0f;
constexpr float kMinReach = 0.05f;

// Taken off every clearance (m), so that rounding in the distances can never let a particle that flies
// freely on its clearance end up touching a shape that a sweep would have met.
constexpr float kClearanceSlop = 1.0e-3f;

SurfaceMaterial MaterialOf(const b2Fixture& fixture)
{
    return SurfaceMaterial{fixture.GetFriction(), fixture.GetRestitution(), fixture.GetRestitutionThreshold(),
                           fixture.GetBody()};
}

// A box grown by `by` (m) on every side.
b2AABB Grown(const b2AABB& box, float by)
{
    b2AABB grown;
    grown.lowerBound = box.lowerBound - b2Vec2(by, by);
    grown.upperBound = box.upperBound + b2Vec2(by, by);
    return grown;
}

bool HasSolidFixture(const b2Body& body)
{
    for (const b2Fixture* fixture = body.GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        if (!fixture->IsSensor())
        {
            return true;
        }
    }
    return false;
}

// How far (m) a shape's child reaches from `center` (in the shape's frame).
float Reach(const b2Shape& shape, int child, b2Vec2 center)
{
    switch (shape.GetType())
    {
    case b2Shape::e_circle:
    {
        const auto& circle = static_cast<const b2CircleShape&>(shape);
        return b2Distance(circle.m_p, center) + circle.m_radius;
    }
    case b2Shape::e_polygon:
    {
        const auto& polygon = static_cast<const b2PolygonShape&>(shape);
        float reach = 0.0f;
        for (int i = 0; i < polygon.m_count; ++i)
        {
            reach = std::max(reach, b2Distance(polygon.m_vertices[i], center));
        }
        return reach;
    }
    case b2Shape::e_edge:
    {
        const auto& edge = static_cast<const b2EdgeShape&>(shape);
        return std::max(b2Distance(edge.m_vertex1, center), b2Distance(edge.m_vertex2, center));
    }
    case b2Shape::e_chain:
    {
        b2EdgeShape edge;
        static_cast<const b2ChainShape&>(shape).GetChildEdge(&edge, child);
        return std::max(b2Distance(edge.m_vertex1, center), b2Distance(edge.m_vertex2, center));
    }
    default:
        return b2_maxFloat;
    }
}

} // namespace

namespace
{
// Grid cells a moving shape is listed in, on average at most (the cells grow until it holds).
constexpr std::size_t kMovingItemsPerBox = 8;

// Static segments longer than kPieceLength (m) are swept as pieces of that length, at most kMaxSegmentPieces
// of them (longer pieces beyond): a sweep measures a particle from a segment's first end, and a float's
// spacing there limits its precision (1 mm particles raining near the middle of a 50 km edge fell through
// it). Near a piece's last end the rounding of its ends, its normal and the particle's offset add up to a few
// float spacings of its length L: the guarantees hold while the radius is at least 4 of them
// (docs/particles.md). The cap bounds the cache: a file of 999 edges of 2,000 km each made 7.8 million
// pieces.
constexpr double kPieceLength = 256.0;
constexpr double kMaxSegmentPieces = 64.0;
} // namespace

void WorldGeometry::Scan(b2World& world, const BodyFilter* ignore, float dt, StaticWatch watch)
{
    Signature signature;
    m_movingMaterials.clear();
    m_movingBodies.clear();
    m_movingShapes.clear();
    m_movingBoxes.clear();
    for (b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
    {
        if (!body->IsEnabled())
        {
            continue;
        }
        if (body->GetType() == b2_staticBody)
        {
            if (watch == StaticWatch::everyStep)
            {
                m_skippedBodies += AddStaticBody(signature, *body) ? 0 : 1;
            }
            continue;
        }
        if (!IsSane(*body))
        {
            ++m_skippedBodies; // and left out of this step's moving shapes
            continue;
        }
        if (ignore != nullptr && ignore->Ignore(body))
        {
            continue;
        }
        if (!HasSolidFixture(*body))
        {
            continue;
        }
        MovingBody moving;
        moving.after = body->GetTransform();
        moving.center = body->GetWorldCenter();
        moving.velocity = body->GetLinearVelocity();
        moving.angularVelocity = body->GetAngularVelocity();
        // Box2D moved the centre by dt * v and the angle by dt * w: undo that for the start pose.
        moving.before.q.Set(body->GetAngle() - dt * moving.angularVelocity);
        moving.centerBefore = moving.center - dt * moving.velocity;
        moving.before.p = moving.centerBefore - b2Mul(moving.before.q, body->GetLocalCenter());
        moving.localCenter = body->GetLocalCenter();
        moving.turn = dt * moving.angularVelocity;
        moving.angleBefore = body->GetAngle() - moving.turn;
        if (!Sane(moving.centerBefore) || !Sane(b2Vec2(moving.angleBefore, 0.0f)))
        {
            // A huge dt (3e38 s) takes its start pose out of the world, or past a float: skipped too.
            ++m_skippedBodies;
            continue;
        }
        const float pieces = std::ceil(std::abs(moving.turn) / kMaxTurn);
        moving.pieces =
            pieces >= 1.0f ? static_cast<int>(std::min(pieces, static_cast<float>(kMaxPieces))) : 1;
        const auto bodyIndex = static_cast<std::uint32_t>(m_movingBodies.size());
        m_movingBodies.push_back(moving);
        for (b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
        {
            if (fixture->IsSensor())
            {
                continue;
            }
            const auto material = static_cast<std::uint32_t>(m_movingMaterials.size());
            m_movingMaterials.push_back(MaterialOf(*fixture));
            const b2Filter& filter = fixture->GetFilterData();
            const b2Shape& shape = *fixture->GetShape();
            const int children = shape.GetChildCount();
            for (int child = 0; child < children; ++child)
            {
                const float reach = Reach(shape, child, moving.localCenter);
                m_movingShapes.push_back(MovingShape{&shape, child, bodyIndex, material, filter.categoryBits,
                                                     filter.maskBits, reach});
                m_movingBoxes.push_back(SweptBox(moving, shape, child, reach));
            }
        }
    }
    BuildStaticIfStale(world, watch, signature.Value());
    // Moving bodies spread out, pile up and fall out of the world: an item budget keeps the grid's
    // memory a function of their number alone, so a step allocates only when there are more than ever.
    m_movingGrid.Build(m_movingBoxes, Grid::Listing::overlapped, kMovingItemsPerBox);
}

void WorldGeometry::BuildStaticIfStale(b2World& world, StaticWatch watch, std::uint64_t signature)
{
    // Watched: the signature of what the cache is built from. Not watched: built once, and again only after
    // Invalidate.
    const std::uint64_t now = watch == StaticWatch::everyStep ? signature : kBuiltUnwatched;
    if (now != m_signature)
    {
        BuildStatic(world);
        m_signature = now;
    }
}

bool WorldGeometry::UpdateStatic(b2World& world, StaticWatch watch)
{
    Signature signature;
    if (watch == StaticWatch::everyStep)
    {
        for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
        {
            if (body->IsEnabled() && body->GetType() == b2_staticBody)
            {
                AddStaticBody(signature, *body); // the words Scan adds, in the same order
            }
        }
    }
    const std::uint64_t builds = m_builds;
    BuildStaticIfStale(world, watch, signature.Value());
    return m_builds != builds;
}

b2AABB WorldGeometry::SweptBox(const MovingBody& body, const b2Shape& shape, int child, float reach)
{
    b2AABB box;
    if (body.turn == 0.0f)
    {
        // A pure translation: every pose's box lies between the two ends'.
        b2AABB after;
        shape.ComputeAABB(&box, body.before, child);
        shape.ComputeAABB(&after, body.after, child);
        box.Combine(after);
    }
    else
    {
        box = PathBox(body.centerBefore, body.center, reach);
    }
    return Grown(box, MovingSlop(box));
}

void WorldGeometry::BuildStatic(b2World& world)
{
    ++m_builds;
    m_materials.clear();
    m_primitives.clear();
    m_primitiveBoxes.clear();
    m_polygonVertices.clear();
    m_polygonNormals.clear();
    for (b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
    {
        if (!body->IsEnabled() || body->GetType() != b2_staticBody || !IsSane(*body))
        {
            continue;
        }
        const b2Transform& xf = body->GetTransform();
        for (b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
        {
            if (fixture->IsSensor())
            {
                continue;
            }
            Primitive primitive{};
            primitive.material = static_cast<std::uint32_t>(m_materials.size());
            primitive.categoryBits = fixture->GetFilterData().categoryBits;
            primitive.maskBits = fixture->GetFilterData().maskBits;
            m_materials.push_back(MaterialOf(*fixture));
            const b2Shape* shape = fixture->GetShape();
            switch (shape->GetType())
            {
            case b2Shape::e_circle:
            {
                const auto* circle = static_cast<const b2CircleShape*>(shape);
                primitive.kind = Kind::circle;
                primitive.a = b2Mul(xf, circle->m_p);
                primitive.scalar = circle->m_radius;
                m_primitives.push_back(primitive);
                m_primitiveBoxes.push_back(PathBox(primitive.a, primitive.a, circle->m_radius));
                break;
            }
            case b2Shape::e_polygon:
            {
                const auto* polygon = static_cast<const b2PolygonShape*>(shape);
                primitive.kind = Kind::polygon;
                primitive.first = static_cast<std::uint32_t>(m_polygonVertices.size());
                primitive.count = static_cast<std::uint8_t>(polygon->m_count);
                b2AABB box =
                    PathBox(b2Mul(xf, polygon->m_vertices[0]), b2Mul(xf, polygon->m_vertices[0]), 0.0f);
                for (int i = 0; i < polygon->m_count; ++i)
                {
                    const b2Vec2 vertex = b2Mul(xf, polygon->m_vertices[i]);
                    m_polygonVertices.push_back(vertex);
                    m_polygonNormals.push_back(b2Mul(xf.q, polygon->m_normals[i]));
                    box.lowerBound = b2Min(box.lowerBound, vertex);
                    box.upperBound = b2Max(box.upperBound, vertex);
                }
                m_primitives.push_back(primitive);
                m_primitiveBoxes.push_back(box);
                break;
            }
            case b2Shape::e_edge:
            case b2Shape::e_chain:
            {
                const int children = shape->GetChildCount();
                for (int child = 0; child < children; ++child)
                {
                    b2EdgeShape edge;
                    detail::ChildEdge(*shape, child, edge);
                    const b2Vec2 v1 = b2Mul(xf, edge.m_vertex1);
                    const b2Vec2 v2 = b2Mul(xf, edge.m_vertex2);
                    // Ends placed along the segment in doubles: each on its line to within its own
                    // float's spacing.
                    const double dx = static_cast<double>(v2.x) - v1.x;
                    const double dy = static_cast<double>(v2.y) - v1.y;
                    // Bounded before the conversion (an edge of 1e12 m overflowed an int; NaN: one piece).
                    const double wanted = std::ceil(std::hypot(dx, dy) / kPieceLength);
                    const int pieces = wanted > kMaxSegmentPieces ? static_cast<int>(kMaxSegmentPieces)
                                       : wanted > 1.0             ? static_cast<int>(wanted)
                                                                  : 1;
                    b2Vec2 from = v1;
                    for (int piece = 1; piece <= pieces; ++piece)
                    {
                        const double f = static_cast<double>(piece) / pieces;
                        const b2Vec2 to = piece == pieces ? v2
                                                          : b2Vec2(static_cast<float>(v1.x + f * dx),
                                                                   static_cast<float>(v1.y + f * dy));
                        if (to == from)
                        {
                            continue;
                        }
                        const Segment segment = MakeSegment(from, to, edge.m_oneSided);
                        primitive.kind = Kind::segment;
                        primitive.a = segment.v1;
                        primitive.b = segment.v2;
                        primitive.normal = segment.normal;
                        primitive.scalar = segment.invLengthSq;
                        primitive.oneSided = segment.oneSided;
                        m_primitives.push_back(primitive);
                        m_primitiveBoxes.push_back(PathBox(from, to, 0.0f));
                        from = to;
                    }
                }
                break;
            }
            default:
                break;
            }
        }
    }
    DropDuplicatePrimitives();
    m_staticGrid.Build(m_primitiveBoxes, Grid::Listing::neighbourhood, 0, &PrimitiveTouches, this,
                       Grid::Storage::automatic);
}

void WorldGeometry::DropDuplicatePrimitives()
{
    // Everything that decides what a particle meets there: the shape, its filter and its material.
    auto contents = [&](const Primitive& primitive)
    {
        Signature hash;
        hash.Add(primitive.a);
        hash.Add(primitive.b);
        hash.Add(primitive.normal);
        hash.Add(primitive.scalar);
        hash.Add((static_cast<std::uint64_t>(primitive.kind) << 48u) |
                 (static_cast<std::uint64_t>(primitive.count) << 40u) |
                 (static_cast<std::uint64_t>(primitive.oneSided) << 32u) |
                 (static_cast<std::uint64_t>(primitive.categoryBits) << 16u) | primitive.maskBits);
        const SurfaceMaterial& material = m_materials[primitive.material];
        hash.Add(material.friction);
        hash.Add(material.restitution);
        hash.Add(material.restSpeed);
        if (primitive.kind == Kind::polygon)
        {
            for (std::uint32_t i = primitive.first; i < primitive.first + primitive.count; ++i)
            {
                hash.Add(m_polygonVertices[i]);
            }
        }
        return Scramble(hash.Value());
    };
    auto same = [&](const Primitive& x, const Primitive& y)
    {
        const SurfaceMaterial& mx = m_materials[x.material];
        const SurfaceMaterial& my = m_materials[y.material];
        bool equal = x.kind == y.kind && x.count == y.count && x.oneSided == y.oneSided &&
                     x.categoryBits == y.categoryBits && x.maskBits == y.maskBits && Word(x.a) == Word(y.a) &&
                     Word(x.b) == Word(y.b) && Word(x.normal) == Word(y.normal) &&
                     std::bit_cast<std::uint32_t>(x.scalar) == std::bit_cast<std::uint32_t>(y.scalar) &&
                     SameResponse(mx, my);
        for (std::uint32_t i = 0; equal && x.kind == Kind::polygon && i < x.count; ++i)
        {
            equal = Word(m_polygonVertices[x.first + i]) == Word(m_polygonVertices[y.first + i]);
        }
        return equal;
    };
    // An open-addressing table of the kept primitives (index + 1, 0: empty) by their contents' hash, at
    // most half full; it and the hashes keep their room from one build to the next, so a rebuild of as many
    // primitives as before allocates nothing.
    std::size_t tableSize = 16;
    while (tableSize < 2 * m_primitives.size())
    {
        tableSize *= 2;
    }
    m_dedupTable.assign(tableSize, 0);
    m_dedupProbes = 0;
    m_dedupHashes.resize(m_primitives.size());
    const std::size_t mask = tableSize - 1;
    std::uint32_t kept = 0;
    for (std::uint32_t index = 0; index < m_primitives.size(); ++index)
    {
        const Primitive primitive = m_primitives[index];
        const std::uint64_t hash = contents(primitive);
        std::size_t at = static_cast<std::size_t>(hash) & mask;
        bool duplicate = false;
        for (; m_dedupTable[at] != 0; at = (at + 1) & mask)
        {
            ++m_dedupProbes;
            const std::uint32_t other = m_dedupTable[at] - 1;
            if (m_dedupHashes[other] == hash && same(m_primitives[other], primitive))
            {
                duplicate = true;
                break;
            }
        }
        if (duplicate)
        {
            continue; // the same shape again: a particle meets it once
        }
        m_dedupTable[at] = kept + 1;
        m_dedupHashes[kept] = hash;
        m_primitives[kept] = primitive;
        m_primitiveBoxes[kept] = m_primitiveBoxes[index];
        ++kept;
    }
    m_primitives.resize(kept);
    m_primitiveBoxes.resize(kept);
}

bool WorldGeometry::PrimitiveTouches(const void* context, std::uint32_t index, const b2AABB& region)
{
    const auto& geometry = *static_cast<const WorldGeometry*>(context);
    const Primitive& primitive = geometry.m_primitives[index];
    // The region's centre and half extent, grown a little so that rounding never drops a primitive that
    // touches it.
    const b2Vec2 center = region.GetCenter();
    const float slop = MovingSlop(region);
    const b2Vec2 half = region.GetExtents() + b2Vec2(slop, slop);
    // How far the region reaches along unit `axis` from its centre.
    auto reach = [&](b2Vec2 axis) { return std::abs(axis.x) * half.x + std::abs(axis.y) * half.y; };
    switch (primitive.kind)
    {
    case Kind::segment:
        // The region overlaps the segment's box (it lies in it); the segment's line is the other axis.
        return std::abs(b2Dot(primitive.normal, center - primitive.a)) <= reach(primitive.normal);
    case Kind::circle:
    {
        const b2Vec2 nearest = b2Clamp(primitive.a, center - half, center + half);
        return b2DistanceSquared(nearest, primitive.a) <= primitive.scalar * primitive.scalar;
    }
    case Kind::polygon:
    {
        // Separated when the region lies wholly in front of one edge (the box's own axes overlap).
        const b2Vec2* vertices = geometry.m_polygonVertices.data() + primitive.first;
        const b2Vec2* normals = geometry.m_polygonNormals.data() + primitive.first;
        for (int i = 0; i < primitive.count; ++i)
        {
            if (b2Dot(normals[i], center - vertices[i]) > reach(normals[i]))
            {
                return false;
            }
        }
        return true;
    }
    }
    return true;
}

// The distances from one point to the static primitives near it: the clearance's part of a sweep, and a
// cheap test that skips the sweep of a primitive the disc cannot reach this step.
class WorldGeometry::Nearest
{
public:
    /// `reachable`: how far (m) from `point` the disc can touch anything this step.
    Nearest(b2Vec2 point, float reachable)
        : m_point(point), m_reachable(reachable), m_reachableSq(reachable * reachable)
    {
    }

    /// Takes the primitive's distance into account; returns whether it lies within `reachable`.
    bool Add(const WorldGeometry& geometry, const Primitive& primitive)
    {
        switch (primitive.kind)
        {
        case Kind::segment:
        {
            const b2Vec2 e = primitive.b - primitive.a;
            const float u = std::clamp(b2Dot(m_point - primitive.a, e) * primitive.scalar, 0.0f, 1.0f);
            const float distanceSq = b2DistanceSquared(m_point, primitive.a + u * e);
            m_segmentSq = std::min(m_segmentSq, distanceSq);
            return distanceSq <= m_reachableSq;
        }
        case Kind::circle:
        {
            const float distance = b2Distance(m_point, primitive.a) - primitive.scalar;
            m_other = std::min(m_other, distance);
            return distance <= m_reachable;
        }
        case Kind::polygon:
        {
            // The polygon lies behind each edge's line: its distance is at least the largest separation.
            const b2Vec2* vertices = geometry.m_polygonVertices.data() + primitive.first;
            const b2Vec2* normals = geometry.m_polygonNormals.data() + primitive.first;
            float separation = -b2_maxFloat;
            for (int i = 0; i < primitive.count; ++i)
            {
                separation = std::max(separation, b2Dot(normals[i], m_point - vertices[i]));
            }
            m_other = std::min(m_other, separation);
            return separation <= m_reachable;
        }
        }
        return true;
    }

    /// The least distance seen (infinity when none).
    float Distance() const { return std::min(m_other, std::sqrt(m_segmentSq)); }

private:
    b2Vec2 m_point;
    float m_reachable;
    float m_reachableSq;
    /// Squared distance to the nearest segment: one square root at the end.
    float m_segmentSq = std::numeric_limits<float>::infinity();
    float m_other = std::numeric_limits<float>::infinity(); ///< distance to the nearest circle or polygon
};

bool WorldGeometry::CrossesStaticSegment(b2Vec2 from, b2Vec2 to, const ParticleSide& side) const
{
    bool crosses = false;
    m_staticGrid.Query(
        PathBox(from, to, 0.0f),
        [&](std::uint32_t index)
        {
            const Primitive& primitive = m_primitives[index];
            crosses = crosses || (primitive.kind == Kind::segment &&
                                  side.Accepts(primitive.categoryBits, primitive.maskBits) &&
                                  PathCrossesEdge(from, to, primitive.a, primitive.b, primitive.oneSided));
        });
    return crosses;
}

bool WorldGeometry::SweepStatic(const SweepInput& in, const ParticleSide& side, SweepResult& result,
                                float* clearance) const
{
    const b2Vec2 end = in.p + in.d;
    const float r = in.radius;
    // Every primitive lies in the grid's bounds, so it is at least as far from `end` as the bounds are.
    const b2AABB bounds = m_staticGrid.Bounds();
    const float outside = std::max(std::max(bounds.lowerBound.x - end.x, end.x - bounds.upperBound.x),
                                   std::max(bounds.lowerBound.y - end.y, end.y - bounds.upperBound.y));
    // The disc's path lies within |d| + r of `end`: a primitive farther than that is not swept. The slop
    // covers rounding in the distances, so that the skip never changes a result.
    const float length = std::sqrt(b2Dot(in.d, in.d));
    Nearest nearest(end, length + r + kClearanceSlop);
    bool found = false;
    auto test = [&](std::uint32_t index)
    {
        const Primitive& primitive = m_primitives[index];
        if (!side.Accepts(primitive.categoryBits, primitive.maskBits) || !nearest.Add(*this, primitive))
        {
            return;
        }
        bool hit = false;
        switch (primitive.kind)
        {
        case Kind::segment:
            hit = SweepSegment(
                in, Segment{primitive.a, primitive.b, primitive.normal, primitive.scalar, primitive.oneSided},
                result.touch);
            break;
        case Kind::circle:
            hit = SweepCircle(in, primitive.a, primitive.scalar, result.touch);
            break;
        case Kind::polygon:
            hit = SweepPolygon(in, m_polygonVertices.data() + primitive.first,
                               m_polygonNormals.data() + primitive.first, primitive.count, result.touch);
            break;
        }
        if (hit)
        {
            result.material = &m_materials[primitive.material];
            result.surfaceVelocity = b2Vec2(0.0f, 0.0f);
            found = true;
        }
    };

    // Most motions stay within a cell's width of `end` (the disc's path lies within |d| + r of it): the
    // list of end's cell holds every primitive they can touch, and every primitive nearer than a cell.
    const float cell = m_staticGrid.CellSize();
    if (r < cell && b2Dot(in.d, in.d) <= (cell - r) * (cell - r))
    {
        if (outside <= cell) // else every primitive is more than a cell away
        {
            for (const std::uint32_t index : m_staticGrid.Around(end))
            {
                test(index);
            }
        }
        if (clearance != nullptr)
        {
            const float distance = std::min(nearest.Distance(), std::max(cell, outside));
            *clearance = found ? 0.0f : std::max(0.0f, distance - r - kClearanceSlop);
        }
        return found;
    }

    b2AABB query = PathBox(in.p, end, r);
    const float reach = std::max(kMinReach, kReachSteps * length);
    const bool measure = clearance != nullptr && outside - r < reach;
    if (measure)
    {
        // A primitive whose box misses this box is more than r + reach from `end` in one axis.
        query.Combine(PathBox(end, end, r + reach));
    }
    // A primitive listed in several of the cells visited is met once per cell: test it once. The few most
    // recent ones suffice, since a cell's neighbour lists mostly the same primitives.
    std::uint32_t recent[kRecent];
    std::uint32_t recentCount = 0;
    auto testOnce = [&](std::uint32_t index)
    {
        for (std::uint32_t k = 0; k < recentCount && k < kRecent; ++k)
        {
            if (recent[k] == index)
            {
                return;
            }
        }
        recent[recentCount++ % kRecent] = index;
        test(index);
    };
    const b2AABB covered = m_staticGrid.Query(query, testOnce);
    if (clearance != nullptr)
    {
        // Primitives not visited lie outside `covered` (which holds `end`): they are at least `beyond`
        // away (up to rounding in the cell sides, far below kClearanceSlop).
        const float beyond = std::min(std::min(end.x - covered.lowerBound.x, covered.upperBound.x - end.x),
                                      std::min(end.y - covered.lowerBound.y, covered.upperBound.y - end.y));
        const float distance = measure ? std::max(outside, std::min(nearest.Distance(), beyond)) : outside;
        *clearance = found ? 0.0f : std::max(0.0f, distance - r - kClearanceSlop);
    }
    return found;
}

std::size_t WorldGeometry::Bytes() const
{
    return (m_materials.capacity() + m_movingMaterials.capacity()) * sizeof(SurfaceMaterial) +
           m_primitives.capacity() * sizeof(Primitive) + m_primitiveBoxes.capacity() * sizeof(b2AABB) +
           (m_polygonVertices.capacity() + m_polygonNormals.capacity()) * sizeof(b2Vec2) +
           m_staticGrid.Bytes() + m_movingBodies.capacity() * sizeof(MovingBody) +
           m_movingShapes.capacity() * sizeof(MovingShape) + m_movingBoxes.capacity() * sizeof(b2AABB) +
           m_movingGrid.Bytes() + m_dedupTable.capacity() * sizeof(std::uint32_t) +
           m_dedupHashes.capacity() * sizeof(std::uint64_t);
}

} // namespace cfx::particles
