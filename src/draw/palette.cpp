// Shape colours by material, and the walk over a world's fixtures that feeds them to a b2Draw.
#include "contactfx/draw/palette.h"

#include "contactfx/effects.h"

#include <array>
#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>

namespace cfx
{

ShapePalette TutorialPalette()
{
    ShapePalette palette;
    palette.materials = {{"steel", b2Color(1.0f, 0.0f, 0.0f)},
                         {"rubber", b2Color(0.5f, 0.5f, 0.5f)},
                         {"concrete", b2Color(0.9f, 0.9f, 0.9f)},
                         {"dirt", b2Color(1.0f, 0.6f, 0.4f)}};
    return palette;
}

b2Color FixtureColor(const Effects& effects, const ShapePalette& palette, const b2Fixture& fixture)
{
    const MaterialId material = effects.Material(&fixture);
    if (material.IsValid())
    {
        const std::string& name = effects.Config().materials[material.index];
        for (const ShapePalette::Entry& entry : palette.materials)
        {
            if (entry.material == name)
            {
                return entry.color;
            }
        }
    }
    switch (fixture.GetBody()->GetType())
    {
    case b2_staticBody:
        return palette.staticBody;
    case b2_kinematicBody:
        return palette.kinematicBody;
    default:
        return palette.dynamicBody;
    }
}

namespace
{

void DrawFixture(const b2Fixture& fixture, const b2Transform& xf, const b2Color& color, b2Draw& draw)
{
    switch (fixture.GetType())
    {
    case b2Shape::e_circle:
    {
        const auto* circle = static_cast<const b2CircleShape*>(fixture.GetShape());
        draw.DrawSolidCircle(b2Mul(xf, circle->m_p), circle->m_radius, xf.q.GetXAxis(), color);
        break;
    }
    case b2Shape::e_polygon:
    {
        const auto* polygon = static_cast<const b2PolygonShape*>(fixture.GetShape());
        std::array<b2Vec2, b2_maxPolygonVertices> vertices;
        for (int32 i = 0; i < polygon->m_count; ++i)
        {
            vertices[i] = b2Mul(xf, polygon->m_vertices[i]);
        }
        draw.DrawSolidPolygon(vertices.data(), polygon->m_count, color);
        break;
    }
    case b2Shape::e_edge:
    {
        const auto* edge = static_cast<const b2EdgeShape*>(fixture.GetShape());
        draw.DrawSegment(b2Mul(xf, edge->m_vertex1), b2Mul(xf, edge->m_vertex2), color);
        break;
    }
    case b2Shape::e_chain:
    {
        const auto* chain = static_cast<const b2ChainShape*>(fixture.GetShape());
        for (int32 i = 0; i + 1 < chain->m_count; ++i)
        {
            draw.DrawSegment(b2Mul(xf, chain->m_vertices[i]), b2Mul(xf, chain->m_vertices[i + 1]), color);
        }
        break;
    }
    default:
        break;
    }
}

} // namespace

void DrawShapes(const Effects& effects, b2Draw& draw, const ShapePalette& palette, BodyKinds kinds)
{
    for (const bool staticPass : {true, false})
    {
        if ((staticPass && kinds == BodyKinds::moving) || (!staticPass && kinds == BodyKinds::fixed))
        {
            continue;
        }
        for (const b2Body* body = effects.World().GetBodyList(); body != nullptr; body = body->GetNext())
        {
            // A body-backed particle's body is the particle, drawn as one (DrawParticles), not as a shape.
            if (!body->IsEnabled() || (body->GetType() == b2_staticBody) != staticPass ||
                effects.IsParticleBody(body))
            {
                continue;
            }
            const b2Transform& xf = body->GetTransform();
            for (const b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr;
                 fixture = fixture->GetNext())
            {
                DrawFixture(*fixture, xf, FixtureColor(effects, palette, *fixture), draw);
            }
        }
    }
}

} // namespace cfx
