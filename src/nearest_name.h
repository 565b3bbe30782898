// contactfx internal: the known name nearest to a misspelt one, for messages ("did you mean ...?").
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace cfx::detail
{

/// Edits turning `a` into `b` (insert, delete, replace, swap two neighbours: 1 each).
std::size_t EditDistance(std::string_view a, std::string_view b);

/// The key of `known` nearest to `key` when near enough to be a typo of it (at most max(2, size / 3) edits,
/// fewer than half its characters; case differences count as one edit); nothing otherwise (also when `key`
/// itself is known).
std::optional<std::string_view> NearestKey(std::string_view key, std::span<const std::string_view> known);

/// The same over a list of names (materials, particle types).
std::optional<std::string_view> NearestKey(std::string_view key, const std::vector<std::string>& known);

/// `, did you mean "steel"?` (the name quoted as QuotedText quotes it) when a name of `known` is near enough
/// to `name` to be a typo of it (NearestKey); empty otherwise.
std::string DidYouMean(std::string_view name, const std::vector<std::string>& known);

} // namespace cfx::detail
