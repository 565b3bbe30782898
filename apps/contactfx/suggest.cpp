#include "suggest.h"

#include <algorithm>
#include <vector>

namespace cfx::cli
{

std::size_t EditDistance(std::string_view a, std::string_view b)
{
    // Three rows of the dynamic programme: distances between the prefixes of `a` of length i - 2,
    // i - 1 and i and every prefix of `b`.
    const std::size_t columns = b.size() + 1;
    std::vector<std::size_t> beforePrevious(columns), previous(columns), current(columns);
    for (std::size_t j = 0; j < columns; ++j)
    {
        previous[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        current[0] = i;
        for (std::size_t j = 1; j < columns; ++j)
        {
            const std::size_t replace = a[i - 1] == b[j - 1] ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + replace});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
            {
                current[j] = std::min(current[j], beforePrevious[j - 2] + 1);
            }
        }
        std::swap(beforePrevious, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::optional<std::string> NearestName(std::string_view word, std::span<const std::string> candidates)
{
    // Near enough: a few edits, and fewer than half of the word ("-x" is not a typo of "-h").
    const std::size_t nearEnough =
        std::min(std::max<std::size_t>(2, word.size() / 3), word.size() == 0 ? 0 : (word.size() - 1) / 2);
    std::optional<std::string> nearest;
    std::size_t nearestDistance = nearEnough + 1;
    for (const std::string& candidate : candidates)
    {
        const std::size_t distance = EditDistance(word, candidate);
        if (distance == 0)
        {
            return std::nullopt;
        }
        if (distance < nearestDistance)
        {
            nearest = candidate;
            nearestDistance = distance;
        }
    }
    return nearest;
}

std::string DidYouMean(std::string_view word, std::span<const std::string> candidates)
{
    const std::optional<std::string> nearest = NearestName(word, candidates);
    return nearest ? "did you mean '" + *nearest + "'?" : std::string();
}

std::string JoinNames(std::span<const std::string> names)
{
    std::string joined;
    for (const std::string& name : names)
    {
        joined += (joined.empty() ? "" : ", ") + name;
    }
    return joined;
}

} // namespace cfx::cli
