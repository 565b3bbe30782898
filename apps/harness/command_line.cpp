#include "harness/command_line.h"

#include "contactfx/error.h"
#include "contactfx/files/text_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <system_error>

namespace cfx
{

std::string ExtensionProblem(const std::string& file, const std::string& extension)
{
    if (file.empty())
    {
        return "";
    }
    std::string found = std::filesystem::path(file).extension().string();
    std::transform(found.begin(), found.end(), found.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return found == extension ? "" : "expected a " + extension + " file, found \"" + file + "\"";
}

void CheckExtension(const std::string& flag, const std::string& file, const std::string& extension)
{
    if (const std::string problem = ExtensionProblem(file, extension); !problem.empty())
    {
        throw InputError(kCommandLine, flag, problem);
    }
}

void CheckOutputFile(const std::string& flag, const std::string& file)
{
    if (const std::string problem = OutputFileProblem(file); !problem.empty())
    {
        throw InputError(kCommandLine, flag, file + ": " + problem);
    }
}

namespace
{

template <typename Number> std::string ShortestText(Number value)
{
    std::array<char, 64> text{};
    const auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() ? std::string(text.data(), end) : std::to_string(value);
}

} // namespace

std::string NumberText(double value)
{
    return ShortestText(value);
}

std::string NumberText(float value)
{
    return ShortestText(value);
}

bool SameFile(const std::filesystem::path& a, const std::filesystem::path& b)
{
    if (a.empty() || b.empty())
    {
        return false;
    }
    std::error_code error; // a missing file is no other file
    return std::filesystem::absolute(a, error).lexically_normal() ==
               std::filesystem::absolute(b, error).lexically_normal() ||
           std::filesystem::equivalent(a, b, error);
}

} // namespace cfx
