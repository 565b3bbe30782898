#include "contactfx/rules.h"

#include <cassert>

namespace cfx
{

RuleTable::RuleTable(int materialCount)
    : m_count(materialCount), m_cells(static_cast<std::size_t>(materialCount * materialCount))
{
}

void RuleTable::Set(MaterialId a, MaterialId b, RuleId rule)
{
    assert(a.IsValid() && b.IsValid() && a.index < m_count && b.index < m_count);
    m_cells[a.index * m_count + b.index] = rule;
    m_cells[b.index * m_count + a.index] = rule;
    if (m_first.size() <= rule.index)
    {
        m_first.resize(rule.index + 1u);
    }
    m_first[rule.index] = a;
}

} // namespace cfx
