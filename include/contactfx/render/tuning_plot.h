// contactfx_render: a plot for tuning thresholds and rates.
//
// Where does an effect start and stop? The plot answers with one panel per rule: the rule's largest
// sample intensity over time against its threshold (a dashed line), and the particles it emitted per
// second, with the stretches where it emitted shaded; below them, a strip of the new touches' approach
// speeds against impactThreshold (and burstThreshold), which says which touches became impacts. A
// recorder samples Effects::Stats() after each step; it keeps at most a fixed number of time buckets (each
// the maximum intensity and approach speed, and the particle and impact counts of its steps), doubling the
// bucket length when full, so a run of any length fits in bounded memory.
#pragma once

#include "contactfx/config.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cfx
{
struct EffectsStats;
}

namespace cfx::render
{

class TuningRecorder
{
public:
    /// What a bucket holds of one rule, and how two stretches of time fold into one.
    struct Totals
    {
        float intensity = 0.0f;    ///< largest sample intensity
        std::uint64_t spawned = 0; ///< particles emitted
        float approach = 0.0f;     ///< m/s: fastest approach of a new touch, impact or not; 0: none
        std::uint64_t impacts = 0; ///< impact events made
        /// Takes `later` in: the largest of the peaks, the sum of the counts.
        void Add(const Totals& later);
    };

    /// For a configuration with `ruleCount` rules; keeps at most `maxBuckets` (>= 2, rounded up to an
    /// even number) time buckets.
    explicit TuningRecorder(std::size_t ruleCount, std::size_t maxBuckets = 1200);

    /// Takes one step's stats (rules[i].intensityMaxLastStep, spawnedLastStep, approachMaxLastStep,
    /// impactsLastStep); `dt` in seconds (> 0).
    void Record(const EffectsStats& stats, float dt);

    std::size_t RuleCount() const { return m_rules; }
    /// Completed and current buckets.
    std::size_t BucketCount() const { return m_bucketCount; }
    /// s covered by each bucket (the last one may be partly filled).
    double BucketSeconds() const { return m_bucketSeconds; }
    double Seconds() const { return m_seconds; }
    /// Rule `rule` in bucket `bucket`.
    const Totals& At(std::size_t bucket, std::size_t rule) const { return m_totals[bucket * m_rules + rule]; }
    /// Largest sample intensity of rule `rule` in bucket `bucket`.
    float Intensity(std::size_t bucket, std::size_t rule) const { return At(bucket, rule).intensity; }
    /// Particles rule `rule` emitted in bucket `bucket`.
    std::uint64_t Spawned(std::size_t bucket, std::size_t rule) const { return At(bucket, rule).spawned; }
    /// Fastest approach (m/s) of a new touch of rule `rule` in bucket `bucket`, impact or not; 0: none.
    float Approach(std::size_t bucket, std::size_t rule) const { return At(bucket, rule).approach; }
    /// Impact events rule `rule` made in bucket `bucket`.
    std::uint64_t Impacts(std::size_t bucket, std::size_t rule) const { return At(bucket, rule).impacts; }
    /// s of simulated time in bucket `bucket`.
    double Duration(std::size_t bucket) const { return m_duration[bucket]; }

private:
    void Halve();

    std::size_t m_rules;
    std::size_t m_maxBuckets;
    std::size_t m_bucketCount = 0;
    std::size_t m_stepsPerBucket = 1;
    std::size_t m_stepsInLast = 0;
    double m_bucketSeconds = 0.0;
    double m_seconds = 0.0;
    std::vector<Totals> m_totals;   // bucket-major
    std::vector<double> m_duration; // per bucket
};

/// The plot of `recorder`'s run of `config` as PNG bytes: `width` x (header + one panel per rule) px.
/// `title` heads the picture (say which scene and which effects config ran). Throws std::invalid_argument
/// when the recorder and the configuration disagree on the rule count.
std::string TuningPlotPng(const TuningRecorder& recorder, const EffectsConfig& config,
                          const std::string& title, int width = 1200, int panelHeight = 170);

namespace detail
{
/// The text of a tick on an axis whose ticks are `step` apart (> 0), in one format for the whole axis: the
/// decimals the step needs (steps of 0.002: "0.000", "0.002", ...), or three significant digits for steps
/// of 100,000 and more and for steps under 0.001 ("2e-07", "4e-07": a tiny intensity's ticks).
std::string TickText(double value, double step);
} // namespace detail

} // namespace cfx::render
