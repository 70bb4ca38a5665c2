// Ground-truth annotation files (SPEC §5.2): strict reading, atomic writing.
#include "visioncore/io/annotations.h"

#include "visioncore/basics/json_text.h"
#include "basics/json_format.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/message_text.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>

namespace fieldsight {

namespace {
constexpr const char* kAnnotationsFormat = "fieldsight-annotations/1";
using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

constexpr const char* kFlagKeys[] = {"concealed", "keyframe", "interpolate", "interpolated",
                                     "track"};

/// The keys an object of the kind of `entry` (a list read from the file) is read from: those
/// its list is written with, under either names (a goalpost's base in results), and the flags.
std::set<std::string> knownKeys(const PerceptEntry& entry)
{
    std::set<std::string> keys(std::begin(kFlagKeys), std::end(kFlagKeys));
    for (PerceptNames names : {PerceptNames::Truth, PerceptNames::Results}) {
        OrderedJson written;
        entry.toJson(names, written);
        if (written.is_array() && !written.empty() && written.front().is_object())
            for (const auto& item : written.front().items())
                keys.insert(item.key());
    }
    return keys;
}

/// The keys each kind's objects are read from, found once a kind's first list is read.
using KnownKeys = std::map<const PerceptKind*, std::set<std::string>>;

/// Reads the optional flags of each object of every list of `kinds` in frame `json`, and keeps
/// the keys it does not know. Lists that are not lists of objects (the field boundary's bare
/// polyline) have none.
std::optional<std::string> readFlags(const Json& json, const std::vector<const PerceptKind*>& kinds,
                                     const std::string& where, FrameAnnotation& frame,
                                     KnownKeys& known_keys)
{
    for (const PerceptKind* kind : kinds) {
        const auto list = json.find(std::string(kind->truth_key));
        if (list == json.end() || !list->is_array() || list->empty())
            continue;
        auto known = known_keys.find(kind);
        if (known == known_keys.end()) {
            const PerceptEntry* entry = frame.truth.find(*kind);
            if (!entry || entry->size() == 0)
                continue;
            known = known_keys.emplace(kind, knownKeys(*entry)).first;
        }
        for (std::size_t i = 0; i < list->size(); ++i) {
            const Json& object = (*list)[i];
            if (!object.is_object())
                continue;
            const std::string at =
                where + "." + std::string(kind->truth_key) + "[" + std::to_string(i) + "].";
            ObjectFlags flags;
            for (auto [name, field] :
                 {std::pair{"concealed", &flags.concealed}, std::pair{"keyframe", &flags.keyframe},
                  std::pair{"interpolate", &flags.interpolate},
                  std::pair{"interpolated", &flags.interpolated}}) {
                const auto it = object.find(name);
                if (it == object.end())
                    continue;
                if (!it->is_boolean())
                    return at + name + " must be true or false";
                *field = it->get<bool>();
            }
            if (const auto it = object.find("track"); it != object.end()) {
                if (!it->is_number_integer() || it->get<long long>() < 0 ||
                    it->get<long long>() > 1'000'000'000)
                    return at + "track must be a whole number from 0 to 1000000000";
                flags.track = int(it->get<long long>());
            }
            flags.unknown = unknownKeys(object, known->second);
            if (!flags.isDefault())
                frame.setFlags(kind->truth_key, i, flags);
        }
    }
    return std::nullopt;
}

std::optional<std::string> readReviewed(const Json& json, const std::string& where,
                                        FrameAnnotation& frame)
{
    const auto reviewed = json.find("reviewed");
    if (reviewed == json.end())
        return std::nullopt;
    const std::string problem = where + ".reviewed must be a list of annotation keys";
    if (!reviewed->is_array())
        return problem;
    for (const Json& key : *reviewed) {
        if (!key.is_string())
            return problem;
        frame.reviewed.insert(key.get<std::string>());
    }
    return std::nullopt;
}

void writeFlags(const FrameAnnotation& frame, OrderedJson& out)
{
    for (const auto& [key, list] : frame.flags) {
        const auto objects = out.find(key);
        if (objects == out.end() || !objects->is_array())
            continue;
        for (std::size_t i = 0; i < list.size() && i < objects->size(); ++i) {
            const ObjectFlags& f = list[i];
            OrderedJson& object = (*objects)[i];
            if (!object.is_object())
                continue;
            if (f.concealed)
                object["concealed"] = true;
            if (f.track != 0)
                object["track"] = f.track;
            if (f.keyframe)
                object["keyframe"] = true;
            if (!f.interpolate)
                object["interpolate"] = false;
            if (f.interpolated)
                object["interpolated"] = true;
            addUnknownKeys(f.unknown, object);
        }
    }
}

/// Reads the frames of one annotations file as the parser finishes each, checking their names.
class FrameReader
{
public:
    FrameReader(const std::string& source, const std::vector<const PerceptKind*>& kinds,
                Annotations& out)
        : m_source(source), m_kinds(kinds), m_out(out)
    {
        for (const PerceptKind* kind : kinds)
            m_known.insert(std::string(kind->truth_key));
        m_known.insert("done");
        m_known.insert("reviewed");
    }

    /// Reads frame `name` from `json`; on bad input, the Error.
    std::optional<Error> add(const std::string& name, const Json& json)
    {
        const std::string where = "frames[\"" + messageText(name) + "\"]";
        if (auto problem = frameNameProblem(name))
            return Error{m_source + ": " + where + ": the frame name " + *problem +
                         "; a frame is named by its file name alone"};
        const auto [same, fresh] = m_by_stem.emplace(frameStem(name), name);
        if (!fresh)
            return Error{m_source + ": " + where + " and frames[\"" + messageText(same->second) +
                         "\"] name the same frame; keep one of them"};
        if (!json.is_object())
            return Error{m_source + ": " + where + " must be an object"};
        FrameAnnotation frame;
        if (const auto done = json.find("done"); done != json.end()) {
            if (!done->is_boolean())
                return Error{m_source + ": " + where + ".done must be true or false"};
            frame.done = done->get<bool>();
        }
        if (auto problem = frame.truth.fromJson(json, m_kinds, PerceptNames::Truth, where))
            return Error{m_source + ": " + *problem};
        if (auto problem = readFlags(json, m_kinds, where, frame, m_known_keys))
            return Error{m_source + ": " + *problem};
        if (auto problem = readReviewed(json, where, frame))
            return Error{m_source + ": " + *problem};
        frame.unknown = unknownKeys(json, m_known);
        m_out.frames.emplace(name, std::move(frame));
        return std::nullopt;
    }

private:
    const std::string& m_source;
    const std::vector<const PerceptKind*>& m_kinds;
    Annotations& m_out;
    std::set<std::string> m_known;                ///< a frame's keys that are read
    std::map<std::string, std::string> m_by_stem; ///< the names read, by frameStem()
    KnownKeys m_known_keys;
};
} // namespace

ObjectFlags FrameAnnotation::flagsOf(std::string_view truth_key, std::size_t index) const
{
    const auto it = flags.find(truth_key);
    return it != flags.end() && index < it->second.size() ? it->second[index] : ObjectFlags{};
}

void FrameAnnotation::setFlags(std::string_view truth_key, std::size_t index, const ObjectFlags& f)
{
    auto it = flags.find(truth_key);
    if (it == flags.end()) {
        if (f.isDefault())
            return;
        it = flags.emplace(std::string(truth_key), std::vector<ObjectFlags>{}).first;
    }
    if (it->second.size() <= index)
        it->second.resize(index + 1);
    it->second[index] = f;
}

void FrameAnnotation::eraseFlags(std::string_view truth_key, std::size_t index)
{
    const auto it = flags.find(truth_key);
    if (it != flags.end() && index < it->second.size())
        it->second.erase(it->second.begin() + std::ptrdiff_t(index));
}

bool operator==(const FrameAnnotation& a, const FrameAnnotation& b)
{
    if (a.done != b.done || a.reviewed != b.reviewed || a.unknown != b.unknown)
        return false;
    OrderedJson ja, jb;
    a.truth.toJson(ja, PerceptNames::Truth);
    b.truth.toJson(jb, PerceptNames::Truth);
    writeFlags(a, ja);
    writeFlags(b, jb);
    // Lists in either order of creation compare equal: compare as unordered JSON.
    // Through text, as a file would compare (a NaN is null there).
    return parseJson(jsonText(ja), "").value() == parseJson(jsonText(jb), "").value();
}

Result<Annotations> Annotations::fromJson(const std::string& text, const std::string& source,
                                          const std::vector<const PerceptKind*>& kinds)
{
    // Each frame is read as soon as the parser has it and then dropped, so the whole file is
    // never held as parsed JSON (15 to 25 times its text).
    Annotations annotations;
    FrameReader reader(source, kinds, annotations);
    std::optional<Error> problem;
    auto parsed = parseJsonMembers(text, source, "frames",
                                   [&](const std::string& name, std::size_t, const Json& frame) {
                                       if (!problem)
                                           problem = reader.add(name, frame);
                                   });
    if (!parsed)
        return parsed.error();
    const Json& root = parsed.value();
    if (auto bad = formatProblem(root, source, kAnnotationsFormat))
        return *bad;
    if (const auto frames = root.find("frames"); frames != root.end() && !frames->is_object())
        return Error{source + ": \"frames\" must be an object keyed by frame name"};
    if (problem)
        return *problem;
    annotations.unknown = unknownKeys(root, {"format", "frames"});
    return annotations;
}

std::size_t maxAnnotationsBytes(std::size_t frames)
{
    return (std::size_t(16) << 20) + frames * 4096;
}

Result<Annotations> Annotations::load(const std::string& path,
                                      const std::vector<const PerceptKind*>& kinds,
                                      std::size_t frames)
{
    return readingWithinMemory(path, [&]() -> Result<Annotations> {
        auto text = readWholeFile(path, maxAnnotationsBytes(frames),
                                  frames ? "annotations of " + std::to_string(frames) + " frames"
                                         : std::string("annotations"));
        if (!text)
            return text.error();
        return fromJson(text.value(), path, kinds);
    });
}

std::string Annotations::toJson(const std::vector<const PerceptKind*>& order) const
{
    OrderedJson frames_json = OrderedJson::object();
    for (const auto& [name, frame] : frames) {
        OrderedJson out;
        out["done"] = frame.done;
        if (!frame.reviewed.empty())
            out["reviewed"] = frame.reviewed;
        frame.truth.toJson(out, PerceptNames::Truth, order);
        writeFlags(frame, out);
        addUnknownKeys(frame.unknown, out);
        frames_json[name] = std::move(out);
    }
    OrderedJson root;
    root["format"] = kAnnotationsFormat;
    root["frames"] = std::move(frames_json);
    addUnknownKeys(unknown, root);
    return jsonText(root, 1) + "\n";
}

std::optional<std::string> frameNameProblem(const std::string& name)
{
    if (name.empty())
        return "is empty";
    if (name == "." || name == "..")
        return "is '" + name + "', a folder";
    if (name.find_first_of("/\\") != std::string::npos)
        return "has a path separator ('/' or '\\')";
    for (const char c : name)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            return std::string(c == 0 ? "has a NUL byte inside" : "has a control character");
    return std::nullopt;
}

std::string frameStem(const std::string& name)
{
    return std::filesystem::path(name).stem().string();
}

std::map<std::string, const PerceptSet*> Annotations::truthByStem() const
{
    std::map<std::string, const PerceptSet*> out;
    for (const auto& [name, frame] : frames)
        out.emplace(frameStem(name), &frame.truth);
    return out;
}

Status Annotations::save(const std::string& path,
                         const std::vector<const PerceptKind*>& order) const
{
    return writeFileAtomically(path, toJson(order));
}

} // namespace fieldsight
