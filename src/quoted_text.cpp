#include "quoted_text.h"

#include <cstdio>

namespace cfx::detail
{

std::string QuotedText(std::string_view text)
{
    return "\"" + EscapedText(text) + "\"";
}

std::string EscapedText(std::string_view text)
{
    std::string quoted;
    for (std::size_t i = 0; i < text.size(); ++i)
    {
        const char c = text[i];
        const std::size_t control = ControlCharacterBytes(text, i);
        if (control == 2) // a C1 control is as much a line break or an escape to some terminals as a C0 one
        {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned char>(text[i + 1]));
            quoted += escape;
            ++i;
            continue;
        }
        if (control == 3) // U+2028 LINE SEPARATOR, U+2029 PARAGRAPH SEPARATOR: line breaks to some editors
        {
            quoted += text[i + 2] == '\xa8' ? "\\u2028" : "\\u2029";
            i += 2;
            continue;
        }
        switch (c)
        {
        case '"':
            quoted += "\\\"";
            break;
        case '\\':
            quoted += "\\\\";
            break;
        case '\n':
            quoted += "\\n";
            break;
        case '\r':
            quoted += "\\r";
            break;
        case '\t':
            quoted += "\\t";
            break;
        default:
            if (control == 1)
            {
                char escape[8];
                std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned char>(c));
                quoted += escape;
            }
            else
            {
                quoted += c;
            }
        }
    }
    return quoted;
}

std::size_t ControlCharacterBytes(std::string_view text, std::size_t i)
{
    const auto byte = static_cast<unsigned char>(text[i]);
    if (byte < 0x20 || byte == 0x7f)
    {
        return 1;
    }
    const auto next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0u;
    const auto third = i + 2 < text.size() ? static_cast<unsigned char>(text[i + 2]) : 0u;
    if (byte == 0xe2 && next == 0x80 && (third == 0xa8 || third == 0xa9))
    {
        return 3;
    }
    return byte == 0xc2 && next >= 0x80 && next <= 0x9f ? 2 : 0;
}

bool HasControlCharacter(std::string_view text)
{
    for (std::size_t i = 0; i < text.size(); ++i)
    {
        if (ControlCharacterBytes(text, i) > 0)
        {
            return true;
        }
    }
    return false;
}

std::string NameList(const std::vector<std::string>& names, std::string_view none)
{
    constexpr std::size_t kListed = 20;
    std::string list;
    for (std::size_t i = 0; i < names.size() && i < kListed; ++i)
    {
        list += (list.empty() ? "" : ", ") + EscapedText(names[i]);
    }
    if (names.size() > kListed)
    {
        list += " and " + std::to_string(names.size() - kListed) + " more";
    }
    return list.empty() ? std::string(none) : list;
}

} // namespace cfx::detail
