// contactfx internal: a few persistent threads that run the parts of one job.
//
// The particle step cuts its particles into contiguous runs, several per thread, and each thread takes the
// next run not yet taken (particle_system.cpp, StepJob): one part per thread. Starting a thread per
// step would cost more than the work at the sizes where splitting pays, so the helper threads are
// started once (by Start, when their owner is created: never in a step) and sleep on a condition variable
// between jobs. Run() gives part 0 to the calling thread and parts 1 .. n-1 to the helpers, and returns
// when all are done. The caller waits for the helpers awake (yielding) for up to 200 microseconds before
// it sleeps too: they take runs from the same pile and finish about when it does, and a sleeping thread takes
// tens of microseconds to wake on a virtual machine (measured: 27 instead of 57 microseconds for a job of
// empty parts on the project's 2-core machine). No allocation per job (a plain function pointer and context,
// no std::function).
//
// Threading: Run is called from one thread at a time (the one that owns the particle system).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace cfx::particles
{

/// The hardware threads this process may run on: those of its CPU affinity (taskset, a container's
/// cpuset), where the system tells it (Linux), else std::thread::hardware_concurrency(); at least 1.
unsigned UsableHardwareThreads();

class Workers
{
public:
    using Task = void (*)(void* context, unsigned part);

    Workers() = default;
    ~Workers();
    Workers(const Workers&) = delete;
    Workers& operator=(const Workers&) = delete;

    /// Starts the helper threads jobs of up to `parts` parts need (parts - 1), unless they run already.
    void Start(unsigned parts);
    /// Runs task(context, part) for part in [0, parts); the helpers a job of more parts than Start made
    /// room for needs are started first.
    void Run(unsigned parts, Task task, void* context);

private:
    void Loop(unsigned part);

    std::vector<std::thread> m_threads;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::condition_variable m_done;
    std::uint64_t m_generation = 0;
    unsigned m_parts = 0;
    std::atomic<unsigned> m_pending{0};
    bool m_stop = false;
    Task m_task = nullptr;
    void* m_context = nullptr;
};

} // namespace cfx::particles
