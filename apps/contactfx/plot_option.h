// contactfx run / demo --plot FILE.png: a tuning plot of the run (intensity and particles emitted per
// rule over time, thresholds marked), drawn by contactfx_render.
#pragma once

#include "contactfx/render/tuning_plot.h"

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace cfx
{
class Effects;
}

namespace cfx::cli
{

/// Adds --plot FILE.png to `command`, storing the file name in `file`.
void AddPlotOption(CLI::App& command, std::string& file);

/// Records a run for its plot when a plot file was asked for; does nothing otherwise.
class PlotWriter
{
public:
    /// `file` empty: no plot. The command registers the file with its outputs, which check it is a .png.
    PlotWriter(std::string file, const Effects& effects);
    /// After each step of `effects` (dt in seconds).
    void AfterStep(const Effects& effects, float dt);
    /// The plot as PNG bytes, headed by `title`; empty when no plot was asked for. The command writes
    /// it with its other outputs (outputs.h).
    std::string Png(const Effects& effects, const std::string& title) const;

private:
    std::string m_file;
    std::optional<render::TuningRecorder> m_recorder;
};

} // namespace cfx::cli
