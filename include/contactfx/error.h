// contactfx: errors for bad input.
//
// Every loader and every constructor that takes user data reports problems the same way: a list of
// diagnostics, each naming the file (or "<api>" for values passed in code), the path of the offending
// field (a JSON path such as `body[3].fixture[0].friction`, or a struct field such as
// `rules[1].threshold`), and what was expected and found. Loaders collect every problem they can find
// before giving up, so that a user fixes a file in one pass.
//
// A warning (Diagnostic::warning) is a problem that does not stop the input from loading but may not be
// what the author meant: an unknown key in a scene, a polygon vertex Box2D drops. Loaders return warnings
// apart from errors; `contactfx validate --strict` counts them as errors.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace cfx
{

/// One problem in one input.
struct Diagnostic
{
    std::string file;     ///< file name as the user gave it, or "<api>" for values passed in code
    std::string path;     ///< JSON path or field name; empty when the problem is the whole file
    std::string message;  ///< what was expected and what was found
    int line = 0;         ///< 1-based line for malformed JSON, 0 when unknown
    int column = 0;       ///< 1-based column for malformed JSON, 0 when unknown
    bool warning = false; ///< true: the input still loads (see the file comment)
    /// > 0: this entry is not a problem itself but the note that ends a list a loader cut short (a hostile
    /// file): this many more problems (or warnings) were found and not listed.
    std::size_t unlisted = 0;

    /// "file:line:column: message" or "file: path: message", on one line; "warning: " before the message
    /// of a warning.
    std::string ToString() const;
};

/// How many problems `diagnostics` stands for: its entries, a note counting as the problems it did not list.
std::size_t CountProblems(const std::vector<Diagnostic>& diagnostics);

/// Thrown on bad input. Holds at least one diagnostic; what() is every diagnostic's ToString(), one per line
/// (a program that logs only what() sees every problem).
class InputError : public std::runtime_error
{
public:
    explicit InputError(std::vector<Diagnostic> diagnostics);
    InputError(std::string file, std::string path, std::string message);

    const std::vector<Diagnostic>& Diagnostics() const { return m_diagnostics; }

private:
    std::vector<Diagnostic> m_diagnostics;
};

} // namespace cfx
