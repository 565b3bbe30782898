// contactfx internal: the fixture children a box meets, from Box2D's broad phase.
//
// b2World::QueryAABB reports a fixture once per child proxy whose box overlaps the query and does not say
// which child: a chain of N segments met by a small box is reported a few times, and a loop over all N
// children per report made every spawn and every particle check cost O(N) (a trial's terrain of one
// 20,000-vertex chain: 429 ms a step against 7.7 ms for the same ground as separate edges). The broad
// phase knows each proxy's child.
//
// Threading: what b2World::QueryAABB allows (reads the broad phase; not while the world steps).
#pragma once

#include <box2d/b2_broad_phase.h>
#include <box2d/b2_contact_manager.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <type_traits>

namespace cfx::detail
{

/// Calls visit(fixture, child, fatBox) once for each child proxy whose broad-phase box (fattened, as Box2D
/// keeps it: `fatBox`) overlaps `box` (b2TestOverlap), in the order b2World::QueryAABB reports them; stops
/// when visit returns false. The order is that of a depth-first walk of Box2D's dynamic tree, pruned where a
/// node's box misses `box`; a node's box holds its children's, so a query with a box inside `box` reports
/// the children this one reports whose fatBox overlaps it, in the same order (while the tree is unchanged).
template <class Visit> void QueryProxies(const b2World& world, const b2AABB& box, Visit&& visit)
{
    struct Callback
    {
        const b2BroadPhase* broadPhase;
        std::remove_reference_t<Visit>* visit;
        bool QueryCallback(int32 proxyId)
        {
            const auto* proxy = static_cast<const b2FixtureProxy*>(broadPhase->GetUserData(proxyId));
            return (*visit)(proxy->fixture, proxy->childIndex, broadPhase->GetFatAABB(proxyId));
        }
    };
    const b2BroadPhase& broadPhase = world.GetContactManager().m_broadPhase;
    Callback callback{&broadPhase, &visit};
    broadPhase.Query(&callback, box);
}

/// Calls visit(fixture, child) once for each child proxy whose broad-phase box (fattened, as Box2D keeps
/// it) overlaps `box`, in the order b2World::QueryAABB reports them; stops when visit returns false.
template <class Visit> void QueryChildren(const b2World& world, const b2AABB& box, Visit&& visit)
{
    QueryProxies(world, box,
                 [&visit](const b2Fixture* fixture, int child, const b2AABB&)
                 { return visit(fixture, child); });
}

} // namespace cfx::detail
