// The helper threads of a particle step: every part runs once, on its own thread, and Run returns only
// when all are done, whether the helpers finish while the caller waits awake or after it went to sleep.
#include "particles/workers.h"

#include <array>
#include <atomic>
#include <chrono>
#include <gtest/gtest.h>
#include <thread>

namespace cfx::particles
{
namespace
{

struct Job
{
    std::array<std::atomic<int>, 3> runs{};
    std::array<std::thread::id, 3> threads{};
    std::chrono::microseconds helperTime{0};

    static void Run(void* context, unsigned part)
    {
        auto& job = *static_cast<Job*>(context);
        if (part > 0)
        {
            std::this_thread::sleep_for(job.helperTime);
        }
        job.threads[part] = std::this_thread::get_id();
        job.runs[part].fetch_add(1);
    }
};

TEST(Workers, RunsEveryPartOnceOnItsOwnThreadAndReturnsWhenAllAreDone)
{
    Workers workers;
    // Helpers that finish at once (the caller is still waiting awake) and after 2 ms (it is asleep).
    for (const auto helperTime : {std::chrono::microseconds{0}, std::chrono::microseconds{2000}})
    {
        for (int repeat = 0; repeat < 20; ++repeat)
        {
            Job job;
            job.helperTime = helperTime;
            workers.Run(3, &Job::Run, &job);
            for (unsigned part = 0; part < 3; ++part)
            {
                ASSERT_EQ(job.runs[part].load(), 1)
                    << "part " << part << ", helpers taking " << helperTime.count() << " us";
            }
            EXPECT_EQ(job.threads[0], std::this_thread::get_id());
            EXPECT_NE(job.threads[1], job.threads[0]);
            EXPECT_NE(job.threads[2], job.threads[0]);
            EXPECT_NE(job.threads[1], job.threads[2]);
        }
    }
    // Fewer parts than helpers: the idle helper runs nothing.
    Job job;
    workers.Run(2, &Job::Run, &job);
    EXPECT_EQ(job.runs[0].load() + job.runs[1].load() + job.runs[2].load(), 2);
    EXPECT_EQ(job.runs[2].load(), 0);
}

} // namespace
} // namespace cfx::particles
