#include "ui/adapters/local_path.h"

#include <filesystem>

namespace fieldsight::ui {

namespace {

constexpr char16_t kEscapeBase = 0xDC00; ///< + byte (0x80..0xFF): a byte that is not UTF-8

/// The length of the valid UTF-8 sequence at `s[i]` and its code point, or 0 when invalid
/// (overlong forms, encoded surrogates and values beyond U+10FFFF are invalid).
int utf8Sequence(std::string_view s, std::size_t i, char32_t& code)
{
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char lead = byte(i);
    int length = 0;
    char32_t min = 0;
    if (lead < 0x80) {
        code = lead;
        return 1;
    } else if ((lead & 0xE0) == 0xC0) {
        length = 2, code = lead & 0x1F, min = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
        length = 3, code = lead & 0x0F, min = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
        length = 4, code = lead & 0x07, min = 0x10000;
    } else {
        return 0;
    }
    if (i + std::size_t(length) > s.size())
        return 0;
    for (int k = 1; k < length; ++k) {
        const unsigned char next = byte(i + std::size_t(k));
        if ((next & 0xC0) != 0x80)
            return 0;
        code = code << 6 | (next & 0x3F);
    }
    if (code < min || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
        return 0;
    return length;
}

void appendUtf8(std::string& out, char32_t code)
{
    if (code < 0x80) {
        out += char(code);
    } else if (code < 0x800) {
        out += char(0xC0 | code >> 6);
        out += char(0x80 | (code & 0x3F));
    } else if (code < 0x10000) {
        out += char(0xE0 | code >> 12);
        out += char(0x80 | (code >> 6 & 0x3F));
        out += char(0x80 | (code & 0x3F));
    } else {
        out += char(0xF0 | code >> 18);
        out += char(0x80 | (code >> 12 & 0x3F));
        out += char(0x80 | (code >> 6 & 0x3F));
        out += char(0x80 | (code & 0x3F));
    }
}

} // namespace

QString fromLocalPath(std::string_view bytes)
{
    QString out;
    out.reserve(qsizetype(bytes.size()));
    for (std::size_t i = 0; i < bytes.size();) {
        char32_t code = 0;
        if (const int length = utf8Sequence(bytes, i, code)) {
            const char32_t one[] = {code};
            out += QString::fromUcs4(one, 1);
            i += std::size_t(length);
        } else {
            out += QChar(char16_t(kEscapeBase + static_cast<unsigned char>(bytes[i])));
            ++i;
        }
    }
    return out;
}

std::string toLocalPath(const QString& path)
{
    std::string out;
    out.reserve(std::size_t(path.size()));
    for (qsizetype i = 0; i < path.size(); ++i) {
        const char16_t unit = path[i].unicode();
        if (QChar::isHighSurrogate(unit) && i + 1 < path.size() &&
            QChar::isLowSurrogate(path[i + 1].unicode())) {
            appendUtf8(out, QChar::surrogateToUcs4(unit, path[i + 1].unicode()));
            ++i;
        } else if (unit >= kEscapeBase + 0x80 && unit <= kEscapeBase + 0xFF) {
            out += char(unit - kEscapeBase); // an escaped byte
        } else {
            appendUtf8(out, QChar::isSurrogate(unit) ? char32_t(0xFFFD) : char32_t(unit));
        }
    }
    return out;
}

bool localPathExists(const QString& path)
{
    std::error_code ec;
    return !path.isEmpty() && std::filesystem::exists(toLocalPath(path), ec);
}

bool isLocalFolder(const QString& path)
{
    std::error_code ec;
    return !path.isEmpty() && std::filesystem::is_directory(toLocalPath(path), ec);
}

bool makeLocalFolder(const QString& path)
{
    std::error_code ec;
    std::filesystem::create_directories(toLocalPath(path), ec);
    return !ec && isLocalFolder(path);
}

QStringList argumentsOf(int argc, char** argv)
{
    QStringList out;
    for (int i = 0; i < argc; ++i)
        out << fromLocalPath(argv[i]);
    return out;
}

} // namespace fieldsight::ui
