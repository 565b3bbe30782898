#include "usage.h"

#include "cli_common.h"
#include "suggest.h"

#include <cctype>
#include <iostream>

namespace cfx::cli
{

namespace
{

// Every name an option of `command` is spelled by: "--seconds", "-h", ...
std::vector<std::string> OptionNames(const CLI::App& command)
{
    std::vector<std::string> names;
    for (const CLI::Option* option :
         command.get_options([](const CLI::Option* o) { return o->nonpositional(); }))
    {
        for (const std::string& name : option->get_lnames())
        {
            names.push_back("--" + name);
        }
        for (const std::string& name : option->get_snames())
        {
            names.push_back("-" + name);
        }
    }
    return names;
}

bool LooksLikeAnOption(const std::string& argument)
{
    // "-2.5" is a (negative) value, not an option.
    return argument.size() > 1 && argument[0] == '-' &&
           !(std::isdigit(static_cast<unsigned char>(argument[1])) || argument[1] == '.');
}

// " for 'contactfx run'" below the top-level command, where what an argument belongs to is not obvious.
std::string ForCommand(const CLI::App& command)
{
    return command.get_parent() == nullptr ? std::string() : " for '" + CommandPath(command) + "'";
}

// One error line, then the pointer at `command`'s help.
int Fail(const CLI::App& command, const std::string& message)
{
    std::cerr << "contactfx: error: " << message << "\nSee '" << CommandPath(command) << " --help'.\n";
    return kExitError;
}

int ReportUnknownArgument(const CLI::App& command, const std::string& argument)
{
    if (LooksLikeAnOption(argument))
    {
        const std::string name = argument.substr(0, argument.find('=')); // --secnds=2 names --secnds
        const std::string suggestion = DidYouMean(name, OptionNames(command));
        return Fail(command, "unknown option '" + name + "'" + ForCommand(command) +
                                 (suggestion.empty() ? "" : "; " + suggestion));
    }
    if (!CommandNames(command).empty())
    {
        return ReportUnknownCommand(command, argument);
    }
    return Fail(command, "unexpected argument '" + argument + "'" + ForCommand(command));
}

// What `contactfx` or `contactfx bench` alone prints: how to call it and its commands.
int PrintShortUsage(const CLI::App& group)
{
    const std::string path = CommandPath(group);
    std::cerr << "contactfx: error: missing command" << ForCommand(group) << "\n"
              << "Usage: " << path << " [OPTIONS] COMMAND\n"
              << "Commands: " << JoinNames(CommandNames(group)) << "\n"
              << "See '" << path << " --help'"
              << (FindCommand(group, "help") != nullptr ? ", or '" + path + " help COMMAND' for one command"
                                                        : "")
              << ".\n";
    return kExitError;
}

} // namespace

std::string CommandPath(const CLI::App& command)
{
    std::string path = command.get_name();
    for (const CLI::App* parent = command.get_parent(); parent != nullptr; parent = parent->get_parent())
    {
        path = parent->get_name() + " " + path;
    }
    return path;
}

std::vector<std::string> CommandNames(const CLI::App& group)
{
    std::vector<std::string> names;
    for (const CLI::App* command : group.get_subcommands(
             [](const CLI::App* sub) { return !sub->get_name().empty() && !sub->get_disabled(); }))
    {
        names.push_back(command->get_name());
    }
    return names;
}

const CLI::App* FindCommand(const CLI::App& group, std::string_view name)
{
    for (const CLI::App* command : group.get_subcommands({}))
    {
        if (!command->get_name().empty() && command->get_name() == name)
        {
            return command;
        }
    }
    return nullptr;
}

std::string HelpText(const CLI::App& command)
{
    // Not command.help(): that delegates to whichever subcommand was parsed (`help` itself, for one).
    return command.get_formatter()->make_help(&command, CommandPath(command), CLI::AppFormatMode::Normal);
}

int ReportUnknownCommand(const CLI::App& group, const std::string& name)
{
    const std::vector<std::string> names = CommandNames(group);
    const std::string suggestion = DidYouMean(name, names);
    if (names.empty()) // `help run extra`: run has no commands
    {
        return Fail(group, "unknown command '" + name + "'" + ForCommand(group) + "; it has no commands");
    }
    return Fail(group, "unknown command '" + name + "'" + ForCommand(group) + "; " +
                           (suggestion.empty() ? "the commands are " + JoinNames(names) : suggestion));
}

int ReportParseError(const CLI::App& app, const CLI::ParseError& error)
{
    // The commands given, outermost first. CLI11 keeps what a command could not take as its
    // "remaining" arguments; the first of those is what the user mistyped.
    std::vector<const CLI::App*> given{&app};
    while (!given.back()->get_subcommands().empty())
    {
        given.push_back(given.back()->get_subcommands().front());
    }
    for (const CLI::App* command : given)
    {
        const std::vector<std::string> leftovers = command->remaining();
        if (!leftovers.empty())
        {
            return ReportUnknownArgument(*command, leftovers.front());
        }
    }
    const CLI::App& innermost = *given.back();
    if (!CommandNames(innermost).empty())
    {
        return PrintShortUsage(innermost);
    }
    return Fail(innermost, DescribeParseError(innermost, error).ToString());
}

} // namespace cfx::cli
