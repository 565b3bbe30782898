#include "contactfx/rules.h"

#include "contactfx/error.h"

#include <string>

namespace cfx
{

namespace
{

// The unordered pair as one key: the smaller id in the high half. Never kEmptyKey (ids are < 0xFFFF).
std::uint32_t PairKey(MaterialId a, MaterialId b)
{
    const std::uint32_t low = a.index < b.index ? a.index : b.index;
    const std::uint32_t high = a.index < b.index ? b.index : a.index;
    return (low << 16) | high;
}

constexpr std::uint32_t kEmptyKey = 0xFFFFFFFFu;

} // namespace

std::string PairName(const RuleDef& rule)
{
    return rule.materialB < rule.materialA ? rule.materialB + "+" + rule.materialA
                                           : rule.materialA + "+" + rule.materialB;
}

RuleTable::RuleTable(int materialCount) : m_count(materialCount)
{
    if (materialCount < 0 || materialCount > MaterialId::kNone)
    {
        throw InputError("<api>", "materialCount",
                         std::to_string(materialCount) + " is not within 0 .. " +
                             std::to_string(MaterialId::kNone));
    }
    if (materialCount <= kDenseMaterials)
    {
        m_cells.resize(static_cast<std::size_t>(materialCount) * static_cast<std::size_t>(materialCount));
    }
    else
    {
        m_cells.resize(16);
        m_keys.assign(16, kEmptyKey);
    }
}

std::size_t RuleTable::HashedSlot(std::uint32_t key) const
{
    const std::size_t mask = m_keys.size() - 1;
    // Every bit of the key reaches the low bits (a multiply alone leaves the low bits to the low half, the
    // larger id: one material with thousands of rules probed one cluster, 5 microseconds a lookup).
    std::uint32_t mixed = key;
    mixed ^= mixed >> 16;
    mixed *= 0x7feb352du;
    mixed ^= mixed >> 15;
    mixed *= 0x846ca68bu;
    mixed ^= mixed >> 16;
    std::size_t slot = mixed & mask; // linear probing
    while (m_keys[slot] != key && m_keys[slot] != kEmptyKey)
    {
        slot = (slot + 1) & mask;
    }
    return slot;
}

RuleId RuleTable::FindHashed(MaterialId a, MaterialId b) const
{
    const std::size_t slot = HashedSlot(PairKey(a, b));
    return m_keys[slot] == kEmptyKey ? RuleId{} : m_cells[slot];
}

void RuleTable::Set(MaterialId a, MaterialId b, RuleId rule)
{
    if (!a.IsValid() || !b.IsValid() || a.index >= m_count || b.index >= m_count || !rule.IsValid())
    {
        throw InputError("<api>", "rule",
                         "materials " + std::to_string(a.index) + " and " + std::to_string(b.index) +
                             " or rule " + std::to_string(rule.index) + " out of range (" +
                             std::to_string(m_count) + " materials)");
    }
    if (m_count <= kDenseMaterials)
    {
        const auto count = static_cast<std::size_t>(m_count);
        m_cells[a.index * count + b.index] = rule;
        m_cells[b.index * count + a.index] = rule;
    }
    else
    {
        std::size_t slot = HashedSlot(PairKey(a, b));
        if (m_keys[slot] == kEmptyKey)
        {
            if (2 * (m_pairs + 1) > m_keys.size())
            {
                // Rehash into twice the slots, then find the new pair's slot there.
                std::vector<std::uint32_t> keys(2 * m_keys.size(), kEmptyKey);
                std::vector<RuleId> cells(keys.size());
                keys.swap(m_keys);
                cells.swap(m_cells);
                for (std::size_t old = 0; old < keys.size(); ++old)
                {
                    if (keys[old] != kEmptyKey)
                    {
                        const std::size_t moved = HashedSlot(keys[old]);
                        m_keys[moved] = keys[old];
                        m_cells[moved] = cells[old];
                    }
                }
                slot = HashedSlot(PairKey(a, b));
            }
            m_keys[slot] = PairKey(a, b);
            ++m_pairs;
        }
        m_cells[slot] = rule;
    }
    if (m_first.size() <= rule.index)
    {
        m_first.resize(rule.index + 1u);
    }
    m_first[rule.index] = a;
}

} // namespace cfx
