#include "suggest.h"

#include "scene/known_keys.h"

#include <vector>

namespace cfx::cli
{

std::optional<std::string> NearestName(std::string_view word, std::span<const std::string> candidates)
{
    // The scene readers' typo rule, so that a flag and a JSON key are suggested alike.
    std::vector<std::string_view> names(candidates.begin(), candidates.end());
    const std::optional<std::string_view> nearest = scene_detail::NearestKey(word, names);
    return nearest ? std::optional<std::string>(*nearest) : std::nullopt;
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
