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

static std::string FirstMessage(const std::vector<Diagnostic>& diagnostics)
{
    return diagnostics.empty() ? std::string("invalid input") : diagnostics.front().ToString();
}

InputError::InputError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(FirstMessage(diagnostics)), m_diagnostics(std::move(diagnostics))
{
}

InputError::InputError(std::string file, std::string path, std::string message)
    : InputError(std::vector<Diagnostic>{Diagnostic{std::move(file), std::move(path), std::move(message)}})
{
}

} // namespace cfx
