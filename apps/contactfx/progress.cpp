#include "progress.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace cfx::cli
{

Progress::Progress(std::string label, std::uint64_t total, std::string unit)
    : m_label(std::move(label)), m_unit(std::move(unit)), m_total(std::max<std::uint64_t>(total, 1)),
      m_terminal(::isatty(STDERR_FILENO) == 1)
{
}

void Progress::Update(std::uint64_t done)
{
    done = std::min(done, m_total);
    const int percent = static_cast<int>(100 * done / m_total);
    const int shown = m_terminal ? percent : percent / 10;
    if (shown == m_shown)
    {
        return;
    }
    m_shown = shown;
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                            std::string(static_cast<std::size_t>(kWidth - filled), '.');
    std::fprintf(stderr, "%s%s [%s] %3d%% %llu/%llu %s%s", m_terminal ? "\r" : "", m_label.c_str(),
                 bar.c_str(), percent, static_cast<unsigned long long>(done),
                 static_cast<unsigned long long>(m_total), m_unit.c_str(), m_terminal ? "" : "\n");
    std::fflush(stderr);
}

void Progress::Finish()
{
    if (m_terminal && m_shown >= 0)
    {
        std::fputc('\n', stderr);
    }
}

} // namespace cfx::cli
