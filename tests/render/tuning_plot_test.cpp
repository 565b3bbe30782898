// The tuning plot's recorder keeps totals and peaks exactly while folding time into few buckets; the plot
// is a PNG of the announced size.
#include "contactfx/effects.h"
#include "contactfx/presets.h"
#include "contactfx/render/tuning_plot.h"
#include "png_header.h"

#include <cairo.h>
#include <cstring>
#include <gtest/gtest.h>

namespace cfx::test
{

namespace
{

// Stats of one step: rule r has intensity f(step, r) and spawned g(step, r).
EffectsStats StepStats(std::size_t rules, int step)
{
    EffectsStats stats;
    stats.rules.resize(rules);
    for (std::size_t r = 0; r < rules; ++r)
    {
        stats.rules[r].intensityMaxLastStep = static_cast<float>((step * 7 + static_cast<int>(r) * 3) % 11);
        stats.rules[r].spawnedLastStep = static_cast<std::uint32_t>((step + static_cast<int>(r)) % 4);
    }
    return stats;
}

} // namespace

TEST(TuningRecorder, FoldsAnyNumberOfStepsIntoBoundedBucketsKeepingTotalsAndPeaks)
{
    constexpr std::size_t kRules = 3;
    constexpr std::size_t kMaxBuckets = 8;
    render::TuningRecorder recorder(kRules, kMaxBuckets);
    std::vector<std::uint64_t> spawned(kRules, 0);
    std::vector<float> peak(kRules, 0.0f);
    constexpr int kSteps = 1001;
    constexpr float kDt = 0.01f;
    for (int step = 0; step < kSteps; ++step)
    {
        const EffectsStats stats = StepStats(kRules, step);
        recorder.Record(stats, kDt);
        for (std::size_t r = 0; r < kRules; ++r)
        {
            spawned[r] += stats.rules[r].spawnedLastStep;
            peak[r] = std::max(peak[r], stats.rules[r].intensityMaxLastStep);
        }
        ASSERT_LE(recorder.BucketCount(), kMaxBuckets);
    }
    EXPECT_GT(recorder.BucketCount(), kMaxBuckets / 2);
    double seconds = 0.0;
    for (std::size_t r = 0; r < kRules; ++r)
    {
        std::uint64_t total = 0;
        float largest = 0.0f;
        for (std::size_t b = 0; b < recorder.BucketCount(); ++b)
        {
            total += recorder.Spawned(b, r);
            largest = std::max(largest, recorder.Intensity(b, r));
        }
        EXPECT_EQ(total, spawned[r]) << r;
        EXPECT_EQ(largest, peak[r]) << r;
    }
    for (std::size_t b = 0; b < recorder.BucketCount(); ++b)
    {
        seconds += recorder.Duration(b);
    }
    EXPECT_NEAR(seconds, kSteps * kDt, 1e-6);
    EXPECT_NEAR(recorder.Seconds(), kSteps * kDt, 1e-6);
}

TEST(TuningRecorder, KeepsEveryStepWhileThereIsRoom)
{
    render::TuningRecorder recorder(1, 64);
    for (int step = 0; step < 10; ++step)
    {
        recorder.Record(StepStats(1, step), 0.5f);
    }
    ASSERT_EQ(recorder.BucketCount(), 10u);
    for (std::size_t b = 0; b < 10; ++b)
    {
        const EffectsStats stats = StepStats(1, static_cast<int>(b));
        EXPECT_EQ(recorder.Intensity(b, 0), stats.rules[0].intensityMaxLastStep);
        EXPECT_EQ(recorder.Spawned(b, 0), stats.rules[0].spawnedLastStep);
        EXPECT_EQ(recorder.Duration(b), 0.5);
    }
}

TEST(TuningPlot, IsAPngWithOnePanelPerRule)
{
    const EffectsConfig config = DefaultPreset();
    render::TuningRecorder recorder(config.rules.size());
    for (int step = 0; step < 120; ++step)
    {
        recorder.Record(StepStats(config.rules.size(), step), 1.0f / 60.0f);
    }
    const auto one = PngSize(render::TuningPlotPng(recorder, config, "test", 640, 100));
    ASSERT_TRUE(one.has_value());
    EXPECT_EQ(one->first, 640u);
    EffectsConfig fewer = config;
    fewer.rules.pop_back();
    EXPECT_THROW(render::TuningPlotPng(recorder, fewer, "test"), std::invalid_argument);
    render::TuningRecorder smaller(fewer.rules.size());
    smaller.Record(StepStats(fewer.rules.size(), 0), 1.0f / 60.0f);
    const auto two = PngSize(render::TuningPlotPng(smaller, fewer, "test", 640, 100));
    ASSERT_TRUE(two.has_value());
    // One rule fewer: one panel of 100 px and its gap fewer.
    EXPECT_GT(one->second, two->second + 100u);
}

// A trial's plot of a run of 0.01 s labelled its time axis "0, 2e-03, 4e-03, ..., 0.01, 0.012": each axis
// has one format.
TEST(TuningPlot, EachAxisLabelsItsTicksInOneFormat)
{
    std::vector<std::string> ticks;
    for (int i = 0; i <= 8; ++i)
    {
        ticks.push_back(render::detail::TickText(0.002 * i, 0.002));
    }
    EXPECT_EQ(ticks, (std::vector<std::string>{"0.000", "0.002", "0.004", "0.006", "0.008", "0.010", "0.012",
                                               "0.014", "0.016"}));
    EXPECT_EQ(render::detail::TickText(1.5, 0.5), "1.5");
    EXPECT_EQ(render::detail::TickText(2.0, 0.5), "2.0");
    EXPECT_EQ(render::detail::TickText(15000.0, 5000.0), "15000");
    EXPECT_EQ(render::detail::TickText(1.2e6, 2.0e5), "1.2e+06");
}

// The same trial's plot of one step had no intensity line: it joined the middles of the columns, and one
// column has no line between middles. Each column's intensity runs across it.
TEST(TuningPlot, OneStepHasAnIntensityLine)
{
    const EffectsConfig config = DefaultPreset();
    render::TuningRecorder recorder(config.rules.size());
    EffectsStats stats = StepStats(config.rules.size(), 0);
    stats.rules[0].intensityMaxLastStep = 30.0f;
    recorder.Record(stats, 1.0f / 60.0f);
    const std::string png = render::TuningPlotPng(recorder, config, "one step", 640, 100);
    std::size_t read = 0;
    const auto reader = [](void* closure, unsigned char* data, unsigned int length)
    {
        auto* source = static_cast<std::pair<const std::string*, std::size_t*>*>(closure);
        if (*source->second + length > source->first->size())
        {
            return CAIRO_STATUS_READ_ERROR;
        }
        std::memcpy(data, source->first->data() + *source->second, length);
        *source->second += length;
        return CAIRO_STATUS_SUCCESS;
    };
    std::pair<const std::string*, std::size_t*> source{&png, &read};
    cairo_surface_t* image = cairo_image_surface_create_from_png_stream(reader, &source);
    ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
    const int width = cairo_image_surface_get_width(image);
    const int height = cairo_image_surface_get_height(image);
    const int stride = cairo_image_surface_get_stride(image);
    const unsigned char* data = cairo_image_surface_get_data(image);
    // Columns of the middle half of the picture (no axis labels there) with a pixel of the intensity's blue
    // (0.40, 0.78, 1.00), more or less: Cairo stores B, G, R, A on little-endian machines.
    int columns = 0;
    for (int x = width / 4; x < 3 * width / 4; ++x)
    {
        bool blue = false;
        for (int y = 0; y < height; ++y)
        {
            const unsigned char* p = data + y * stride + 4 * x;
            blue = blue || (p[0] > 120 && p[0] > p[2] + 60);
        }
        columns += blue ? 1 : 0;
    }
    cairo_surface_destroy(image);
    EXPECT_EQ(columns, 3 * width / 4 - width / 4);
}

} // namespace cfx::test
