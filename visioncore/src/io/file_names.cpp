// Frame file names: lower case and natural order.
#include "io/file_names.h"

#include <algorithm>
#include <cctype>
#include <cstddef>

namespace fieldsight::io {

namespace {

bool isDigit(char c)
{
    return c >= '0' && c <= '9';
}

} // namespace

std::string lowercase(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

bool naturalLess(const std::string& a, const std::string& b)
{
    std::size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        if (isDigit(a[i]) && isDigit(b[j])) {
            std::size_t ie = i, je = j;
            while (ie < a.size() && isDigit(a[ie]))
                ++ie;
            while (je < b.size() && isDigit(b[je]))
                ++je;
            std::size_t iz = i, jz = j; // skip leading zeros
            while (iz + 1 < ie && a[iz] == '0')
                ++iz;
            while (jz + 1 < je && b[jz] == '0')
                ++jz;
            const std::size_t ilen = ie - iz, jlen = je - jz;
            if (ilen != jlen)
                return ilen < jlen;
            if (const int c = a.compare(iz, ilen, b, jz, jlen); c != 0)
                return c < 0;
            i = ie;
            j = je;
        } else {
            if (a[i] != b[j])
                return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
            ++i;
            ++j;
        }
    }
    if ((a.size() - i) != (b.size() - j))
        return (a.size() - i) < (b.size() - j);
    return a < b; // "f01" and "f1" are equal so far; keep the order total
}

} // namespace fieldsight::io
