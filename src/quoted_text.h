// contactfx internal: a name from a file, quoted for a message.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace cfx::detail
{

/// `text` between double quotes, with quotes, backslashes and control characters escaped as JSON escapes
/// them ("a\nb" for a line break), and C1 controls (U+0080 .. U+009F) as "\u0085", U+2028 and U+2029 as
/// "\u2028" and "\u2029": a name read from a file
/// can neither end its message early nor forge another line of it. Other bytes (UTF-8) are kept.
std::string QuotedText(std::string_view text);
/// The same without the surrounding quotes (a pair's name, "a+b").
std::string EscapedText(std::string_view text);

/// What a list holds, for a message naming what there is instead of an unknown name: "a, b, c" (each
/// escaped), the first 20 and then "and N more" (a config of 20,000 materials made a message of 900 kB);
/// `none` when the list is empty.
std::string NameList(const std::vector<std::string>& names, std::string_view none);

/// How many bytes the control character starting at text[i] takes: 1 for a C0 control (below 0x20) or
/// DEL, 2 for a C1 control (U+0080 .. U+009F: UTF-8 0xC2 then 0x80 .. 0x9F; U+0085 is NEXT LINE, U+009B
/// starts a terminal's escape sequence), 3 for U+2028 LINE SEPARATOR and U+2029 PARAGRAPH SEPARATOR, 0 when
/// none starts there.
std::size_t ControlCharacterBytes(std::string_view text, std::size_t i);
/// Whether `text` holds a control character (as ControlCharacterBytes counts them).
bool HasControlCharacter(std::string_view text);

} // namespace cfx::detail
