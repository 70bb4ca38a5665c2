// Reading a versioned JSON document ({"format": "fieldsight-...", ...}): one set of checks and
// messages for every such file, each naming the file and the problem.
#pragma once

#include "visioncore/basics/json_text.h"
#include "visioncore/basics/message_text.h"
#include "visioncore/basics/result.h"

#include <nlohmann/json.hpp>

#include <cstdlib>

#include <optional>
#include <set>
#include <string>

namespace fieldsight {

/// Why the parsed document `root` (from `source`) is not an object whose "format" is `format`:
/// not an object, no "format", a "format" that is not a string (`"format": 1`: its type is named,
/// not called missing), or another format (a newer one said to be newer).
template <class Json>
std::optional<Error> formatProblem(const Json& root, const std::string& source,
                                   const std::string& format)
{
    if (!root.is_object())
        return Error{source + ": expected a JSON object at the top level"};
    const auto found = root.find("format");
    if (found == root.end())
        return Error{source + ": missing \"format\": \"" + format + "\""};
    if (!found->is_string())
        return Error{
            source + ": \"format\" must be the string \"" + format + "\", not " +
            (found->is_null() ? std::string("null") : "a " + std::string(found->type_name())) +
            " (" + jsonText(*found).substr(0, 40) + ")"};
    const std::string given = found->template get<std::string>();
    if (given != format) {
        const auto slash = format.rfind('/');
        const bool newer =
            slash != std::string::npos && given.size() > slash + 1 &&
            given.compare(0, slash + 1, format, 0, slash + 1) == 0 &&
            std::atof(given.c_str() + slash + 1) > std::atof(format.c_str() + slash + 1);
        return Error{source + ": unsupported format \"" + messageText(given) + "\" (expected \"" +
                     format + "\")" +
                     (newer
                          ? ": a newer Fieldsight wrote it; this one reads only \"" + format + "\""
                          : std::string())};
    }
    return std::nullopt;
}

/// Parses `text` (from `source`, for messages) as a JSON object whose "format" is `format`.
inline Result<nlohmann::json> parseFormattedJson(const std::string& text, const std::string& source,
                                                 const std::string& format)
{
    auto parsed = parseJson(text, source);
    if (!parsed)
        return parsed.error();
    nlohmann::json root = std::move(parsed).value();
    if (auto problem = formatProblem(root, source, format))
        return *problem;
    return root;
}

/// The keys of `object` not in `known`, as the text of a JSON object ("" none): what a reader
/// keeps of a file it does not understand, to write back (addUnknownKeys) so that a newer
/// Fieldsight's or another tool's fields survive a save.
inline std::string unknownKeys(const nlohmann::json& object, const std::set<std::string>& known)
{
    nlohmann::ordered_json unknown = nlohmann::ordered_json::object();
    for (const auto& item : object.items())
        if (known.find(item.key()) == known.end())
            unknown[item.key()] = item.value();
    return unknown.empty() ? std::string() : jsonText(unknown);
}

/// Adds the keys of `unknown` (unknownKeys()' text) to `object` after its own; a key `object`
/// has already is not replaced.
inline void addUnknownKeys(const std::string& unknown, nlohmann::ordered_json& object)
{
    if (unknown.empty())
        return;
    nlohmann::ordered_json kept = nlohmann::ordered_json::parse(unknown);
    for (auto& item : kept.items())
        if (!object.contains(item.key()))
            object[item.key()] = std::move(item.value());
}

} // namespace fieldsight
