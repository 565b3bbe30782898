#include "plot_option.h"

#include "cli_common.h"
#include "contactfx/effects.h"

namespace cfx::cli
{

void AddPlotOption(CLI::App& command, std::string& file)
{
    command
        .add_option(
            "--plot", file,
            "Write a PNG plot of intensity and particles emitted per rule over time, thresholds marked")
        ->check(NamesAFile());
}

PlotWriter::PlotWriter(std::string file, const Effects& effects) : m_file(std::move(file))
{
    if (!m_file.empty())
    {
        m_recorder.emplace(effects.Config().rules.size());
    }
}

void PlotWriter::AfterStep(const Effects& effects, float dt)
{
    if (m_recorder)
    {
        m_recorder->Record(effects.Stats(), dt);
    }
}

std::string PlotWriter::Png(const Effects& effects, const std::string& title) const
{
    return m_recorder ? render::TuningPlotPng(*m_recorder, effects.Config(), title) : std::string();
}

} // namespace cfx::cli
