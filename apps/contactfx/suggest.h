// contactfx's "did you mean ...?": the valid name nearest to a mistyped one.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace cfx::cli
{

/// Edits that turn `a` into `b`: inserting, deleting or replacing a character, or swapping two
/// neighbouring ones, each counts 1 (optimal string alignment distance). Case-sensitive.
std::size_t EditDistance(std::string_view a, std::string_view b);

/// The candidate nearest to `word` by EditDistance when it is near enough to be a typo of it: at most
/// max(2, word.size() / 3) edits, and fewer than half of word.size(). Of equally near ones the first;
/// nullopt when none is that near or `word` is one of the candidates.
std::optional<std::string> NearestName(std::string_view word, std::span<const std::string> candidates);

/// "did you mean 'X'?" for NearestName's X; empty when there is none.
std::string DidYouMean(std::string_view word, std::span<const std::string> candidates);

/// The candidates joined by ", ".
std::string JoinNames(std::span<const std::string> names);

} // namespace cfx::cli
