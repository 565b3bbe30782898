// contactfx internal: a name from a file, quoted for a message.
#pragma once

#include <string>
#include <string_view>

namespace cfx::detail
{

/// `text` between double quotes, with quotes, backslashes and control characters escaped as JSON escapes
/// them ("a\nb" for a line break), and C1 controls (U+0080 .. U+009F) as "\u0085": a name read from a file
/// can neither end its message early nor forge another line of it. Other bytes (UTF-8) are kept.
std::string QuotedText(std::string_view text);
/// The same without the surrounding quotes (a pair's name, "a+b").
std::string EscapedText(std::string_view text);

} // namespace cfx::detail
