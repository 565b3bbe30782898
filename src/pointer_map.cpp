#include "pointer_map.h"

namespace cfx::detail
{

void PointerMap::Set(const void* key, std::uint64_t value)
{
    if (std::uint64_t* existing = Find(key))
    {
        *existing = value;
        return;
    }
    if ((m_count + 1) * 2 > m_keys.size())
    {
        Grow();
    }
    std::size_t i = Home(key);
    while (m_keys[i] != nullptr)
    {
        i = (i + 1) & m_mask;
    }
    m_keys[i] = key;
    m_values[i] = value;
    ++m_count;
}

bool PointerMap::Erase(const void* key)
{
    if (m_count == 0 || key == nullptr)
    {
        return false;
    }
    std::size_t i = Home(key);
    while (m_keys[i] != key)
    {
        if (m_keys[i] == nullptr)
        {
            return false;
        }
        i = (i + 1) & m_mask;
    }
    // Backward-shift deletion: pull later entries of the probe run into the hole, no tombstones.
    std::size_t hole = i;
    for (std::size_t j = (hole + 1) & m_mask; m_keys[j] != nullptr; j = (j + 1) & m_mask)
    {
        std::size_t home = Home(m_keys[j]);
        bool between = hole <= j ? (hole < home && home <= j) : (hole < home || home <= j);
        if (!between)
        {
            m_keys[hole] = m_keys[j];
            m_values[hole] = m_values[j];
            hole = j;
        }
    }
    m_keys[hole] = nullptr;
    --m_count;
    return true;
}

void PointerMap::Reserve(std::size_t count)
{
    while (count * 2 > m_keys.size())
    {
        Grow();
    }
}

void PointerMap::Grow()
{
    std::vector<const void*> oldKeys = std::move(m_keys);
    std::vector<std::uint64_t> oldValues = std::move(m_values);
    std::size_t size = oldKeys.empty() ? 64 : oldKeys.size() * 2;
    m_keys.assign(size, nullptr);
    m_values.assign(size, 0);
    m_mask = size - 1;
    m_count = 0;
    for (std::size_t i = 0; i < oldKeys.size(); ++i)
    {
        if (oldKeys[i] != nullptr)
        {
            Set(oldKeys[i], oldValues[i]);
        }
    }
}

} // namespace cfx::detail
