// contactfx benchmarks: what the benchmark scenes share to turn timings into results.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace cfx::bench
{

inline double Milliseconds(std::chrono::steady_clock::duration duration)
{
    return std::chrono::duration<double, std::milli>(duration).count();
}

/// The least and the median (the (n/2+1)-th smallest) of `values`, sorted in place; 0 when empty.
inline void Summarize(std::vector<double>& values, double& minOut, double& medianOut)
{
    std::sort(values.begin(), values.end());
    minOut = values.empty() ? 0.0 : values.front();
    medianOut = values.empty() ? 0.0 : values[values.size() / 2];
}

} // namespace cfx::bench
