// contactfx's "did you mean ...?": the valid name nearest to a mistyped one.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace cfx::cli
{

/// The candidate nearest to `word` when it is near enough to be a typo of it, by the scene readers' rule
/// (scene_detail::NearestKey: at most max(2, size / 3) edits of inserting, deleting, replacing or swapping
/// neighbouring characters, fewer than half of the word's characters, a case slip counting one). Of
/// equally near ones the first; nullopt when none is that near or `word` is one of the candidates.
std::optional<std::string> NearestName(std::string_view word, std::span<const std::string> candidates);

/// "did you mean 'X'?" for NearestName's X; empty when there is none.
std::string DidYouMean(std::string_view word, std::span<const std::string> candidates);

/// The candidates joined by ", ".
std::string JoinNames(std::span<const std::string> names);

} // namespace cfx::cli
