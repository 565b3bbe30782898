#include "fixture_materials.h"

namespace cfx
{

void FixtureMaterials::Set(const b2Fixture* fixture, MaterialId material)
{
    if (material.IsValid())
    {
        m_map.Set(fixture, material.index);
    }
    else
    {
        m_map.Erase(fixture);
    }
}

} // namespace cfx
