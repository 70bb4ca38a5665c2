// The stream.json manifest: every key checked, every problem named with the file.
#include "io/stream_manifest.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/json_text.h"

#include <nlohmann/json.hpp>

#include <cstddef>

namespace fieldsight::io {

namespace {

/// A JSON array of exactly two numbers.
std::optional<std::array<double, 2>> numberPair(const nlohmann::json& value)
{
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
        return std::nullopt;
    return std::array<double, 2>{value[0].get<double>(), value[1].get<double>()};
}

Result<Manifest> readManifest(const std::string& path, std::size_t frames)
{
    auto text = readWholeFile(path, maxManifestBytes(frames),
                              "a stream.json of " + std::to_string(frames) + " frames");
    if (!text)
        return text.error();
    auto parsed = parseJson(text.value(), path);
    if (!parsed)
        return parsed.error();
    const nlohmann::json root = std::move(parsed).value();
    auto bad = [&](const std::string& problem) { return Error{path + ": " + problem}; };
    if (!root.is_object())
        return bad("expected a JSON object at the top level");

    Manifest manifest;
    if (const auto it = root.find("format"); it != root.end()) {
        if (!it->is_string())
            return bad("\"format\" must be a string");
        if (it->get<std::string>() != kManifestFormat)
            return bad("unsupported format \"" + it->get<std::string>() + "\" (expected \"" +
                       kManifestFormat + "\")");
    }
    if (const auto it = root.find("pixel_format"); it != root.end()) {
        const std::string value = it->is_string() ? it->get<std::string>() : std::string();
        if (value == "rgb")
            manifest.pixel_format = PixelFormat::Rgb;
        else if (value == "ycbcr")
            manifest.pixel_format = PixelFormat::YCbCr;
        else
            return bad("\"pixel_format\" must be \"rgb\" or \"ycbcr\"");
    }
    if (const auto it = root.find("flipped"); it != root.end()) {
        if (!it->is_boolean())
            return bad("\"flipped\" must be true or false");
        manifest.flipped = it->get<bool>();
    }
    if (const auto it = root.find("lut"); it != root.end()) {
        if (!it->is_string())
            return bad("\"lut\" must be a string (a file name relative to the folder)");
        manifest.lut = it->get<std::string>();
    }
    if (const auto it = root.find("camera"); it != root.end()) {
        if (!it->is_object())
            return bad("\"camera\" must be an object");
        if (const auto fov = it->find("fov_deg"); fov != it->end()) {
            manifest.fov_deg = numberPair(*fov);
            if (!manifest.fov_deg)
                return bad("\"camera.fov_deg\" must be an array of two numbers");
        }
    }
    if (const auto it = root.find("frames"); it != root.end()) {
        if (!it->is_array())
            return bad("\"frames\" must be an array");
        for (std::size_t i = 0; i < it->size(); ++i) {
            const nlohmann::json& entry = (*it)[i];
            const std::string where = "frames[" + std::to_string(i) + "]";
            if (!entry.is_object())
                return bad(where + " must be an object");
            const auto file = entry.find("file");
            if (file == entry.end() || !file->is_string())
                return bad(where + ".file must be a string");
            if (manifest.frames.count(file->get<std::string>()))
                return bad(where + ".file \"" + file->get<std::string>() + "\" is listed twice");
            FrameMeta meta;
            if (const auto t = entry.find("timestamp_ms"); t != entry.end()) {
                if (!t->is_number())
                    return bad(where + ".timestamp_ms must be a number");
                meta.timestamp_ms = t->get<double>();
            }
            if (const auto h = entry.find("horizon"); h != entry.end()) {
                const auto pair = numberPair(*h);
                if (!pair)
                    return bad(where + ".horizon must be [y at x = 0, y at x = width-1]");
                meta.horizon = Horizon{(*pair)[0], (*pair)[1]};
                if (!meta.horizon->isPlausible())
                    return bad(where + ".horizon must be two image rows from -1e6 to 1e6");
            }
            manifest.frames[file->get<std::string>()] = meta;
        }
    }
    return manifest;
}

} // namespace

std::size_t maxManifestBytes(std::size_t frames)
{
    return (std::size_t(1) << 20) + frames * 1024;
}

Result<Manifest> parseManifest(const std::string& path, std::size_t frames)
{
    return readingWithinMemory(path, [&] { return readManifest(path, frames); });
}

} // namespace fieldsight::io
