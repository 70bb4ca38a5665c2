// Reading a versioned JSON document ({"format": "fieldsight-...", ...}): one set of checks and
// messages for every such file, each naming the file and the problem.
#pragma once

#include "visioncore/basics/json_text.h"
#include "visioncore/basics/result.h"

#include <nlohmann/json.hpp>

#include <cstdlib>

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
    const std::string given = found->get<std::string>();
    if (given != format) {
        const auto slash = format.rfind('/');
        const bool newer =
            slash != std::string::npos && given.size() > slash + 1 &&
            given.compare(0, slash + 1, format, 0, slash + 1) == 0 &&
            std::atof(given.c_str() + slash + 1) > std::atof(format.c_str() + slash + 1);
        return Error{
            source + ": unsupported format \"" + given + "\" (expected \"" + format + "\")" +
            (newer ? ": a newer Fieldsight wrote it; this one reads only \"" + format + "\""
                   : std::string())};
    }
    return root;
}

} // namespace fieldsight
