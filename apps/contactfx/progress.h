// contactfx command line: a progress bar on stderr for long jobs.
//
// On a terminal the bar redraws in place ("\r"); into a file or a pipe (CI logs) it prints a line at
// every tenth instead, so logs stay short. Standard output is left alone for results.
#pragma once

#include <cstdint>
#include <string>

namespace cfx::cli
{

class Progress
{
public:
    /// `total` units of work (> 0) called `unit` ("frames"), labelled `label`.
    Progress(std::string label, std::uint64_t total, std::string unit);
    /// `done` units finished so far, at most total; redraws only when the shown value changes.
    void Update(std::uint64_t done);
    /// Ends the line on a terminal.
    void Finish();

private:
    std::string m_label;
    std::string m_unit;
    std::uint64_t m_total;
    bool m_terminal;
    int m_shown = -1; // percent on a terminal, tenths otherwise
};

} // namespace cfx::cli
