// Writes a generated stream: PNG frames, stream.json, annotations.json, default.lut, image.strm.
#include "synth/synth.h"

#include "synth/camera_model.h"
#include "synth/ideal_lut.h"
#include "synth/output_folder.h"
#include "synth/scenario_script.h"
#include "synth/stream_frame.h"

#include "visioncore/framework/controller.h"
#include "visioncore/io/annotations.h"
#include "visioncore/io/image_files.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/json_text.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/io/stream_reader.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <system_error>

namespace fieldsight::synth {

namespace {

/// The LUT is voted over at least this many frames, so even a one-frame stream gets a usable one.
constexpr int kMinTrainingFrames = 24;
constexpr int kTrainingWidth = 320; ///< px, the widest frame rendered only for the table
constexpr int kMaxFrames = 1000000;

double round2(double v)
{
    return std::round(v * 100.0) / 100.0;
}

} // namespace

std::vector<std::string> scenarioNames()
{
    return {"lab1", "lab2", "difficult", "rc2012", "rc2013", "crowded"};
}

Result<Scenario> scenarioFromName(const std::string& name)
{
    const std::vector<std::string> names = scenarioNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name)
            return Scenario(i);
    std::string known;
    for (const std::string& n : names)
        known += (known.empty() ? "" : ", ") + n;
    return Error{"unknown scenario '" + name + "' (known: " + known + ")"};
}

std::string scenarioName(Scenario scenario)
{
    return scenarioNames()[std::size_t(scenario)];
}

int paperFrameCount(Scenario scenario)
{
    switch (scenario) {
    case Scenario::Lab1:
        return 5090;
    case Scenario::Lab2:
        return 470;
    case Scenario::Difficult:
        return 175;
    case Scenario::RC2012:
        return 2640;
    case Scenario::RC2013:
        return 625;
    case Scenario::Crowded:
        return 300;
    }
    return 0;
}

namespace {

/// The names of the files a stream of `options` has.
std::set<std::string> outputNames(const SynthOptions& options)
{
    std::set<std::string> names{"default.lut", "annotations.json"};
    if (options.write_strm)
        names.insert("image.strm");
    if (options.write_png) {
        names.insert("stream.json");
        for (int i = 0; i < options.frames; ++i)
            names.insert(frameFileName(i));
    }
    return names;
}

/// A new folder beside `out` to generate the stream into whole; never one that was there.
Result<std::filesystem::path> makeStaging(const std::filesystem::path& out)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path parent = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    fs::create_directories(parent, ec);
    for (int i = 0; i < 1000; ++i) {
        const fs::path staging = parent / ("." + out.filename().string() + ".synth-partial" +
                                           (i ? "-" + std::to_string(i) : std::string()));
        if (fs::create_directory(staging, ec) && !ec)
            return staging;
    }
    return Error{out.string() + ": cannot make a folder beside it to write the stream into" +
                 (ec ? ": " + ec.message() : std::string())};
}

Status writeStream(const SynthOptions& options, const std::filesystem::path& dir);

} // namespace

Status generateStream(const SynthOptions& options, bool* refused)
{
    namespace fs = std::filesystem;
    bool folder_refused = false;
    if (options.out_dir.empty())
        return Error{"synth: no output folder given"};
    if (options.frames < 1 || options.frames > kMaxFrames)
        return Error{options.out_dir + ": frame count " + std::to_string(options.frames) +
                     " is out of range (1.." + std::to_string(kMaxFrames) + ")"};
    if (!(options.table_light >= 0 && options.table_light <= 1))
        return Error{options.out_dir + ": table light " + std::to_string(options.table_light) +
                     " is out of range (0..1)"};
    if (!(options.drift >= 0 && options.drift <= 0.5))
        return Error{options.out_dir + ": light drift " + std::to_string(options.drift) +
                     " is out of range (0..0.5)"};
    if (!(options.camera_height >= 0.3 && options.camera_height <= 0.7))
        return Error{options.out_dir + ": camera height " + std::to_string(options.camera_height) +
                     " m is out of range (0.3..0.7)"};
    if (options.width < 16 || options.height < 16 || options.width > 4096 || options.height > 4096)
        return Error{options.out_dir + ": image size " + std::to_string(options.width) + "x" +
                     std::to_string(options.height) + " is out of range (16x16..4096x4096)"};
    // Checked before the frames are rendered, and again (with the new bytes) before anything in
    // the folder is touched.
    std::error_code ec;
    fs::path dir(options.out_dir); // as the user wrote it, for the messages
    if (dir.filename().empty())
        dir = dir.parent_path();
    OutputFolder folder(dir);
    if (Status s = folder.check(outputNames(options)); !s) {
        if (refused)
            *refused = true;
        return s;
    }
    auto staging = makeStaging(fs::absolute(dir, ec).lexically_normal());
    if (!staging)
        return staging.error();
    Status s = writeStream(options, staging.value());
    if (s)
        s = folder.commit(staging.value(), folder_refused);
    fs::remove_all(staging.value(), ec); // made above, ours alone
    if (refused)
        *refused = folder_refused;
    return s;
}

namespace {

Status writeStream(const SynthOptions& options, const std::filesystem::path& dir)
{
    namespace fs = std::filesystem;
    std::error_code ec;

    ScenarioScript script(options.scenario, options.seed, options.width, options.height);
    script.setCameraHeight(options.camera_height);
    // The table is voted from frames all in one light: the first frame's, or the one asked for.
    ScenarioScript first_light = script;
    if (options.table_light != 0)
        first_light.setLightDrift(options.drift, options.frames, options.table_light);
    script.setLightDrift(options.drift, options.frames);
    IdealLutBuilder lut;
    Annotations annotations;
    nlohmann::json frames = nlohmann::json::array();
    std::optional<StrmWriter> strm;
    if (options.write_strm) {
        auto writer = StrmWriter::create((dir / "image.strm").string());
        if (!writer)
            return writer.error();
        strm.emplace(std::move(writer).value());
    }

    // Frames rendered only to vote the table are at most 320 px wide: the colours are the same,
    // and a 1280x720 stream of a few frames no longer renders 24 full-size frames for its table.
    const bool small_training = options.width > kTrainingWidth;
    ScenarioScript training_light =
        small_training
            ? ScenarioScript(options.scenario, options.seed, kTrainingWidth,
                             std::max(1, int(std::lround(double(options.height) * kTrainingWidth /
                                                         options.width))))
            : first_light;
    if (small_training && options.table_light != 0)
        training_light.setLightDrift(options.drift, options.frames, options.table_light);
    training_light.setCameraHeight(options.camera_height);

    const int rendered = std::max(options.frames, kMinTrainingFrames);
    for (int i = 0; i < rendered; ++i) {
        if (i >= options.frames) { // a training frame only
            const StreamFrame frame = renderStreamFrame(training_light, i);
            lut.addFrame(frame.image.ycbcr, frame.image.labels);
            continue;
        }
        StreamFrame frame = renderStreamFrame(script, i);
        if (options.drift == 0) {
            lut.addFrame(frame.image.ycbcr, frame.image.labels);
        } else {
            const StreamFrame lit = renderStreamFrame(first_light, i);
            lut.addFrame(lit.image.ycbcr, lit.image.labels);
        }
        if (options.write_png) {
            // zlib's level 6: level 9 made files a tenth smaller in thirteen times the time
            // (0.18 s against 0.014 s a 320x240 frame, 1.8 s against 0.13 s at 1280x720).
            if (Status s = writeImage((dir / frame.name).string(), frame.image.bgr,
                                      {cv::IMWRITE_PNG_COMPRESSION, 6, cv::IMWRITE_PNG_STRATEGY,
                                       cv::IMWRITE_PNG_STRATEGY_FILTERED});
                !s)
                return s;
        }
        if (strm) {
            Frame f;
            f.ycbcr = frame.image.ycbcr;
            f.name = frame.name;
            f.timestamp_ms = frame.timestamp_ms;
            f.horizon = frame.horizon;
            if (Status s = strm->append(f, false); !s)
                return s;
        }
        annotations.frames[frame.name] = frame.truth;
        frames.push_back(
            {{"file", frame.name},
             {"timestamp_ms", frame.timestamp_ms},
             {"horizon", {round2(frame.horizon.y_left), round2(frame.horizon.y_right)}}});
    }
    if (strm)
        if (Status s = strm->close(); !s)
            return s;

    if (Status s = lut.build().save((dir / "default.lut").string()); !s)
        return s;
    if (Status s = annotations.save((dir / "annotations.json").string(),
                                    Pipeline::standard().perceptKinds());
        !s)
        return s;
    if (!options.write_png)
        return {}; // a manifest would name frames that do not exist
    const bool four_by_three = std::int64_t(options.width) * 3 == std::int64_t(options.height) * 4;
    const double fov_y =
        four_by_three
            ? 48.8
            : std::round(CameraModel(options.width, options.height).fovYDeg() * 100) / 100;
    nlohmann::json manifest = {
        {"format", "fieldsight-stream/1"},
        {"pixel_format", "rgb"},
        {"lut", "default.lut"},
        {"camera", {{"fov_deg", {62.8, fov_y}}, {"height_m", options.camera_height}}},
        {"generator",
         {{"scenario", scenarioName(options.scenario)},
          {"seed", options.seed},
          {"ball_diameter_m", FieldGeometry::kBallDiameter}}},
        {"frames", frames}};
    if (options.drift != 0)
        manifest["generator"]["light_drift"] = options.drift;
    return writeFileAtomically((dir / "stream.json").string(), jsonText(manifest, 1) + "\n");
}

} // namespace

} // namespace fieldsight::synth
