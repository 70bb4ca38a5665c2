// The core's text (UTF-8 std::string and std::string_view) as the GUI shows it.
#pragma once

#include <QString>

#include <string_view>

namespace fieldsight::ui {

/// `s`, UTF-8, as a QString.
inline QString toQString(std::string_view s)
{
    return QString::fromUtf8(s.data(), qsizetype(s.size()));
}

} // namespace fieldsight::ui
