#include "plot_option.h"

#include "contactfx/effects.h"
#include "contactfx/error.h"
#include "contactfx/scene/text_file.h"

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

PlotWriter::PlotWriter(std::string file, const Effects& effects) : m_file(std::move(file))
{
    if (m_file.empty())
    {
        return;
    }
    std::string extension = std::filesystem::path(m_file).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".png")
    {
        throw InputError("<command line>", "--plot", "expected a .png file, found \"" + m_file + "\"");
    }
    m_recorder.emplace(effects.Config().rules.size());
}

void PlotWriter::AfterStep(const Effects& effects, float dt)
{
    if (m_recorder)
    {
        m_recorder->Record(effects.Stats(), dt);
    }
}

void PlotWriter::Write(const Effects& effects, const std::string& title) const
{
    if (m_recorder)
    {
        WriteTextFileAtomically(m_file, render::TuningPlotPng(*m_recorder, effects.Config(), title));
    }
}

} // namespace cfx::cli
