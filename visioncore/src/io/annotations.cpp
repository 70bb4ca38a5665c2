// Ground-truth annotation files (SPEC §5.2): strict reading, atomic writing.
#include "visioncore/io/annotations.h"

#include "visioncore/basics/json_text.h"
#include "basics/json_format.h"

#include "visioncore/basics/atomic_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>

namespace fieldsight {

namespace {
constexpr const char* kFormat = "fieldsight-annotations/1";
using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

/// Reads the optional flags of each object of every list of `kinds` in frame `json`. Lists that
/// are not lists of objects (the field boundary's bare polyline) have none.
std::optional<std::string> readFlags(const Json& json, const std::vector<const PerceptKind*>& kinds,
                                     const std::string& where, FrameAnnotation& frame)
{
    for (const PerceptKind* kind : kinds) {
        const auto list = json.find(std::string(kind->truth_key));
        if (list == json.end() || !list->is_array())
            continue;
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
        }
    }
}
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
    if (a.done != b.done || a.reviewed != b.reviewed)
        return false;
    OrderedJson ja, jb;
    a.truth.toJson(ja, PerceptNames::Truth);
    b.truth.toJson(jb, PerceptNames::Truth);
    writeFlags(a, ja);
    writeFlags(b, jb);
    // Lists in either order of creation compare equal: compare as unordered JSON.
    return Json::parse(ja.dump()) == Json::parse(jb.dump());
}

Result<Annotations> Annotations::fromJson(const std::string& text, const std::string& source,
                                          const std::vector<const PerceptKind*>& kinds)
{
    auto parsed = parseFormattedJson(text, source, kFormat);
    if (!parsed)
        return parsed.error();
    const Json& root = parsed.value();

    Annotations annotations;
    const auto frames = root.find("frames");
    if (frames == root.end())
        return annotations;
    if (!frames->is_object())
        return Error{source + ": \"frames\" must be an object keyed by frame name"};
    for (const auto& [name, json] : frames->items()) {
        const std::string where = "frames[\"" + name + "\"]";
        if (!json.is_object())
            return Error{source + ": " + where + " must be an object"};
        FrameAnnotation frame;
        if (const auto done = json.find("done"); done != json.end()) {
            if (!done->is_boolean())
                return Error{source + ": " + where + ".done must be true or false"};
            frame.done = done->get<bool>();
        }
        if (auto problem = frame.truth.fromJson(json, kinds, PerceptNames::Truth, where))
            return Error{source + ": " + *problem};
        if (auto problem = readFlags(json, kinds, where, frame))
            return Error{source + ": " + *problem};
        if (auto problem = readReviewed(json, where, frame))
            return Error{source + ": " + *problem};
        annotations.frames.emplace(name, std::move(frame));
    }
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
        frames_json[name] = std::move(out);
    }
    OrderedJson root;
    root["format"] = kFormat;
    root["frames"] = std::move(frames_json);
    return jsonText(root, 1) + "\n";
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
