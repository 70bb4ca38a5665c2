#include "visioncore/basics/json_text.h"

namespace fieldsight {

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
