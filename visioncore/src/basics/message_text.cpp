// Text from a file made safe and short for a one-line message.
#include "visioncore/basics/message_text.h"

namespace fieldsight {

std::string messageText(std::string_view text, std::size_t max_chars)
{
    std::string out;
    std::size_t shown = 0;
    std::size_t i = 0;
    for (; i < text.size() && shown < max_chars; ++i, ++shown) {
        const auto c = static_cast<unsigned char>(text[i]);
        switch (c) {
        case 0:
            out += "\\0";
            continue;
        case '\n':
            out += "\\n";
            continue;
        case '\r':
            out += "\\r";
            continue;
        case '\t':
            out += "\\t";
            continue;
        case '\\':
            out += "\\\\";
            continue;
        default:
            break;
        }
        if (c < 0x20 || c == 0x7f) {
            constexpr char kHex[] = "0123456789abcdef";
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
            continue;
        }
        out += char(c);
        // A UTF-8 character's continuation bytes go with it, and count once.
        while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xc0) == 0x80)
            out += text[++i];
    }
    if (i < text.size())
        out += "… (" + std::to_string(text.size()) + " bytes)";
    return out;
}

} // namespace fieldsight
