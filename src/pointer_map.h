// contactfx internal: a flat open-addressing map from an object address to a 64-bit value.
//
// Why not std::unordered_map: one allocation per insert and pointer-chasing lookups on every contact
// callback. This map keeps keys and values in two flat arrays (linear probing, backward-shift
// deletion), allocates only when it grows past half full, and never on lookup or erase, so a warmed-up
// world adds and removes contacts without touching the heap. It is never iterated, so its layout has no
// effect on results (determinism). Not thread-safe.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cfx::detail
{

class PointerMap
{
public:
    /// The value for `key`, or nullptr (always for a null key: null marks the empty slots).
    const std::uint64_t* Find(const void* key) const
    {
        if (m_count == 0 || key == nullptr)
        {
            return nullptr;
        }
        for (std::size_t i = Home(key);; i = (i + 1) & m_mask)
        {
            if (m_keys[i] == key)
            {
                return &m_values[i];
            }
            if (m_keys[i] == nullptr)
            {
                return nullptr;
            }
        }
    }
    std::uint64_t* Find(const void* key)
    {
        return const_cast<std::uint64_t*>(static_cast<const PointerMap*>(this)->Find(key));
    }

    /// Inserts or overwrites. `key` must not be null.
    void Set(const void* key, std::uint64_t value);

    /// Removes `key` if present; returns whether it was (never for a null key).
    bool Erase(const void* key);

    std::size_t Size() const { return m_count; }
    /// Makes room for `count` entries so that inserting up to that many does not allocate.
    void Reserve(std::size_t count);

private:
    std::size_t Home(const void* key) const
    {
        auto bits = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(key));
        bits ^= bits >> 33;
        bits *= 0xff51afd7ed558ccdULL;
        bits ^= bits >> 33;
        return static_cast<std::size_t>(bits) & m_mask;
    }
    void Grow();

    std::vector<const void*> m_keys;
    std::vector<std::uint64_t> m_values;
    std::size_t m_mask = 0;
    std::size_t m_count = 0;
};

} // namespace cfx::detail
