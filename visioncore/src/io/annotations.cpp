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
} // namespace

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
        frame.truth.toJson(out, PerceptNames::Truth, order);
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
