#include "fixture_materials.h"

#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <cstring>

namespace cfx
{

namespace
{

class Hash
{
public:
    void Add(std::uint64_t word)
    {
        m_state = (m_state ^ word) * 0x9E3779B97F4A7C15ULL;
        m_state ^= m_state >> 29;
    }
    void Add(const void* pointer)
    {
        Add(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(pointer)));
    }
    void Add(float value)
    {
        std::uint32_t bits = 0;
        std::memcpy(&bits, &value, sizeof(bits));
        Add(std::uint64_t{bits});
    }
    void Add(b2Vec2 value)
    {
        Add(value.x);
        Add(value.y);
    }
    std::uint64_t Value() const { return m_state; }

private:
    std::uint64_t m_state = 0x243F6A8885A308D3ULL;
};

// Who the fixture is, in the upper 48 bits (the lower 16 hold the material).
std::uint64_t Identity(const b2Fixture* fixture)
{
    Hash hash;
    const b2Shape* shape = fixture->GetShape();
    hash.Add(static_cast<const void*>(fixture->GetBody()));
    hash.Add(static_cast<const void*>(shape));
    hash.Add(static_cast<std::uint64_t>(shape->GetType()));
    hash.Add(static_cast<std::uint64_t>(shape->GetChildCount()));
    hash.Add(shape->m_radius);
    switch (shape->GetType())
    {
    case b2Shape::e_circle:
        hash.Add(static_cast<const b2CircleShape*>(shape)->m_p);
        break;
    case b2Shape::e_edge:
    {
        const auto* edge = static_cast<const b2EdgeShape*>(shape);
        hash.Add(edge->m_vertex1);
        hash.Add(edge->m_vertex2);
        break;
    }
    case b2Shape::e_polygon:
    {
        const auto* polygon = static_cast<const b2PolygonShape*>(shape);
        for (int i = 0; i < polygon->m_count; ++i)
        {
            hash.Add(polygon->m_vertices[i]);
        }
        break;
    }
    case b2Shape::e_chain:
    {
        // The ends only: a chain may have thousands of vertices, and this runs on every lookup.
        const auto* chain = static_cast<const b2ChainShape*>(shape);
        if (chain->m_count > 0)
        {
            hash.Add(chain->m_vertices[0]);
            hash.Add(chain->m_vertices[chain->m_count - 1]);
        }
        break;
    }
    default:
        break;
    }
    return hash.Value() & ~std::uint64_t{0xFFFF};
}

} // namespace

void FixtureMaterials::Set(const b2Fixture* fixture, MaterialId material)
{
    if (material.IsValid())
    {
        m_map.Set(fixture, Identity(fixture) | material.index);
    }
    else
    {
        m_map.Erase(fixture);
    }
}

MaterialId FixtureMaterials::Get(const b2Fixture* fixture) const
{
    const std::uint64_t* value = m_map.Find(fixture);
    if (value == nullptr)
    {
        return MaterialId{};
    }
    if ((*value & ~std::uint64_t{0xFFFF}) != Identity(fixture))
    {
        // Recorded for a fixture destroyed without Effects::ForgetFixture; this one only took its address.
        m_map.Erase(fixture);
        ++m_stale;
        return MaterialId{};
    }
    return MaterialId{static_cast<std::uint16_t>(*value & 0xFFFFu)};
}

} // namespace cfx
