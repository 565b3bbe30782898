// Test support: reading the size of a PNG from its bytes (signature, then the IHDR chunk).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace cfx::test
{

/// Width and height of PNG file bytes, or nothing when they do not start like a PNG.
inline std::optional<std::pair<std::uint32_t, std::uint32_t>> PngSize(const std::string& bytes)
{
    if (bytes.size() < 24 || bytes.compare(0, 8, std::string("\x89PNG\r\n\x1a\n", 8)) != 0 ||
        bytes.compare(12, 4, "IHDR") != 0)
    {
        return std::nullopt;
    }
    auto be32 = [&](std::size_t at)
    {
        std::uint32_t value = 0;
        for (std::size_t i = 0; i < 4; ++i)
        {
            value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
        }
        return value;
    };
    return std::make_pair(be32(16), be32(20));
}

} // namespace cfx::test
