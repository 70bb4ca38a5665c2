// JSON as text for every file Fieldsight writes: names that are not valid UTF-8 (a frame file
// named in another encoding) are written with U+FFFD in place of the bad bytes, never an
// exception halfway through a save. And JSON from text for every file it reads, with one message
// for text that is not JSON.
#pragma once

#include "visioncore/basics/result.h"

#include <nlohmann/json.hpp>

#include <string>

namespace fieldsight {

/// `json` as text, `indent` spaces a level (-1: one line).
template <class Json> std::string jsonText(const Json& json, int indent = -1)
{
    return json.dump(indent, ' ', false, Json::error_handler_t::replace);
}

/// "<source>: not valid JSON at line L, column C (the parser's problem)" for the message of a
/// nlohmann parse error.
std::string jsonSyntaxError(const std::string& source, const std::string& parser_message);

/// `text` (read from `source`) as JSON; text that is not JSON is an Error saying where and why.
template <class Json = nlohmann::json>
Result<Json> parseJson(const std::string& text, const std::string& source)
{
    try {
        return Json::parse(text);
    } catch (const nlohmann::json::exception& e) { // a syntax error, or a number overflow
        return Error{jsonSyntaxError(source, e.what())};
    }
}

} // namespace fieldsight
