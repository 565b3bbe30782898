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
    for (const char c : text)
    {
        const auto byte = static_cast<unsigned char>(c);
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
