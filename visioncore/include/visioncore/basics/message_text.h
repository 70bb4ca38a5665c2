// Text from a file put into a one-line message: control characters escaped, long text shortened,
// so a name with a NUL or a newline inside, or one of 10,000 characters, reads as one short line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace fieldsight {

/// `text` for a message: a control character (a NUL, a newline, DEL) as `\0`, `\n`, `\t`, `\r`
/// or `\xNN`, a backslash as `\\`, and past `max_chars` characters cut with "…" and how many
/// bytes there are in all. Bytes of 0x80 and above (UTF-8) are kept.
std::string messageText(std::string_view text, std::size_t max_chars = 60);

} // namespace fieldsight
