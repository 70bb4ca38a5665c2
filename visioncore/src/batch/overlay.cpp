// Overlay images for `fieldsight run --overlays`: each frame with what the pipeline found (and,
// when the stream has annotations, the ground truth in thin dark lines), to look at by eye.
#include "visioncore/atomic_file.h"
#include "visioncore/batch.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <filesystem>

namespace fieldsight {

namespace {

constexpr int kScale = 2; // overlays are drawn at twice the frame size, to be readable

cv::Point at(double x, double y)
{
    return {int(std::lround((x + 0.5) * kScale - 0.5)), int(std::lround((y + 0.5) * kScale - 0.5))};
}

cv::Mat toBgr(const cv::Mat& ycbcr)
{
    cv::Mat ycrcb, bgr;
    const int from_to[] = {0, 0, 1, 2, 2, 1};
    ycrcb.create(ycbcr.size(), CV_8UC3);
    cv::mixChannels(&ycbcr, 1, &ycrcb, 1, from_to, 3);
    cv::cvtColor(ycrcb, bgr, cv::COLOR_YCrCb2BGR);
    cv::resize(bgr, bgr, {}, kScale, kScale, cv::INTER_NEAREST);
    return bgr;
}

} // namespace

cv::Mat renderOverlay(const cv::Mat& ycbcr, const FrameResult& f, const FrameAnnotation* truth)
{
    cv::Mat img = toBgr(ycbcr);
    const cv::Scalar dark(40, 40, 40);
    if (truth) {
        for (std::size_t i = 1; i < truth->field_boundary.size(); ++i)
            cv::line(img, at(truth->field_boundary[i - 1].x, truth->field_boundary[i - 1].y),
                     at(truth->field_boundary[i].x, truth->field_boundary[i].y), dark, 1);
        for (const Ball& b : truth->balls)
            cv::circle(img, at(b.x, b.y), int(b.radius * kScale), dark, 1);
        for (const Goalpost& g : truth->goalposts)
            cv::rectangle(img, at(g.left, g.top), at(g.right, g.bottom), dark, 1);
        for (const Obstacle& o : truth->obstacles)
            cv::rectangle(img, at(o.left, o.top), at(o.right, o.bottom), dark, 1);
    }
    for (std::size_t i = 1; i < f.green_horizon.size(); ++i)
        cv::line(img, at(f.green_horizon[i - 1].x, f.green_horizon[i - 1].y),
                 at(f.green_horizon[i].x, f.green_horizon[i].y), cv::Scalar(255, 0, 255), 2);
    for (const FieldLine& l : f.field_lines)
        cv::line(img, at(l.x1, l.y1), at(l.x2, l.y2), cv::Scalar(0, 0, 255), 2);
    for (const Obstacle& o : f.obstacles)
        cv::rectangle(img, at(o.left, o.top), at(o.right, o.bottom), cv::Scalar(255, 255, 0), 2);
    for (const Goalpost& g : f.goalposts) {
        cv::rectangle(img, at(g.left, g.top), at(g.right, g.bottom), cv::Scalar(0, 255, 255), 2);
        cv::circle(img, at(g.base_x, g.base_y), 4, cv::Scalar(255, 0, 0), cv::FILLED);
    }
    for (const Ball& b : f.balls)
        cv::circle(img, at(b.x, b.y), int(b.radius * kScale), cv::Scalar(0, 160, 255), 2);
    return img;
}

Status writeOverlays(BatchInput& input, const std::vector<FrameResult>& frames,
                     const std::string& dir, const Annotations* truth)
{
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec)
        return Error{dir + ": cannot create folder: " + ec.message()};
    for (const FrameResult& f : frames) {
        auto frame = input.reader->read(f.index);
        if (!frame)
            return frame.error();
        const FrameAnnotation* t = nullptr;
        if (truth) {
            auto it = truth->frames.find(f.name);
            t = it == truth->frames.end() ? nullptr : &it->second;
        }
        std::vector<unsigned char> png;
        if (!cv::imencode(".png", renderOverlay(frame.value().ycbcr, f, t), png))
            return Error{dir + ": cannot encode overlay of " + f.name};
        const std::string stem = std::filesystem::path(f.name).stem().string();
        if (Status s = writeFileAtomically(dir + "/" + stem + ".png", png.data(), png.size()); !s)
            return s;
    }
    return {};
}

} // namespace fieldsight
