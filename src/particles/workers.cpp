// contactfx internal: the persistent helper threads (see workers.h).
#include "particles/workers.h"

#include <algorithm>
#include <chrono>
#if defined(__linux__)
#include <sched.h>
#endif

namespace cfx::particles
{

namespace
{

// How long Run waits awake for the helpers before it sleeps.
constexpr std::chrono::microseconds kAwakeWait{200};

} // namespace

unsigned UsableHardwareThreads()
{
#if defined(__linux__)
    // std::thread::hardware_concurrency counts the machine's threads, not the process's: under taskset -c 0
    // a split step waited for a helper that shared the one core (20 % slower than one thread).
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
    {
        return static_cast<unsigned>(CPU_COUNT(&set));
    }
#endif
    return std::max(1u, std::thread::hardware_concurrency());
}

Workers::~Workers()
{
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_stop = true;
    }
    m_wake.notify_all();
    for (std::thread& thread : m_threads)
    {
        thread.join();
    }
}

void Workers::Start(unsigned parts)
{
    while (m_threads.size() + 1 < parts)
    {
        const auto part = static_cast<unsigned>(m_threads.size()) + 1;
        m_threads.emplace_back([this, part] { Loop(part); });
    }
}

void Workers::Run(unsigned parts, Task task, void* context)
{
    if (parts <= 1)
    {
        task(context, 0);
        return;
    }
    Start(parts);
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_task = task;
        m_context = context;
        m_parts = parts;
        m_pending.store(parts - 1, std::memory_order_relaxed);
        ++m_generation;
    }
    m_wake.notify_all();
    task(context, 0);
    const auto deadline = std::chrono::steady_clock::now() + kAwakeWait;
    while (m_pending.load(std::memory_order_acquire) != 0 && std::chrono::steady_clock::now() < deadline)
    {
        std::this_thread::yield();
    }
    if (m_pending.load(std::memory_order_acquire) != 0)
    {
        std::unique_lock<std::mutex> lock(m_mutex);
        m_done.wait(lock, [this] { return m_pending.load(std::memory_order_acquire) == 0; });
    }
}

void Workers::Loop(unsigned part)
{
    std::uint64_t seen = 0;
    for (;;)
    {
        Task task = nullptr;
        void* context = nullptr;
        {
            std::unique_lock<std::mutex> lock(m_mutex);
            m_wake.wait(lock, [&] { return m_stop || m_generation != seen; });
            if (m_stop)
            {
                return;
            }
            seen = m_generation;
            if (part >= m_parts)
            {
                continue;
            }
            task = m_task;
            context = m_context;
        }
        task(context, part);
        if (m_pending.fetch_sub(1, std::memory_order_acq_rel) == 1)
        {
            // Under the lock, so that a Run about to sleep either sees 0 or gets this notice.
            std::lock_guard<std::mutex> lock(m_mutex);
            m_done.notify_one();
        }
    }
}

} // namespace cfx::particles
