// JSON as text for every file Fieldsight writes: names that are not valid UTF-8 (a frame file
// named in another encoding) are written with U+FFFD in place of the bad bytes, never an
// exception halfway through a save.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace fieldsight {

/// `json` as text, `indent` spaces a level (-1: one line).
template <class Json> std::string jsonText(const Json& json, int indent = -1)
{
    return json.dump(indent, ' ', false, Json::error_handler_t::replace);
}

} // namespace fieldsight
