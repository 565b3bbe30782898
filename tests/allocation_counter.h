// Test support: replaces the global operator new with one that counts, for the binaries that check that a
// steady state allocates nothing. Include it in exactly one source file of a test binary. Box2D allocates
// with b2Alloc (malloc), which this does not count; contactfx allocates only with new.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>

namespace cfx::test
{

inline std::atomic<long> g_allocations{0};

/// Allocations through operator new since the program started.
inline long Allocations()
{
    return g_allocations.load(std::memory_order_relaxed);
}

} // namespace cfx::test

// GCC, inlining both into one call site, sees the malloc of operator new and the free of operator delete
// and warns of a mismatched pair (-Wmismatched-new-delete), although the two are paired here.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t size)
{
    cfx::test::g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* memory = std::malloc(size == 0 ? 1 : size))
    {
        return memory;
    }
    throw std::bad_alloc();
}
void* operator new[](std::size_t size)
{
    return operator new(size);
}
void operator delete(void* memory) noexcept
{
    std::free(memory);
}
void operator delete[](void* memory) noexcept
{
    std::free(memory);
}
void operator delete(void* memory, std::size_t) noexcept
{
    std::free(memory);
}
void operator delete[](void* memory, std::size_t) noexcept
{
    std::free(memory);
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
