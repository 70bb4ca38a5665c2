// JSON as text for every file Fieldsight writes: names that are not valid UTF-8 (a frame file
// named in another encoding) are written with U+FFFD in place of the bad bytes, never an
// exception halfway through a save. And JSON from text for every file it reads, with one message
// for text that is not JSON.
#pragma once

#include "visioncore/basics/result.h"

#include <nlohmann/json.hpp>

#include <string>

namespace fieldsight {

/// `json` as text, `indent` spaces a level (-1: one line). Out of line, as parseJson is: the JSON
/// library's serialiser and parser are compiled once, not in every file that reads or writes JSON.
std::string jsonText(const nlohmann::json& json, int indent = -1);
std::string jsonText(const nlohmann::ordered_json& json, int indent = -1);

/// "<source>: not valid JSON at line L, column C (the parser's problem)" for the message of a
/// nlohmann parse error.
std::string jsonSyntaxError(const std::string& source, const std::string& parser_message);

/// `text` (read from `source`) as JSON; text that is not JSON is an Error saying where and why.
/// Defined, and made, for nlohmann::json and nlohmann::ordered_json in json_text.cpp.
template <class Json = nlohmann::json>
Result<Json> parseJson(const std::string& text, const std::string& source);

/// `text` as JSON, or a discarded value (not an object, is_discarded()) where it is not JSON: for
/// a reader that only asks whether a file is of its kind.
nlohmann::json jsonOrDiscarded(const std::string& text);

} // namespace fieldsight
