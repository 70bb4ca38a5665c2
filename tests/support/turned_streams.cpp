// Streams stored turned, for the orientation tests.
#include "support/turned_streams.h"

#include "support/synthetic_frames.h"
#include "support/test_images.h"
#include "visioncore/basics/atomic_file.h"

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <QtGlobal>

#include <cstdio>
#include <filesystem>

namespace fieldsight::test {

namespace {

/// The turn that undoes `o`.
Orientation undoing(Orientation o)
{
    return *orientationFromDegrees((360 - degrees(o)) % 360);
}

} // namespace

cv::Mat uprightScene(int i)
{
    cv::Mat f = filledFrame(320, 240, Colour::Unclassified);
    fillRect(f, 0, 60, 319, 239, Colour::Green);
    fillRect(f, 200, 10, 209, 100, Colour::Yellow);
    fillCircle(f, 100 + 30 * i, 160, 9, Colour::Orange);
    drawLine(f, 0, 200, 319, 180, 3, Colour::White);
    return f;
}

bool writeTurnedStream(const std::string& dir, const std::vector<cv::Mat>& upright,
                       const TurnedStream& how)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dir, ec);
    nlohmann::json frames = nlohmann::json::array();
    for (std::size_t i = 0; i < upright.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%06zu.png", i);
        cv::Mat stored;
        orientImage(upright[i], stored, undoing(how.stored));
        // The PNG's R, G, B hold Y, Cb, Cr; imwrite takes B, G, R.
        cv::Mat bgr;
        cv::cvtColor(stored, bgr, cv::COLOR_RGB2BGR);
        if (!fieldsight::test::imwrite((fs::path(dir) / name).string(), bgr)) {
            qWarning("cannot write %s in %s", name, dir.c_str());
            return false;
        }
        nlohmann::json entry{{"file", name}, {"timestamp_ms", 40.0 * double(i)}};
        if (i < how.upright_horizons.size()) {
            // A quarter turn keeps no horizon: the values are then written as they are, for a
            // horizon the reader must drop.
            const Horizon h =
                orientHorizon(how.upright_horizons[i], undoing(how.stored), upright[i].rows)
                    .value_or(how.upright_horizons[i]);
            entry["horizon"] = {h.y_left, h.y_right};
        }
        frames.push_back(std::move(entry));
    }
    nlohmann::json manifest{{"format", "fieldsight-stream/1"},
                            {"pixel_format", "ycbcr"},
                            {"lut", "default.lut"},
                            {"frames", frames}};
    if (how.manifest_orientation)
        manifest["orientation"] = *how.manifest_orientation;
    if (!writeFileAtomically((fs::path(dir) / "stream.json").string(), manifest.dump(1)).ok())
        return false;
    return testLut().save((fs::path(dir) / "default.lut").string()).ok();
}

} // namespace fieldsight::test
