#include "visioncore/basics/json_text.h"

namespace fieldsight {

namespace {

template <class Json> std::string textOf(const Json& json, int indent)
{
    return json.dump(indent, ' ', false, Json::error_handler_t::replace);
}

} // namespace

std::string jsonText(const nlohmann::json& json, int indent)
{
    return textOf(json, indent);
}

std::string jsonText(const nlohmann::ordered_json& json, int indent)
{
    return textOf(json, indent);
}

template <class Json> Result<Json> parseJson(const std::string& text, const std::string& source)
{
    try {
        return Json::parse(text);
    } catch (const nlohmann::json::exception& e) { // a syntax error, or a number overflow
        return Error{jsonSyntaxError(source, e.what())};
    }
}

template Result<nlohmann::json> parseJson(const std::string&, const std::string&);
template Result<nlohmann::ordered_json> parseJson(const std::string&, const std::string&);

nlohmann::json jsonOrDiscarded(const std::string& text)
{
    return nlohmann::json::parse(text, nullptr, false);
}

std::string jsonSyntaxError(const std::string& source, const std::string& parser_message)
{
    // nlohmann: "[json.exception.parse_error.101] parse error at line 1, column 9: syntax error
    // while parsing value - unexpected end of input; expected '[', '{', or a literal".
    std::string where;
    std::string problem = parser_message;
    if (const auto at = parser_message.find("at line "); at != std::string::npos) {
        const auto colon = parser_message.find(": ", at);
        where = " " + parser_message.substr(at, colon - at);
        problem = colon == std::string::npos ? "" : parser_message.substr(colon + 2);
    } else if (const auto bracket = parser_message.find("] "); bracket != std::string::npos) {
        problem = parser_message.substr(bracket + 2);
    }
    return source + ": not valid JSON" + where + (problem.empty() ? "" : " (" + problem + ")");
}

} // namespace fieldsight
