// contactfx: where a particle starts.
//
// A Box2D contact point lies inside both fixtures (it is the midpoint of the overlap), so a particle
// started there is inside solid geometry: a body-backed particle gets shoved, a pool particle is stuck,
// and behind a one-sided edge it can never come back. FindSpawnPoint looks for a point outside both
// surfaces: it projects the contact point onto the surface fixture's boundary with a ray cast from the
// other body's side (the outside, so one-sided edges and chains are hit from their solid-facing side),
// lifts it by the particle's radius plus the shape's skin (b2_polygonRadius for polygons and edges), and
// walks along the surface, first to the side the particles leave to (SpawnQuery::leaving), until the
// particle's disc is inside no solid fixture of the world. Circles, polygons, edges and chains all answer ray
// casts, so one method serves every shape.
//
// Inside means: the disc overlaps a solid fixture (Solids: not a sensor, and one the particle collides
// with), skins included, or its centre is behind the nearest one-sided edge or chain (they collide on their
// front only, so what is behind them is in the solid they bound). When no start near the contact is outside
// (piles, crevices), the search says so and the particle is not spawned: a particle never starts inside.
#pragma once

#include "particles/collision_filter.h"

#include <box2d/b2_fixture.h>
#include <box2d/b2_math.h>
#include <cstdint>

class b2World;
class b2Fixture;
class b2Body;

namespace cfx
{

/// Decides whether a body is to be ignored by point tests (e.g. the bodies of body-backed particles).
struct BodyFilter
{
    virtual ~BodyFilter() = default;
    virtual bool Ignore(const b2Body* body) const = 0;
};

/// The fixtures a particle's start must keep out of: not sensors, on a body `ignore` does not ignore (null:
/// none ignored), and that the particle collides with by its collision filter (ParticleTypeDef's
/// categoryBits and maskBits, as for a fixture of group 0: decoration filtered to meet no particle does not
/// close a start).
struct Solids
{
    const BodyFilter* ignore = nullptr;
    std::uint16_t categoryBits = 0xFFFF; ///< the particle's (default: every fixture that collides at all)
    std::uint16_t maskBits = 0xFFFF;
    /// Whether the contact's other body (SpawnQuery::otherBody) is kept out of whatever the filter says:
    /// particles then start beside it, not inside it, where they would seem to come out of it. False: only
    /// where the filter meets it, like any fixture (the tutorial's drop, which starts particles inside the
    /// car's wheel or body standing on the contact when they do not collide with it, as the tutorial does).
    bool otherBodyWhateverFilter = true;

    bool Include(const b2Fixture& fixture) const
    {
        const b2Filter& filter = fixture.GetFilterData();
        return !fixture.IsSensor() &&
               particles::FilterAccepts(categoryBits, maskBits, filter.categoryBits, filter.maskBits) &&
               (ignore == nullptr || !ignore->Ignore(fixture.GetBody()));
    }
};

/// One contact side as seen from the surface the particle should start on.
struct SpawnQuery
{
    const b2Fixture* surface = nullptr; ///< the fixture whose boundary the particle starts on
    int surfaceChild = 0;               ///< child index of `surface` (chains)
    b2Vec2 point{0.0f, 0.0f};           ///< contact point, world, m
    b2Vec2 normal{0.0f, 1.0f};          ///< unit normal pointing out of `surface` toward the other fixture
    /// m/s: where the particles go, relative to the other body's footprint on the surface (see
    /// Emitter): the start is searched on the side this points to first, so that they leave the contact
    /// instead of flying into the closing gap beside it.
    b2Vec2 leaving{0.0f, 0.0f};
    /// The body of the other fixture of the contact (may be null): a start inside it only (under a sliding
    /// block) does not end the walk along the surface, a start inside anything else does.
    const b2Body* otherBody = nullptr;
    float radius = 0.01f;        ///< m, > 0: the particle's radius; its whole disc must be clear
    float searchDistance = 1.0f; ///< m: how far along the surface to look, each way
};

struct SpawnPoint
{
    b2Vec2 position{0.0f, 0.0f}; ///< where to start, world, m
    b2Vec2 normal{0.0f, 1.0f};   ///< surface normal there, unit
    bool outside = false;        ///< false when no start outside every solid fixture was found
};

/// A start near the contact outside every solid (see the file comment), `outside` false when none within
/// query.searchDistance along the surface.
SpawnPoint FindSpawnPoint(const b2World& world, const SpawnQuery& query, const Solids& solids);

/// The tutorial's placement: (x, y of the highest static fixture under x, plus 0.05 m), from a ray
/// cast from (x, 1000) down to (x, -1000). `outside` is false when nothing static is under x (the
/// position is then the point itself). Whatever else may stand there is not looked at.
SpawnPoint TutorialDropPoint(const b2World& world, b2Vec2 point);

/// The tutorial's placement, never inside: the drop at query.point's x when the particle's disc there is
/// clear (DiscIsClear), else the drop at x moved along the ground, the side query.leaving.x points to
/// first, by growing steps up to query.searchDistance each way. The tutorial's own drop lands
/// inside the wheel or the car's body that stands on the contact (its particles do not collide with
/// them): so does this one with solids.otherBodyWhateverFilter false; with it true, it lands beside
/// them. `outside` false when no clear drop was found.
SpawnPoint FindTutorialDropPoint(const b2World& world, const SpawnQuery& query, const Solids& solids);

/// Whether a disc is inside none of `solids`: it overlaps none (polygon
/// and edge skins, b2_polygonRadius, included) and its centre is not behind the nearest one-sided edge or
/// chain within 0.1 m of the disc.
bool DiscIsClear(const b2World& world, b2Vec2 center, float radius, const Solids& solids);

/// An audit of a start, independent of DiscIsClear: whether the disc overlaps one of `solids` by more
/// than 10 micrometres, by Box2D's own overlap test
/// (b2TestOverlap, skins included, of the disc made 1e-5 m smaller: b2TestOverlap alone calls a disc within
/// 1.2e-6 m of a surface overlapping), each child of each fixture whose box the disc's box meets. Being
/// behind a one-sided edge or chain is not looked at (Box2D has no test for it).
bool DiscOverlapsSolid(const b2World& world, b2Vec2 center, float radius, const Solids& solids);

} // namespace cfx
