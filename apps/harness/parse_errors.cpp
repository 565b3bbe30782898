#include "harness/parse_errors.h"

#include "harness/command_line.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cfx
{

namespace
{

/// What a value of CLI11's type name `typeName` is, in words ("INT": "a whole number"); a validator's
/// description after a ':' ("UINT:INT in [1 - 8]") is left out.
std::string TypeInWords(const std::string& typeName)
{
    const std::string type = typeName.substr(0, typeName.find(':'));
    if (type == "INT" || type == "UINT")
    {
        return "a whole number";
    }
    if (type == "FLOAT")
    {
        return "a number";
    }
    return type.empty() || type == "TEXT" ? std::string("a value") : type;
}

/// The option of `app` whose name `message` mentions first (followed by ':', ' ' or the end, so that
/// "--scene" is not found in "--scenes"), or nullptr.
const CLI::Option* OptionNamedIn(const CLI::App& app, const std::string& message, std::size_t& at)
{
    const CLI::Option* named = nullptr;
    at = std::string::npos;
    for (const CLI::Option* option : app.get_options())
    {
        const std::string name = option->get_name();
        for (std::size_t found = message.find(name); found != std::string::npos;
             found = message.find(name, found + 1))
        {
            const std::size_t end = found + name.size();
            const bool wholeName = end == message.size() || message[end] == ':' || message[end] == ' ';
            if (wholeName && found < at)
            {
                named = option;
                at = found;
            }
            if (wholeName)
            {
                break;
            }
        }
    }
    return named;
}

/// `text` as a decimal whole number: digits with an optional sign and spaces around ("+5", " 010 " is
/// 10); nothing for anything else (hex, a fraction, an exponent, out of long long's range).
std::optional<long long> ParseDecimal(std::string_view text)
{
    while (!text.empty() && text.front() == ' ')
    {
        text.remove_prefix(1);
    }
    while (!text.empty() && text.back() == ' ')
    {
        text.remove_suffix(1);
    }
    if (text.size() > 1 && text.front() == '+' && text[1] != '-')
    {
        text.remove_prefix(1);
    }
    long long value = 0;
    const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || stop != text.data() + text.size())
    {
        return std::nullopt;
    }
    return value;
}

} // namespace

Diagnostic DescribeParseError(const CLI::App& app, const CLI::ParseError& error)
{
    const std::vector<std::string> leftovers = app.remaining();
    if (!leftovers.empty())
    {
        const std::string& argument = leftovers.front();
        const bool flagLike = argument.size() > 1 && argument.front() == '-';
        return Diagnostic{kCommandLine, argument,
                          std::string(flagLike ? "unknown flag" : "unexpected argument") + " (see --help)"};
    }
    const std::string message = error.what();
    std::size_t at = 0;
    const CLI::Option* option = OptionNamedIn(app, message, at);
    if (option == nullptr)
    {
        return Diagnostic{kCommandLine, "", message};
    }
    if (dynamic_cast<const CLI::ConversionError*>(&error) != nullptr && !option->results().empty())
    {
        return Diagnostic{kCommandLine, option->get_name(),
                          "expected " + TypeInWords(option->get_type_name()) + ", found \"" +
                              CLI::detail::join(option->results()) + "\""};
    }
    if (dynamic_cast<const CLI::RequiredError*>(&error) != nullptr)
    {
        return Diagnostic{kCommandLine, option->get_name(), "required, but not given"};
    }
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) != nullptr)
    {
        if (option->results().empty())
        {
            return Diagnostic{kCommandLine, option->get_name(),
                              "needs " + TypeInWords(option->get_type_name()) + " (see --help)"};
        }
        if (option->count() > 1)
        {
            return Diagnostic{kCommandLine, option->get_name(), "given more than once"};
        }
    }
    // Anything else: CLI11's words after the name ("--frames: ...").
    std::string rest = message.substr(at + option->get_name().size());
    rest.erase(0, std::min(rest.find_first_not_of(": ="), rest.size()));
    return Diagnostic{kCommandLine, option->get_name(), rest.empty() ? message : rest};
}

const CLI::Validator& NamesAFile()
{
    // No description: the help shows the option's type as before.
    static const CLI::Validator check(
        [](const std::string& value) { return value.empty() ? std::string("names no file") : std::string(); },
        "");
    return check;
}

CLI::Validator WholeNumberIn(long long lowest, long long highest)
{
    const std::string range = std::to_string(lowest) + " to " + std::to_string(highest);
    return CLI::Validator(
        [lowest, highest, range](std::string& text)
        {
            const std::optional<long long> value = ParseDecimal(text);
            if (!value || *value < lowest || *value > highest)
            {
                return "expected a whole number from " + range + ", found \"" + text + "\"";
            }
            text = std::to_string(*value); // what CLI11 converts: "010" is 10 here, not octal 8
            return std::string();
        },
        "INT in [" + std::to_string(lowest) + " - " + std::to_string(highest) + "]");
}

const CLI::Validator& DecimalNumber()
{
    static const CLI::Validator check(
        [](const std::string& text)
        {
            const bool hex = text.find_first_of("xX") != std::string::npos;
            return hex ? "expected a number in decimal, found \"" + text + "\"" : std::string();
        },
        "");
    return check;
}

} // namespace cfx
