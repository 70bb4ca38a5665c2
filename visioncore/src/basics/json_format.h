// Reading a versioned JSON document ({"format": "fieldsight-...", ...}): one set of checks and
// messages for every such file, each naming the file and the problem.
#pragma once

#include "visioncore/basics/json_text.h"
#include "visioncore/basics/result.h"

#include <nlohmann/json.hpp>

#include <string>

namespace fieldsight {

/// Parses `text` (from `source`, for messages) as a JSON object whose "format" is `format`.
inline Result<nlohmann::json> parseFormattedJson(const std::string& text, const std::string& source,
                                                 const std::string& format)
{
    auto parsed = parseJson(text, source);
    if (!parsed)
        return parsed.error();
    nlohmann::json root = std::move(parsed).value();
    if (!root.is_object())
        return Error{source + ": expected a JSON object at the top level"};
    const auto found = root.find("format");
    if (found == root.end() || !found->is_string())
        return Error{source + ": missing \"format\": \"" + format + "\""};
    if (found->get<std::string>() != format)
        return Error{source + ": unsupported format \"" + found->get<std::string>() +
                     "\" (expected \"" + format + "\")"};
    return root;
}

} // namespace fieldsight
