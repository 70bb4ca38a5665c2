// An image folder: FUZZ_MODE "manifest" fuzzes stream.json beside two good frames; "png", "jpg"
// or "bmp" fuzzes the bytes of the second frame a good manifest lists, after a good first frame
// that sets the stream's size (image decoding through the DataWrapper, header checks first).
#include "fuzz_support.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdint>
#include <filesystem>
#include <string>

namespace {

using namespace fieldsight;

/// The folder, made once: a manifest listing frame_0.<ext> and frame_1.<ext>, both good frames.
std::string folder(const std::string& ext)
{
    static const std::string dir = [&] {
        const std::string d = fuzz::scratchDir() + "/stream";
        std::filesystem::create_directories(d);
        cv::Mat bgr(24, 32, CV_8UC3, cv::Scalar(40, 160, 60));
        cv::circle(bgr, {16, 12}, 5, cv::Scalar(0, 128, 255), -1);
        for (int i = 0; i < 2; ++i)
            cv::imwrite(d + "/frame_" + std::to_string(i) + "." + ext, bgr);
        fuzz::writeInput("stream/stream.json", R"({"format": "fieldsight-stream/1", "frames": [)"
                                               R"({"file": "frame_0.)" +
                                                   ext +
                                                   R"(", "horizon": [4, 6]}, {"file": "frame_1.)" +
                                                   ext + R"(", "timestamp_ms": 33.3}]})");
        return d;
    }();
    return dir;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string mode = FUZZ_MODE;
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const std::string dir = folder(mode == "manifest" ? "png" : mode);
    fuzz::writeInput(mode == "manifest" ? "stream/stream.json" : "stream/frame_1." + mode, bytes);
    fuzz::readStream(dir);
    return 0;
}
