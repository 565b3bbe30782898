// contactfx internal: the persistent helper threads (see workers.h).
#include "particles/workers.h"

namespace cfx::particles
{

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

void Workers::Run(unsigned parts, Task task, void* context)
{
    if (parts <= 1)
    {
        task(context, 0);
        return;
    }
    while (m_threads.size() + 1 < parts)
    {
        const auto part = static_cast<unsigned>(m_threads.size()) + 1;
        m_threads.emplace_back([this, part] { Loop(part); });
    }
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        m_task = task;
        m_context = context;
        m_parts = parts;
        m_pending = parts - 1;
        ++m_generation;
    }
    m_wake.notify_all();
    task(context, 0);
    std::unique_lock<std::mutex> lock(m_mutex);
    m_done.wait(lock, [this] { return m_pending == 0; });
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
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            --m_pending;
        }
        m_done.notify_one();
    }
}

} // namespace cfx::particles
