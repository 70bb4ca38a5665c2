// The stream.json manifest: every key checked, every problem named with the file.
#include "io/stream_manifest.h"

#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/json_text.h"
#include "visioncore/basics/message_text.h"
#include "basics/json_format.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <system_error>

#include <unistd.h>

namespace fieldsight::io {

namespace {

/// A JSON array of exactly two numbers.
std::optional<std::array<double, 2>> numberPair(const nlohmann::json& value)
{
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
        return std::nullopt;
    return std::array<double, 2>{value[0].get<double>(), value[1].get<double>()};
}

/// 0, 90, 180 or 270 as a JSON number (180.0 too).
std::optional<Orientation> orientationOf(const nlohmann::json& value)
{
    if (value.is_number_integer())
        return orientationFromDegrees(value.get<long long>());
    if (value.is_number_float()) {
        const double d = value.get<double>();
        for (Orientation o : {Orientation::Upright, Orientation::Clockwise90, Orientation::Half,
                              Orientation::Clockwise270})
            if (d == double(degrees(o)))
                return o;
    }
    return std::nullopt;
}

/// A JSON value as a message shows it, cut short.
std::string shortText(const nlohmann::json& value)
{
    std::string text = jsonText(value);
    if (text.size() > 40)
        text = text.substr(0, 37) + "...";
    return text;
}

/// Reads entry `i` of the manifest's "frames" into `manifest`; on bad input, "frames[i]... must
/// be ...".
std::optional<std::string> readFrameEntry(const nlohmann::json& entry, std::size_t i,
                                          Manifest& manifest)
{
    const std::string where = "frames[" + std::to_string(i) + "]";
    if (!entry.is_object())
        return where + " must be an object";
    const auto file = entry.find("file");
    if (file == entry.end() || !file->is_string())
        return where + ".file must be a string";
    if (manifest.frames.count(file->get<std::string>()))
        return where + ".file \"" + messageText(file->get<std::string>()) + "\" is listed twice";
    FrameMeta meta;
    if (const auto t = entry.find("timestamp_ms"); t != entry.end()) {
        if (!t->is_number())
            return where + ".timestamp_ms must be a number";
        meta.timestamp_ms = t->get<double>();
    }
    if (const auto h = entry.find("horizon"); h != entry.end()) {
        const auto pair = numberPair(*h);
        if (!pair)
            return where + ".horizon must be [y at x = 0, y at x = width-1]";
        meta.horizon = Horizon{(*pair)[0], (*pair)[1]};
        if (!meta.horizon->isPlausible())
            return where + ".horizon must be two image rows from -1e6 to 1e6";
    }
    manifest.frames[file->get<std::string>()] = meta;
    return std::nullopt;
}

Result<Manifest> readManifest(const std::string& path, std::size_t frames)
{
    auto text = readWholeFile(path, maxManifestBytes(frames),
                              "a stream.json of " + std::to_string(frames) + " frames");
    if (!text)
        return text.error();
    auto bad = [&](const std::string& problem) { return Error{path + ": " + problem}; };
    // Each frame entry is read as the parser completes it and its JSON dropped: the whole
    // manifest is never held parsed (15 to 25 times its text).
    Manifest manifest;
    std::optional<Error> entry_problem;
    auto parsed =
        parseJsonMembers(text.value(), path, "frames",
                         [&](const std::string&, std::size_t i, const nlohmann::json& entry) {
                             if (!entry_problem)
                                 if (auto problem = readFrameEntry(entry, i, manifest))
                                     entry_problem = bad(*problem);
                         });
    if (!parsed)
        return parsed.error();
    const nlohmann::json root = std::move(parsed).value();
    if (!root.is_object())
        return bad("expected a JSON object at the top level");

    if (const auto it = root.find("format"); it != root.end()) {
        if (!it->is_string())
            return bad("\"format\" must be a string");
        if (it->get<std::string>() != kManifestFormat)
            return bad("unsupported format \"" + messageText(it->get<std::string>()) +
                       "\" (expected \"" + kManifestFormat + "\")");
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
    std::optional<Orientation> flipped;
    if (const auto it = root.find("flipped"); it != root.end()) {
        if (!it->is_boolean())
            return bad("\"flipped\" must be true or false");
        flipped = it->get<bool>() ? Orientation::Half : Orientation::Upright;
        manifest.orientation = *flipped;
    }
    if (const auto it = root.find("orientation"); it != root.end()) {
        const std::optional<Orientation> o = orientationOf(*it);
        if (!o)
            return bad("\"orientation\" must be 0, 90, 180 or 270 (degrees clockwise to turn "
                       "the pictures upright), not " +
                       shortText(*it));
        if (flipped && *flipped != *o)
            return bad("\"flipped\" (" + shortText(root["flipped"]) + ") and \"orientation\" (" +
                       orientationText(*o) + ") disagree; \"flipped\": true is orientation 180");
        manifest.orientation = *o;
    }
    if (const auto it = root.find("lut"); it != root.end()) {
        if (!it->is_string())
            return bad("\"lut\" must be a string (a file name relative to the folder)");
        manifest.lut = it->get<std::string>();
    }
    if (const auto it = root.find("params"); it != root.end()) {
        if (!it->is_string())
            return bad("\"params\" must be a string (a fieldsight-params/1 file name relative to "
                       "the folder)");
        manifest.params = it->get<std::string>();
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
    if (const auto it = root.find("frames"); it != root.end() && !it->is_array())
        return bad("\"frames\" must be an array");
    if (entry_problem)
        return *entry_problem;
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

namespace fieldsight {

namespace {

/// No write permission for anyone, or none for this process (a read-only mount, another
/// user's folder). A folder made read-only on purpose is respected even by root, who could
/// write into it.
bool readOnly(const std::filesystem::path& path)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::perms perms = fs::status(path, ec).permissions();
    if (ec)
        return false; // not there: the write itself says why
    const fs::perms writable =
        fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write;
    return (perms & writable) == fs::perms::none || ::access(path.c_str(), W_OK) != 0;
}

} // namespace

namespace {

/// Rewrites the folder's manifest with `change` applied (keeping every other key in its order),
/// or makes one naming only the format; `what` names the setting in the errors.
Status updateManifest(const std::string& folder, const std::string& what,
                      const std::function<void(nlohmann::ordered_json&)>& change)
{
    namespace fs = std::filesystem;
    const fs::path path = fs::path(folder) / io::kManifestName;
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        return Error{folder + ": not a folder of images; only an image folder has a " +
                     io::kManifestName + " to keep its " + what + " in"};
    if (readOnly(folder))
        return Error{folder + ": the folder is read-only; the " + what + " was not saved"};
    nlohmann::ordered_json root;
    if (fs::exists(fs::symlink_status(path, ec))) {
        // Only a manifest the stream opens with is rewritten: a damaged one stays as it is.
        std::size_t entries = 0; // at least the frames: the stream's own cap, or more
        for (fs::directory_iterator it(folder, ec); !ec && it != fs::directory_iterator();
             it.increment(ec))
            ++entries;
        if (auto checked = io::parseManifest(path.string(), entries); !checked)
            return Error{checked.error().message + "; the " + what + " was not saved"};
        if (readOnly(path))
            return Error{path.string() + ": the file is read-only; the " + what + " was not saved"};
        auto text = readWholeFile(path.string());
        if (!text)
            return text.error();
        auto parsed = parseJson<nlohmann::ordered_json>(text.value(), path.string());
        if (!parsed)
            return parsed.error();
        root = std::move(parsed).value();
    } else {
        root["format"] = io::kManifestFormat;
    }
    change(root);
    return writeFileAtomically(path.string(), jsonText(root, 1) + "\n");
}

} // namespace

Status writeStreamOrientation(const std::string& folder, Orientation o)
{
    return updateManifest(folder, "orientation", [o](nlohmann::ordered_json& root) {
        root.erase("flipped");
        root["orientation"] = degrees(o);
    });
}

namespace {

/// `file` as the manifest of `folder` names it: relative to the folder when inside it, so the
/// stream can move with its files.
std::string namedFromFolder(const std::string& folder, const std::string& file)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path base = fs::weakly_canonical(fs::absolute(folder, ec), ec);
    const fs::path target = fs::weakly_canonical(fs::absolute(file, ec), ec);
    fs::path named = target.lexically_relative(base);
    if (named.empty() || *named.begin() == "..")
        named = target;
    return named.string();
}

} // namespace

Status writeStreamLut(const std::string& folder, const std::string& lut)
{
    return updateManifest(folder, "table",
                          [named = namedFromFolder(folder, lut)](nlohmann::ordered_json& root) {
                              root["lut"] = named;
                          });
}

Status writeStreamParams(const std::string& folder, const std::string& params)
{
    return updateManifest(folder, "parameter file",
                          [named = namedFromFolder(folder, params)](nlohmann::ordered_json& root) {
                              root["params"] = named;
                          });
}

} // namespace fieldsight
