#include "plot_option.h"

#include "contactfx/effects.h"
#include "contactfx/error.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace cfx::cli
{

void AddPlotOption(CLI::App& command, std::string& file)
{
    command.add_option(
        "--plot", file,
        "Write a PNG plot of intensity and particles emitted per rule over time, thresholds marked");
}

void CheckPlotFile(const std::string& file)
{
    if (file.empty())
    {
        return;
    }
    std::string extension = std::filesystem::path(file).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".png")
    {
        throw InputError("<command line>", "--plot", "expected a .png file, found \"" + file + "\"");
    }
}

PlotWriter::PlotWriter(std::string file, const Effects& effects) : m_file(std::move(file))
{
    CheckPlotFile(m_file);
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
