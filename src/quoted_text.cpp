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
        const auto byte = static_cast<unsigned char>(c);
        // A C1 control (U+0080 .. U+009F, in UTF-8 0xC2 then 0x80 .. 0x9F) is as much a line break or an
        // escape sequence to some terminals as a C0 one.
        const auto next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0u;
        if (byte == 0xc2 && next >= 0x80 && next <= 0x9f)
        {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", next);
            quoted += escape;
            ++i;
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
            if (byte < 0x20 || byte == 0x7f)
            {
                char escape[8];
                std::snprintf(escape, sizeof escape, "\\u%04x", byte);
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

} // namespace cfx::detail
