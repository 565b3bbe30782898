// contactfx internal: see nearest_name.h.
#include "nearest_name.h"

#include "quoted_text.h"

#include <algorithm>
#include <cctype>

namespace cfx::detail
{

std::size_t EditDistance(std::string_view a, std::string_view b)
{
    // Optimal string alignment: three rows of the table, for the prefixes of `a` of length i - 2, i - 1, i.
    const std::size_t columns = b.size() + 1;
    std::vector<std::size_t> older(columns), previous(columns), current(columns);
    for (std::size_t j = 0; j < columns; ++j)
    {
        previous[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        current[0] = i;
        for (std::size_t j = 1; j < columns; ++j)
        {
            const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
            {
                current[j] = std::min(current[j], older[j - 2] + 1);
            }
        }
        std::swap(older, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

namespace
{

// The most edits a typo of `key` may have: max(2, size / 3), fewer than half its characters.
std::size_t NearestLimit(std::string_view key)
{
    return std::min(std::max<std::size_t>(2, key.size() / 3), key.empty() ? 0 : (key.size() - 1) / 2);
}

// Whether `candidate` may be within `limit` edits of `key` by their lengths alone (more apart takes as many
// insertions): the test that keeps a hostile 1 MB key cheap, and what a suggestion's cost counts.
bool CloseInLength(std::string_view key, std::string_view candidate, std::size_t limit)
{
    return std::max(key.size(), candidate.size()) - std::min(key.size(), candidate.size()) <= limit;
}

std::string Lower(std::string_view text)
{
    std::string out(text);
    for (char& c : out)
    {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

} // namespace

std::size_t TypoDistance(std::string_view key, std::string_view candidate)
{
    // A case slip ("Gravity") is one edit, whatever its length.
    const std::size_t folded = EditDistance(Lower(key), Lower(candidate));
    return folded == 0 ? (candidate == key ? 0 : 1) : folded;
}

std::optional<std::string_view> NearestKey(std::string_view key, std::span<const std::string_view> known)
{
    const std::size_t limit = NearestLimit(key);
    std::optional<std::string_view> nearest;
    std::size_t best = limit + 1;
    for (std::string_view candidate : known)
    {
        if (!CloseInLength(key, candidate, limit))
        {
            continue;
        }
        const std::size_t distance = TypoDistance(key, candidate);
        if (distance < best)
        {
            best = distance;
            nearest = candidate;
        }
    }
    if (best == 0)
    {
        return std::nullopt;
    }
    return nearest;
}

std::optional<std::string_view> NearestKey(std::string_view key, const std::vector<std::string>& known)
{
    const std::vector<std::string_view> views(known.begin(), known.end());
    return NearestKey(key, std::span<const std::string_view>(views));
}

std::string DidYouMean(std::string_view name, const std::vector<std::string>& known, SuggestionBudget& budget)
{
    // What NearestKey's tables cost: every candidate its length test lets through.
    const std::size_t limit = NearestLimit(name);
    std::size_t cells = 0;
    for (const std::string& candidate : known)
    {
        if (CloseInLength(name, candidate, limit))
        {
            cells += (name.size() + 1) * (candidate.size() + 1);
            if (cells > budget.cells)
            {
                return std::string();
            }
        }
    }
    budget.cells -= cells;
    const std::optional<std::string_view> nearest = NearestKey(name, known);
    return nearest ? ", did you mean " + QuotedText(*nearest) + "?" : std::string();
}

} // namespace cfx::detail
