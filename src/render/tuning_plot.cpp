// The tuning plot: a recorder that folds steps into a bounded number of time buckets, and a Cairo
// drawing of it with one panel per rule (intensity against threshold on the left axis, particles per
// second on the right one, the time axis shared at the bottom).
#include "contactfx/render/tuning_plot.h"

#include "contactfx/effects.h"
#include "contactfx/render/png.h"

#include <algorithm>
#include <cairo.h>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace cfx::render
{

void TuningRecorder::Totals::Add(const Totals& later)
{
    intensity = std::max(intensity, later.intensity);
    spawned += later.spawned;
    approach = std::max(approach, later.approach);
    impacts += later.impacts;
}

TuningRecorder::TuningRecorder(std::size_t ruleCount, std::size_t maxBuckets)
    : m_rules(ruleCount), m_maxBuckets(std::max<std::size_t>(2, maxBuckets + (maxBuckets % 2)))
{
    m_totals.assign(m_maxBuckets * m_rules, Totals{});
    m_duration.assign(m_maxBuckets, 0.0);
}

void TuningRecorder::Halve()
{
    // Only called with every bucket full, so pairs merge into buckets of twice the length.
    for (std::size_t b = 0; b < m_bucketCount / 2; ++b)
    {
        for (std::size_t r = 0; r < m_rules; ++r)
        {
            Totals merged = m_totals[2 * b * m_rules + r];
            merged.Add(m_totals[(2 * b + 1) * m_rules + r]);
            m_totals[b * m_rules + r] = merged;
        }
        m_duration[b] = m_duration[2 * b] + m_duration[2 * b + 1];
    }
    m_bucketCount /= 2;
    m_stepsPerBucket *= 2;
    m_stepsInLast = m_stepsPerBucket;
    m_bucketSeconds *= 2.0;
}

void TuningRecorder::Record(const EffectsStats& stats, float dt)
{
    if (m_bucketCount == 0 || m_stepsInLast == m_stepsPerBucket)
    {
        if (m_bucketCount == m_maxBuckets)
        {
            Halve();
        }
        const std::size_t b = m_bucketCount++;
        std::fill_n(m_totals.begin() + static_cast<std::ptrdiff_t>(b * m_rules), m_rules, Totals{});
        m_duration[b] = 0.0;
        m_stepsInLast = 0;
    }
    if (m_bucketSeconds == 0.0)
    {
        m_bucketSeconds = dt;
    }
    const std::size_t b = m_bucketCount - 1;
    const std::size_t rules = std::min(m_rules, stats.rules.size());
    for (std::size_t r = 0; r < rules; ++r)
    {
        const RuleStats& rule = stats.rules[r];
        m_totals[b * m_rules + r].Add(Totals{rule.intensityMaxLastStep, rule.spawnedLastStep,
                                             rule.approachMaxLastStep, rule.impactsLastStep});
    }
    m_duration[b] += dt;
    m_seconds += dt;
    ++m_stepsInLast;
}

namespace
{

constexpr double kLeft = 84.0;   // px, room for the intensity axis
constexpr double kRight = 96.0;  // px, room for the rate axis
constexpr double kHeader = 72.0; // px, title and legend
constexpr double kFooter = 44.0; // px, time axis
constexpr double kGap = 14.0;    // px between panels

struct Rgb
{
    double r, g, b;
};
constexpr Rgb kBackground{0.06, 0.07, 0.10};
constexpr Rgb kPanel{0.10, 0.11, 0.15};
constexpr Rgb kGrid{0.22, 0.24, 0.30};
constexpr Rgb kText{0.88, 0.88, 0.90};
constexpr Rgb kIntensity{0.40, 0.78, 1.00};
constexpr Rgb kThreshold{1.00, 0.38, 0.38};
constexpr Rgb kStrip{0.08, 0.09, 0.12};
constexpr Rgb kSoftTouch{0.45, 0.47, 0.55}; // a new touch below impactThreshold
constexpr Rgb kImpact{0.95, 0.95, 0.97};    // an impact event
constexpr Rgb kBurst{1.00, 0.55, 0.10};     // an impact that burst particles (whatever their colour)

void SetColor(cairo_t* cr, Rgb c, double alpha = 1.0)
{
    cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

/// A step of 1, 2 or 5 times a power of ten giving about `ticks` intervals over `range`.
double NiceStep(double range, int ticks)
{
    const double raw = range / ticks;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double factor : {1.0, 2.0, 5.0})
    {
        if (raw <= factor * power)
        {
            return factor * power;
        }
    }
    return 10.0 * power;
}

std::string Number(double value)
{
    char text[32];
    if (value != 0.0 && (std::abs(value) >= 10000.0 || std::abs(value) < 0.01))
    {
        std::snprintf(text, sizeof text, "%.0e", value);
    }
    else
    {
        std::snprintf(text, sizeof text, "%g", value);
    }
    return text;
}

void Text(cairo_t* cr, double x, double y, const std::string& text, double alignX = 0.0)
{
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    cairo_move_to(cr, x - alignX * extents.x_advance, y);
    cairo_show_text(cr, text.c_str());
}

struct Panel
{
    double x, y, width, height;
};

/// A stretch of time drawn as one column: buckets merged until it is a few pixels wide, so that the
/// particle rate (whole particles per step) reads as a rate instead of a comb.
struct Column
{
    double start = 0.0;    // s
    double duration = 0.0; // s
    TuningRecorder::Totals totals;
    double Rate() const { return static_cast<double>(totals.spawned) / duration; }
};

std::vector<Column> Columns(const TuningRecorder& recorder, std::size_t rule, double minSeconds)
{
    std::vector<Column> columns;
    double t = 0.0;
    for (std::size_t b = 0; b < recorder.BucketCount(); ++b)
    {
        if (columns.empty() || columns.back().duration >= minSeconds)
        {
            columns.push_back(Column{.start = t, .duration = 0.0, .totals = {}});
        }
        Column& column = columns.back();
        column.duration += recorder.Duration(b);
        column.totals.Add(recorder.At(b, rule));
        t += recorder.Duration(b);
    }
    return columns;
}

void VerticalText(cairo_t* cr, double x, double y, const std::string& text)
{
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_rotate(cr, -0.5 * std::numbers::pi);
    Text(cr, 0.0, 0.0, text, 0.5);
    cairo_restore(cr);
}

/// The top of an axis showing values up to `peak` and a level line at `level` (both >= 0): room for both,
/// unless the level is far above everything seen (a huge threshold), which would flatten the curve: then
/// the axis follows the values and the level is drawn at the top, marked as above it.
double AxisTop(double peak, double level)
{
    if (peak > 0.0 && level > 6.0 * peak)
    {
        return 1.15 * peak;
    }
    return std::max({peak, 1.5 * level, 1e-3}) * 1.15;
}

/// A dashed level line across `p` at value `level` of an axis whose top is `top`, labelled on a dark
/// `backing` (bars under it do not hide it), the label's right end `labelRight` px from the panel's right
/// edge; a level above the top is drawn at the top and its label says so.
void LevelLine(cairo_t* cr, const Panel& p, double level, double top, Rgb color, const std::string& label,
               Rgb backing, double labelRight = 4.0)
{
    const bool above = level > top;
    const double y = above ? p.y + 1.0 : p.y + p.height * (1.0 - level / top);
    const double dash[] = {6.0, 4.0};
    cairo_set_dash(cr, dash, 2, 0.0);
    SetColor(cr, color);
    cairo_move_to(cr, p.x, y);
    cairo_line_to(cr, p.x + p.width, y);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    const std::string text = above ? label + " (above)" : label;
    cairo_text_extents_t extents;
    cairo_text_extents(cr, text.c_str(), &extents);
    // Above the line, or below it when the line is too near the panel's top.
    const double baseline = y - 4.0 - extents.height < p.y ? y + extents.height + 3.0 : y - 4.0;
    const double x = p.x + p.width - labelRight - extents.x_advance;
    SetColor(cr, backing, 0.85);
    cairo_rectangle(cr, x - 2.0, baseline - extents.height - 1.0, extents.x_advance + 4.0,
                    extents.height + 3.0);
    cairo_fill(cr);
    SetColor(cr, color);
    Text(cr, x, baseline, text);
}

/// The strip under a rule's chart: each column's fastest new touch as a bar of its approach speed, grey
/// below impactThreshold, white where it made an impact event, amber where that impact burst particles;
/// the thresholds as dashed lines.
void DrawImpactStrip(cairo_t* cr, const Panel& p, const std::vector<Column>& columns, float peak,
                     double seconds, const RuleDef& def)
{
    const double burstFrom = def.BurstFrom();
    const bool bursts = def.burstPerSpeed > 0.0f;
    const double top = AxisTop(peak, bursts ? burstFrom : def.impactThreshold);
    auto xAt = [&](double t) { return p.x + p.width * t / seconds; };
    auto yAt = [&](double v) { return p.y + p.height * (1.0 - v / top); };

    SetColor(cr, kStrip);
    cairo_rectangle(cr, p.x, p.y, p.width, p.height);
    cairo_fill(cr);
    cairo_set_font_size(cr, 10.0);
    const double step = NiceStep(top, 3); // at most 0.83 of the top: one tick above 0 at least
    SetColor(cr, kImpact);
    for (double v = 0.0; v <= top + 1e-9; v += step)
    {
        // A tick near the top is labelled inside the strip, clear of the chart's lowest label above it.
        Text(cr, p.x - 6.0, std::max(yAt(v) + 4.0, p.y + 10.0), detail::TickText(v, step), 1.0);
    }
    VerticalText(cr, p.x - 52.0, p.y + 0.5 * p.height, "m/s");
    for (const Column& column : columns)
    {
        if (column.totals.approach <= 0.0f && column.totals.impacts == 0)
        {
            continue;
        }
        // Amber only where the impact asked for a particle at least (3.1 m/s with a burstPerSpeed of 8
        // from 3 m/s asks for none).
        const bool burst = column.totals.impacts > 0 && def.BurstSize(column.totals.approach) > 0;
        SetColor(cr, burst ? kBurst : column.totals.impacts > 0 ? kImpact : kSoftTouch);
        const double x0 = xAt(column.start);
        const double x1 = std::max(xAt(column.start + column.duration) - 1.0, x0 + 1.0);
        // At least 2 px tall: an impact at 0 m/s (impactThreshold 0) shows too.
        const double y = std::min(yAt(std::min<double>(column.totals.approach, top)), yAt(0.0) - 2.0);
        cairo_rectangle(cr, x0, y, x1 - x0, yAt(0.0) - y);
        cairo_fill(cr);
    }
    cairo_set_line_width(cr, 1.0);
    const std::string impact = "impact " + Number(def.impactThreshold) + " m/s";
    if (bursts && def.burstThreshold > def.impactThreshold)
    {
        // Drawn first, its label left of the impact line's (which may be just below it and is drawn over
        // this line).
        cairo_text_extents_t extents;
        cairo_text_extents(cr, impact.c_str(), &extents);
        LevelLine(cr, p, def.burstThreshold, top, kBurst, "burst " + Number(def.burstThreshold) + " m/s",
                  kStrip, 4.0 + extents.x_advance + 10.0);
    }
    LevelLine(cr, p, def.impactThreshold, top, kThreshold, impact, kStrip);
    SetColor(cr, kText);
    Text(cr, p.x + 8.0, p.y + 12.0, "new touches: approach speed");
}

void DrawPanel(cairo_t* cr, const Panel& panel, const TuningRecorder& recorder, std::size_t rule,
               const RuleDef& def, Rgb particleColor)
{
    constexpr double kColumnPixels = 3.0;
    // The chart on top, the impact strip under it.
    const double stripHeight = std::round(std::clamp(0.28 * panel.height, 20.0, 80.0));
    const Panel p{panel.x, panel.y, panel.width, panel.height - stripHeight - 2.0};
    const double seconds = std::max(recorder.Seconds(), 1e-9);
    const std::vector<Column> columns = Columns(recorder, rule, seconds * kColumnPixels / p.width);
    TuningRecorder::Totals all; // over the whole run
    double peakRate = 0.0;
    for (const Column& column : columns)
    {
        all.Add(column.totals);
        peakRate = std::max(peakRate, column.Rate());
    }
    DrawImpactStrip(cr, Panel{p.x, p.y + p.height + 2.0, p.width, stripHeight}, columns, all.approach,
                    seconds, def);
    const double top = AxisTop(all.intensity, def.threshold);
    const double rateTop = std::max(peakRate, 1.0) * 1.1;
    auto xAt = [&](double t) { return p.x + p.width * t / seconds; };
    auto yAt = [&](double v) { return p.y + p.height * (1.0 - v / top); };
    auto yRate = [&](double v) { return p.y + p.height * (1.0 - v / rateTop); };

    SetColor(cr, kPanel);
    cairo_rectangle(cr, p.x, p.y, p.width, p.height);
    cairo_fill(cr);

    // Where the rule emitted: shaded in the particle's colour, so starts and stops stand out.
    SetColor(cr, particleColor, 0.13);
    for (const Column& column : columns)
    {
        if (column.totals.spawned > 0)
        {
            const double x0 = xAt(column.start);
            cairo_rectangle(cr, x0, p.y, xAt(column.start + column.duration) - x0, p.height);
        }
    }
    cairo_fill(cr);

    // Grid and axes: intensity on the left, particles per second on the right.
    cairo_set_font_size(cr, 11.0);
    cairo_set_line_width(cr, 1.0);
    const double step = NiceStep(top, 5);
    for (double v = 0.0; v <= top + 1e-9; v += step)
    {
        SetColor(cr, kGrid);
        cairo_move_to(cr, p.x, std::round(yAt(v)) + 0.5);
        cairo_line_to(cr, p.x + p.width, std::round(yAt(v)) + 0.5);
        cairo_stroke(cr);
        SetColor(cr, kIntensity);
        Text(cr, p.x - 6.0, yAt(v) + 4.0, detail::TickText(v, step), 1.0);
    }
    VerticalText(cr, p.x - 52.0, p.y + 0.5 * p.height, "intensity");
    const double rateStep = NiceStep(rateTop, 5);
    SetColor(cr, particleColor);
    for (double v = 0.0; v <= rateTop + 1e-9; v += rateStep)
    {
        Text(cr, p.x + p.width + 6.0, yRate(v) + 4.0, detail::TickText(v, rateStep));
    }
    VerticalText(cr, p.x + p.width + 70.0, p.y + 0.5 * p.height, "particles/s");

    // Particles per second: a filled step curve on the right axis.
    cairo_move_to(cr, p.x, yRate(0.0));
    for (const Column& column : columns)
    {
        cairo_line_to(cr, xAt(column.start), yRate(column.Rate()));
        cairo_line_to(cr, xAt(column.start + column.duration), yRate(column.Rate()));
    }
    cairo_line_to(cr, xAt(seconds), yRate(0.0));
    cairo_close_path(cr);
    SetColor(cr, particleColor, 0.45);
    cairo_fill(cr);

    // Intensity: the largest sample of each column, across the column (so one step is a line too).
    for (const Column& column : columns)
    {
        cairo_line_to(cr, xAt(column.start), yAt(column.totals.intensity));
        cairo_line_to(cr, xAt(column.start + column.duration), yAt(column.totals.intensity));
    }
    SetColor(cr, kIntensity);
    cairo_set_line_width(cr, 1.5);
    cairo_stroke(cr);

    // The threshold.
    cairo_set_line_width(cr, 1.5);
    LevelLine(cr, p, def.threshold, top, kThreshold, "threshold " + Number(def.threshold), kPanel);

    // Label.
    cairo_set_font_size(cr, 13.0);
    SetColor(cr, kText);
    Text(cr, p.x + 8.0, p.y + 17.0,
         def.materialA + " + " + def.materialB + "  \xE2\x86\x92  " + def.particleType + "   (" +
             std::to_string(all.spawned) + " particles, " + std::to_string(all.impacts) +
             (all.impacts == 1 ? " impact)" : " impacts)"));
}

} // namespace

std::string TuningPlotPng(const TuningRecorder& recorder, const EffectsConfig& config,
                          const std::string& title, int width, int panelHeight)
{
    if (recorder.RuleCount() != config.rules.size())
    {
        throw std::invalid_argument("tuning plot: the recorder has " + std::to_string(recorder.RuleCount()) +
                                    " rules, the configuration " + std::to_string(config.rules.size()));
    }
    const std::size_t rules = config.rules.size();
    width = std::clamp(width, 320, 8192);
    panelHeight = std::clamp(panelHeight, 60, 2000);
    const double height = kHeader + static_cast<double>(rules) * (panelHeight + kGap) + kFooter;
    const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> image(
        cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, static_cast<int>(std::ceil(height))),
        cairo_surface_destroy);
    cairo_t* cr = cairo_create(image.get());
    SetColor(cr, kBackground);
    cairo_paint(cr);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);

    cairo_set_font_size(cr, 15.0);
    SetColor(cr, kText);
    Text(cr, kLeft, 22.0, title);
    cairo_set_font_size(cr, 12.0);
    SetColor(cr, kIntensity);
    Text(cr, kLeft, 44.0, "\xE2\x80\x94 largest intensity of the step");
    SetColor(cr, kThreshold);
    Text(cr, kLeft + 220.0, 44.0, "- - threshold");
    SetColor(cr, kText);
    Text(cr, kLeft + 330.0, 44.0, "filled: particles emitted per second (right axis); shaded: emitting;");
    Text(cr, kLeft + 330.0, 58.0,
         "strip: fastest new touch (grey: below the impact threshold, white: impact, amber: burst)");

    const double panelWidth = width - kLeft - kRight;
    for (std::size_t r = 0; r < rules; ++r)
    {
        const RuleDef& def = config.rules[r];
        const ParticleTypeId type = config.FindParticleType(def.particleType);
        Rgb color{0.8, 0.8, 0.8};
        if (type.IsValid())
        {
            const Color& c = config.particleTypes[type.index].colorStart;
            color = Rgb{c.r, c.g, c.b};
        }
        const Panel panel{kLeft, kHeader + static_cast<double>(r) * (panelHeight + kGap), panelWidth,
                          static_cast<double>(panelHeight)};
        DrawPanel(cr, panel, recorder, r, def, color);
    }

    // Time axis.
    const double seconds = std::max(recorder.Seconds(), 1e-9);
    const double bottom = kHeader + static_cast<double>(rules) * (panelHeight + kGap) - kGap;
    const double step = NiceStep(seconds, 10);
    cairo_set_font_size(cr, 11.0);
    SetColor(cr, kText);
    cairo_set_line_width(cr, 1.0);
    for (double t = 0.0; t <= seconds + 1e-9; t += step)
    {
        const double x = std::round(kLeft + panelWidth * t / seconds) + 0.5;
        cairo_move_to(cr, x, bottom);
        cairo_line_to(cr, x, bottom + 5.0);
        cairo_stroke(cr);
        Text(cr, x, bottom + 18.0, detail::TickText(t, step), 0.5);
    }
    Text(cr, kLeft + 0.5 * panelWidth, bottom + 36.0, "time (s)", 0.5);

    cairo_destroy(cr);
    cairo_surface_flush(image.get());
    return EncodePng(cairo_image_surface_get_data(image.get()), cairo_image_surface_get_width(image.get()),
                     cairo_image_surface_get_height(image.get()),
                     cairo_image_surface_get_stride(image.get()));
}

std::string detail::TickText(double value, double step)
{
    char text[32];
    if (step >= 1.0e5 || step < 1.0e-3) // "0.0000002" would run into the axis's title
    {
        std::snprintf(text, sizeof text, "%.3g", value);
    }
    else
    {
        const int decimals = step < 1.0 ? static_cast<int>(std::ceil(-std::log10(step) - 1e-9)) : 0;
        std::snprintf(text, sizeof text, "%.*f", decimals, value);
    }
    return text;
}

} // namespace cfx::render
