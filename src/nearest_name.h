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

/// Edits from `key` to `candidate` as NearestKey counts them: EditDistance of the two in lower case, and a
/// difference of case alone as one edit ("Gravity" is 1 from "gravity").
std::size_t TypoDistance(std::string_view key, std::string_view candidate);

/// The key of `known` nearest to `key` when near enough to be a typo of it (at most max(2, size / 3) edits,
/// fewer than half its characters; case differences count as one edit); nothing otherwise (also when `key`
/// itself is known).
std::optional<std::string_view> NearestKey(std::string_view key, std::span<const std::string_view> known);

/// The same over a list of names (materials, particle types).
std::optional<std::string_view> NearestKey(std::string_view key, const std::vector<std::string>& known);

/// Work a file's checks may spend on suggestions, in cells of EditDistance's table (one per pair of
/// characters compared): a config of 20,000 materials with 2,000 rules naming unknown ones took minutes
/// to validate, and a 100 kB name against one as long took 34 s. About 0.1 s of work in all; the hints
/// after it are left out.
struct SuggestionBudget
{
    std::size_t cells = 50'000'000;
};

/// `, did you mean "steel"?` (the name quoted as QuotedText quotes it) when a name of `known` is near enough
/// to `name` to be a typo of it (NearestKey); empty otherwise, and when `budget` has not the cells the
/// comparison would take (which it then keeps for later, shorter ones).
std::string DidYouMean(std::string_view name, const std::vector<std::string>& known,
                       SuggestionBudget& budget);

} // namespace cfx::detail
