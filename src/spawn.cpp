#include "spawn.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <cmath>
#include <initializer_list>

namespace cfx
{

namespace
{

class PointQuery final : public b2QueryCallback
{
public:
    PointQuery(b2Vec2 point, const BodyFilter* ignore) : m_point(point), m_ignore(ignore) {}

    bool ReportFixture(b2Fixture* fixture) override
    {
        if (fixture->IsSensor() || (m_ignore != nullptr && m_ignore->Ignore(fixture->GetBody())))
        {
            return true;
        }
        if (fixture->TestPoint(m_point))
        {
            inside = true;
            return false;
        }
        return true;
    }

    bool inside = false;

private:
    b2Vec2 m_point;
    const BodyFilter* m_ignore;
};

// Whether a disc overlaps any solid fixture (skins of polygons and edges included).
class DiscQuery final : public b2QueryCallback
{
public:
    DiscQuery(b2Vec2 center, float radius, const BodyFilter* ignore) : m_ignore(ignore)
    {
        m_disc.m_radius = radius;
        m_disc.m_p = center;
        m_discProxy.Set(&m_disc, 0);
        m_box.lowerBound = center - b2Vec2(radius, radius);
        m_box.upperBound = center + b2Vec2(radius, radius);
    }

    bool ReportFixture(b2Fixture* fixture) override
    {
        if (fixture->IsSensor() || (m_ignore != nullptr && m_ignore->Ignore(fixture->GetBody())))
        {
            return true;
        }
        const b2Shape* shape = fixture->GetShape();
        for (int child = 0; child < shape->GetChildCount(); ++child)
        {
            if (!b2TestOverlap(fixture->GetAABB(child), m_box))
            {
                continue;
            }
            b2DistanceInput input;
            input.proxyA.Set(shape, child);
            input.proxyB = m_discProxy;
            input.transformA = fixture->GetBody()->GetTransform();
            input.transformB.SetIdentity();
            input.useRadii = true;
            b2SimplexCache cache;
            cache.count = 0;
            b2DistanceOutput output;
            b2Distance(&output, &cache, &input);
            if (output.distance <= 0.0f)
            {
                overlaps = true;
                return false;
            }
        }
        return true;
    }

    const b2AABB& Box() const { return m_box; }
    bool overlaps = false;

private:
    const BodyFilter* m_ignore;
    b2CircleShape m_disc;
    b2DistanceProxy m_discProxy;
    b2AABB m_box;
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

} // namespace

bool IsInsideSolid(const b2World& world, b2Vec2 point, const BodyFilter* ignore)
{
    PointQuery query(point, ignore);
    b2AABB box;
    box.lowerBound = point - b2Vec2(b2_linearSlop, b2_linearSlop);
    box.upperBound = point + b2Vec2(b2_linearSlop, b2_linearSlop);
    world.QueryAABB(&query, box);
    return query.inside;
}

bool DiscIsClear(const b2World& world, b2Vec2 center, float radius, const BodyFilter* ignore)
{
    DiscQuery query(center, radius, ignore);
    world.QueryAABB(&query, query.Box());
    return !query.overlaps;
}

SpawnPoint FindSpawnPoint(const b2World& world, const SpawnQuery& query, const BodyFilter* ignore)
{
    b2Vec2 tangent(-query.normal.y, query.normal.x);
    // Trailing side first: particles are left behind the moving body, as a scrape leaves them.
    float firstSide = b2Dot(query.slip, tangent) > 0.0f ? -1.0f : 1.0f;
    // Ray casts find the core shape; polygons and edges carry a skin of b2_polygonRadius beyond it.
    const b2Shape* shape = query.surface->GetShape();
    const float skin = shape->GetType() == b2Shape::e_circle ? 0.0f : shape->m_radius;
    const float clearance = query.radius + skin + b2_linearSlop;
    float step = std::max(clearance, 0.01f);
    float reach = std::max(4.0f * clearance, 0.25f);

    SpawnPoint fallback;
    fallback.position = query.point + clearance * query.normal;
    fallback.normal = query.normal;

    // Offsets 0, 1, 2, ... 8 steps, then growing by half each time up to the search distance.
    float offset = 0.0f;
    for (int k = 0; offset <= query.searchDistance; ++k)
    {
        for (float side : {firstSide, -firstSide})
        {
            if (k == 0 && side != firstSide)
            {
                continue;
            }
            b2Vec2 along = query.point + (side * offset) * tangent;
            b2Vec2 surfacePoint = along;
            b2Vec2 surfaceNormal = query.normal;
            if (!ProjectOntoSurface(query, along, reach, &surfacePoint, &surfaceNormal))
            {
                // Past the end of the surface (or not facing us): keep the contact plane.
                surfacePoint = along;
                surfaceNormal = query.normal;
            }
            b2Vec2 candidate = surfacePoint + clearance * surfaceNormal;
            if (DiscIsClear(world, candidate, query.radius, ignore))
            {
                return SpawnPoint{candidate, surfaceNormal, true};
            }
        }
        offset = k < 8 ? offset + step : offset * 1.5f;
    }
    return fallback;
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
