#include "contactfx/error.h"

#include <sstream>

namespace cfx
{

std::string Diagnostic::ToString() const
{
    std::ostringstream text;
    text << (file.empty() ? "<input>" : file);
    if (line > 0)
    {
        text << ':' << line << ':' << column;
    }
    if (!path.empty())
    {
        text << ": " << path;
    }
    text << ": " << (warning ? "warning: " : "") << message;
    return text.str();
}

std::size_t CountProblems(const std::vector<Diagnostic>& diagnostics)
{
    std::size_t count = 0;
    for (const Diagnostic& diagnostic : diagnostics)
    {
        count += diagnostic.unlisted > 0 ? diagnostic.unlisted : 1;
    }
    return count;
}

static std::string AllMessages(const std::vector<Diagnostic>& diagnostics)
{
    if (diagnostics.empty())
    {
        return "invalid input";
    }
    std::string text = diagnostics.front().ToString();
    for (std::size_t i = 1; i < diagnostics.size(); ++i)
    {
        text += '\n';
        text += diagnostics[i].ToString();
    }
    return text;
}

InputError::InputError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(AllMessages(diagnostics)), m_diagnostics(std::move(diagnostics))
{
}

InputError::InputError(std::string file, std::string path, std::string message)
    : InputError(std::vector<Diagnostic>{Diagnostic{std::move(file), std::move(path), std::move(message)}})
{
}

} // namespace cfx
