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

/// Parses `text` (from `source`, for messages) as JSON, handing each member of the top-level
/// object's `list_key` (an object's or an array's) to `each(name, index, value)` as soon as the
/// parser has it whole (`name` empty for an array's), and then dropping it: the tree returned
/// holds `list_key` empty, so a file of many frames or samples is never held parsed whole (15 to
/// 25 times its text). A syntax error is an Error saying where.
template <class Each>
Result<nlohmann::json> parseJsonMembers(const std::string& text, const std::string& source,
                                        const std::string& list_key, Each each)
{
    using Event = nlohmann::json::parse_event_t;
    std::string top_key, name;
    std::size_t index = 0;
    bool inside = false;
    const auto callback = [&](int depth, Event event, nlohmann::json& value) {
        if (depth == 1) {
            if (event == Event::key)
                top_key = value.template get<std::string>();
            else if (event == Event::object_start || event == Event::array_start)
                inside = top_key == list_key, index = 0;
            else if (event == Event::object_end || event == Event::array_end)
                inside = false;
            return true;
        }
        if (depth != 2 || !inside || event == Event::object_start || event == Event::array_start)
            return true;
        if (event == Event::key) {
            name = value.template get<std::string>();
            return true;
        }
        each(name, index++, value); // an object's or array's end, or a plain value
        return false;
    };
    try {
        return nlohmann::json::parse(text, nlohmann::json::parser_callback_t(callback));
    } catch (const nlohmann::json::exception& e) { // a syntax error, or a number overflow
        return Error{jsonSyntaxError(source, e.what())};
    }
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
    // unknownKeys() wrote it: it is JSON.
    nlohmann::ordered_json kept = parseJson<nlohmann::ordered_json>(unknown, "").value();
    for (auto& item : kept.items())
        if (!object.contains(item.key()))
            object[item.key()] = std::move(item.value());
}

} // namespace fieldsight
