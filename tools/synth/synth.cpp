// Writes a generated stream: PNG frames, stream.json, annotations.json, default.lut, image.strm.
#include "synth/synth.h"

#include "synth/ideal_lut.h"
#include "synth/scenario_script.h"
#include "synth/stream_frame.h"

#include "visioncore/framework/controller.h"
#include "visioncore/io/annotations.h"
#include "visioncore/basics/atomic_file.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/io/stream_reader.h"

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <system_error>

namespace fieldsight::synth {

namespace {

/// The LUT is voted over at least this many frames, so even a one-frame stream gets a usable one.
constexpr int kMinTrainingFrames = 24;
constexpr int kMaxFrames = 1000000;

double round2(double v)
{
    return std::round(v * 100.0) / 100.0;
}

} // namespace

std::vector<std::string> scenarioNames()
{
    return {"lab1", "lab2", "difficult", "rc2012", "rc2013"};
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
    }
    return 0;
}

namespace {

/// The files synth writes into its folder.
bool isSynthFile(const std::string& name)
{
    return name == "image.strm" || name == "default.lut" || name == "annotations.json" ||
           name == "stream.json" ||
           (name.rfind("frame_", 0) == 0 && name.size() > 10 &&
            name.compare(name.size() - 4, 4, ".png") == 0);
}

/// A folder synth wrote before: its stream.json names the generator, or (frames only in
/// image.strm) it holds exactly image.strm, annotations.json and default.lut.
bool isEarlierSynthOutput(const std::filesystem::path& dir)
{
    std::error_code ec;
    if (auto text = readWholeFile((dir / "stream.json").string()); text) {
        const auto manifest = nlohmann::json::parse(text.value(), nullptr, false);
        return manifest.is_object() && manifest.contains("generator");
    }
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        names.insert(entry.path().filename().string());
    return !ec && names == std::set<std::string>{"annotations.json", "default.lut", "image.strm"};
}

} // namespace

Status clearEarlierOutput(const std::string& folder)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(folder, ec))
        return {};
    if (!fs::is_directory(folder, ec))
        return Error{folder + ": exists and is not a folder; nothing was written"};
    if (fs::is_empty(folder, ec))
        return {};
    if (!isEarlierSynthOutput(folder))
        return Error{folder + ": the folder is not empty and is not an earlier synth output; "
                              "nothing was written (choose a new or empty folder)"};
    // Its own earlier stream is replaced whole, never mixed with the new one.
    for (const auto& entry : fs::directory_iterator(folder, ec))
        if (entry.is_regular_file() && isSynthFile(entry.path().filename().string()))
            fs::remove(entry.path(), ec);
    return {};
}

Status generateStream(const SynthOptions& options)
{
    namespace fs = std::filesystem;
    if (options.out_dir.empty())
        return Error{"synth: no output folder given"};
    if (options.frames < 1 || options.frames > kMaxFrames)
        return Error{options.out_dir + ": frame count " + std::to_string(options.frames) +
                     " is out of range (1.." + std::to_string(kMaxFrames) + ")"};
    if (options.width < 16 || options.height < 16 || options.width > 4096 || options.height > 4096)
        return Error{options.out_dir + ": image size " + std::to_string(options.width) + "x" +
                     std::to_string(options.height) + " is out of range (16x16..4096x4096)"};
    if (Status s = clearEarlierOutput(options.out_dir); !s)
        return s;
    std::error_code ec;
    fs::create_directories(options.out_dir, ec);
    if (ec || !fs::is_directory(options.out_dir))
        return Error{options.out_dir + ": cannot create the folder: " +
                     (ec ? ec.message() : std::string("not a directory"))};
    const fs::path dir(options.out_dir);

    const ScenarioScript script(options.scenario, options.seed, options.width, options.height);
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

    const int rendered = std::max(options.frames, kMinTrainingFrames);
    for (int i = 0; i < rendered; ++i) {
        StreamFrame frame = renderStreamFrame(script, i);
        lut.addFrame(frame.image.ycbcr, frame.image.labels);
        if (i >= options.frames)
            continue; // a training frame only
        if (options.write_png) {
            std::vector<unsigned char> png;
            try {
                cv::imencode(".png", frame.image.bgr, png,
                             {cv::IMWRITE_PNG_COMPRESSION, 9, cv::IMWRITE_PNG_STRATEGY,
                              cv::IMWRITE_PNG_STRATEGY_FILTERED});
            } catch (const cv::Exception& e) {
                return Error{(dir / frame.name).string() + ": cannot encode PNG: " + e.what()};
            }
            if (Status s = writeFileAtomically((dir / frame.name).string(), png.data(), png.size());
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
    const nlohmann::json manifest = {{"format", "fieldsight-stream/1"},
                                     {"pixel_format", "rgb"},
                                     {"lut", "default.lut"},
                                     {"camera", {{"fov_deg", {62.8, 48.8}}, {"height_m", 0.45}}},
                                     {"generator",
                                      {{"scenario", scenarioName(options.scenario)},
                                       {"seed", options.seed},
                                       {"ball_diameter_m", FieldGeometry::kBallDiameter}}},
                                     {"frames", frames}};
    return writeFileAtomically((dir / "stream.json").string(), manifest.dump(1) + "\n");
}

} // namespace fieldsight::synth
