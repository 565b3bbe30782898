// The tuning plot's recorder keeps totals and peaks exactly while folding time into few buckets; the plot
// is a PNG of the announced size.
#include "contactfx/effects.h"
#include "contactfx/presets.h"
#include "contactfx/render/tuning_plot.h"
#include "png_header.h"

#include <cairo.h>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <gtest/gtest.h>
#include <vector>

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
        stats.rules[r].approachMaxLastStep = static_cast<float>((step * 5 + static_cast<int>(r)) % 13) * 0.5f;
        stats.rules[r].impactsLastStep =
            static_cast<std::uint32_t>((step * 3 + static_cast<int>(r)) % 5 == 0);
    }
    return stats;
}

// A decoded PNG: Cairo's ARGB32 pixels, B, G, R, A in memory on little-endian machines.
struct Picture
{
    int width = 0;
    int height = 0;
    std::vector<unsigned char> bgra; // width * 4 bytes a row

    const unsigned char* At(int x, int y) const
    {
        return bgra.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x) * 4;
    }
    // Whether a pixel of column x is the colour (r, g, b) (0..255), give or take 1.
    bool ColumnHas(int x, int r, int g, int b) const
    {
        for (int y = 0; y < height; ++y)
        {
            const unsigned char* p = At(x, y);
            if (std::abs(p[2] - r) <= 1 && std::abs(p[1] - g) <= 1 && std::abs(p[0] - b) <= 1)
            {
                return true;
            }
        }
        return false;
    }
};

Picture Decode(const std::string& png)
{
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
    Picture picture;
    if (cairo_surface_status(image) == CAIRO_STATUS_SUCCESS)
    {
        picture.width = cairo_image_surface_get_width(image);
        picture.height = cairo_image_surface_get_height(image);
        const int stride = cairo_image_surface_get_stride(image);
        const unsigned char* data = cairo_image_surface_get_data(image);
        for (int y = 0; y < picture.height; ++y)
        {
            picture.bgra.insert(picture.bgra.end(), data + y * stride, data + y * stride + 4 * picture.width);
        }
    }
    cairo_surface_destroy(image);
    return picture;
}

} // namespace

TEST(TuningRecorder, FoldsAnyNumberOfStepsIntoBoundedBucketsKeepingTotalsAndPeaks)
{
    constexpr std::size_t kRules = 3;
    constexpr std::size_t kMaxBuckets = 8;
    render::TuningRecorder recorder(kRules, kMaxBuckets);
    std::vector<std::uint64_t> spawned(kRules, 0);
    std::vector<float> peak(kRules, 0.0f);
    std::vector<std::uint64_t> impacts(kRules, 0);
    std::vector<float> fastest(kRules, 0.0f);
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
            impacts[r] += stats.rules[r].impactsLastStep;
            fastest[r] = std::max(fastest[r], stats.rules[r].approachMaxLastStep);
        }
        ASSERT_LE(recorder.BucketCount(), kMaxBuckets);
    }
    EXPECT_GT(recorder.BucketCount(), kMaxBuckets / 2);
    double seconds = 0.0;
    for (std::size_t r = 0; r < kRules; ++r)
    {
        std::uint64_t total = 0;
        std::uint64_t impactTotal = 0;
        float largest = 0.0f;
        float largestApproach = 0.0f;
        for (std::size_t b = 0; b < recorder.BucketCount(); ++b)
        {
            total += recorder.Spawned(b, r);
            largest = std::max(largest, recorder.Intensity(b, r));
            impactTotal += recorder.Impacts(b, r);
            largestApproach = std::max(largestApproach, recorder.Approach(b, r));
        }
        EXPECT_EQ(total, spawned[r]) << r;
        EXPECT_EQ(largest, peak[r]) << r;
        EXPECT_EQ(impactTotal, impacts[r]) << r;
        EXPECT_GT(impactTotal, 100u) << r;
        EXPECT_EQ(largestApproach, fastest[r]) << r;
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
        EXPECT_EQ(recorder.Approach(b, 0), stats.rules[0].approachMaxLastStep);
        EXPECT_EQ(recorder.Impacts(b, 0), stats.rules[0].impactsLastStep);
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
    // A tiny intensity's axis: "0.0000004" ran into the axis's title.
    EXPECT_EQ(render::detail::TickText(4.0e-7, 2.0e-7), "4e-07");
    EXPECT_EQ(render::detail::TickText(0.0, 2.0e-7), "0");
    EXPECT_EQ(render::detail::TickText(0.003, 0.001), "0.003");
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
    const Picture picture = Decode(render::TuningPlotPng(recorder, config, "one step", 640, 100));
    ASSERT_GT(picture.width, 0);
    const int width = picture.width;
    // Columns of the middle half of the picture (no axis labels there) with a pixel of the intensity's blue
    // (0.40, 0.78, 1.00), more or less.
    int columns = 0;
    for (int x = width / 4; x < 3 * width / 4; ++x)
    {
        bool blue = false;
        for (int y = 0; y < picture.height; ++y)
        {
            const unsigned char* p = picture.At(x, y);
            blue = blue || (p[0] > 120 && p[0] > p[2] + 60);
        }
        columns += blue ? 1 : 0;
    }
    EXPECT_EQ(columns, 3 * width / 4 - width / 4);
}

// Under each rule's chart, the strip draws each column's fastest new touch: grey below impactThreshold,
// white where it made an impact, amber where that impact burst (a re-check found smoke's bursts drawn in
// smoke's grey, as if below the threshold: the rule here is the smoke's). A rule whose impacts do not burst
// draws them white.
TEST(TuningPlot, TheImpactStripTellsSoftTouchesImpactsAndBurstsApart)
{
    auto plot = [](float burstPerSpeed, float impactThreshold = 2.0f)
    {
        EffectsConfig config = DefaultPreset();
        config.rules = {config.rules[1]}; // rubber + concrete -> smoke; one panel: every colour is its
        config.rules[0].impactThreshold = impactThreshold;
        config.rules[0].burstThreshold = 0.0f;
        config.rules[0].burstPerSpeed = burstPerSpeed;
        render::TuningRecorder recorder(1);
        for (int step = 0; step < 30; ++step)
        {
            EffectsStats stats;
            stats.rules.resize(1);
            if (step < 10)
            {
                stats.rules[0].approachMaxLastStep = 1.0f; // soft
            }
            else if (step >= 20)
            {
                stats.rules[0].approachMaxLastStep = 6.0f; // an impact every step
                stats.rules[0].impactsLastStep = 1;
            }
            recorder.Record(stats, 1.0f / 60.0f);
        }
        return Decode(render::TuningPlotPng(recorder, config, "impacts", 640, 100));
    };
    // The plot's panel spans x = 84 .. 544 for 0.5 s: steps 0-9 at 84 .. 237, 20-29 at 391 .. 544.
    const Picture withBursts = plot(5.0f);
    const Picture withoutBursts = plot(0.0f);
    ASSERT_GT(withBursts.width, 0);
    ASSERT_GT(withoutBursts.width, 0);
    constexpr int r = 255, g = 140, b = 26; // kBurst (1.00, 0.55, 0.10), whatever the particles' colour
    auto columnsWith = [](const Picture& picture, int from, int to, int red, int green, int blue)
    {
        int count = 0;
        for (int x = from; x < to; ++x)
        {
            count += picture.ColumnHas(x, red, green, blue) ? 1 : 0;
        }
        return count;
    };
    constexpr int kGrey[] = {115, 120, 140};  // kSoftTouch
    constexpr int kWhite[] = {242, 242, 247}; // kImpact
    for (const Picture* picture : {&withBursts, &withoutBursts})
    {
        EXPECT_GT(columnsWith(*picture, 100, 220, kGrey[0], kGrey[1], kGrey[2]), 100);
        EXPECT_EQ(columnsWith(*picture, 250, 380, kGrey[0], kGrey[1], kGrey[2]), 0) << "no touch, no bar";
        EXPECT_EQ(columnsWith(*picture, 250, 380, kWhite[0], kWhite[1], kWhite[2]), 0);
        EXPECT_EQ(columnsWith(*picture, 100, 220, kWhite[0], kWhite[1], kWhite[2]), 0) << "soft: no impact";
    }
    EXPECT_GT(columnsWith(withBursts, 400, 530, r, g, b), 100);
    EXPECT_EQ(columnsWith(withBursts, 400, 530, kWhite[0], kWhite[1], kWhite[2]), 0);
    EXPECT_GT(columnsWith(withoutBursts, 400, 530, kWhite[0], kWhite[1], kWhite[2]), 100);
    EXPECT_EQ(columnsWith(withoutBursts, 400, 530, r, g, b), 0);
    // An impact that asks for no whole particle (6 m/s, 0.2 a m/s from 2 m/s: 0.8) made no burst: white (a
    // trial read an amber bar as a burst that never came).
    const Picture tooFew = plot(0.2f);
    EXPECT_GT(columnsWith(tooFew, 400, 530, kWhite[0], kWhite[1], kWhite[2]), 100);
    EXPECT_EQ(columnsWith(tooFew, 400, 530, r, g, b), 0);
    // A threshold far above every touch (1e4 m/s; the trial's strips were empty, bars 0 px tall at a scale
    // of 17,250 m/s): the axis follows the touches, and they show.
    const Picture huge = plot(0.0f, 1.0e4f);
    EXPECT_GT(columnsWith(huge, 100, 220, kGrey[0], kGrey[1], kGrey[2]), 100);
    EXPECT_GT(columnsWith(huge, 400, 530, kWhite[0], kWhite[1], kWhite[2]), 100);
}

} // namespace cfx::test
