// Turning pictures and their horizons upright.
#include "visioncore/io/orientation.h"

#include <opencv2/core.hpp>

namespace fieldsight {

std::optional<Orientation> orientationFromDegrees(long long degrees)
{
    switch (degrees) {
    case 0:
        return Orientation::Upright;
    case 90:
        return Orientation::Clockwise90;
    case 180:
        return Orientation::Half;
    case 270:
        return Orientation::Clockwise270;
    default:
        return std::nullopt;
    }
}

std::string orientationText(Orientation o)
{
    return std::to_string(degrees(o));
}

void orientImage(const cv::Mat& in, cv::Mat& out, Orientation o)
{
    switch (o) {
    case Orientation::Upright:
        if (in.data != out.data)
            in.copyTo(out);
        return;
    case Orientation::Clockwise90:
        cv::rotate(in, out, cv::ROTATE_90_CLOCKWISE);
        return;
    case Orientation::Half:
        cv::rotate(in, out, cv::ROTATE_180);
        return;
    case Orientation::Clockwise270:
        cv::rotate(in, out, cv::ROTATE_90_COUNTERCLOCKWISE);
        return;
    }
}

std::optional<Horizon> orientHorizon(const Horizon& horizon, Orientation o, int height)
{
    switch (o) {
    case Orientation::Upright:
        return horizon;
    case Orientation::Half:
        // (x, y) goes to (width-1-x, height-1-y): the right end becomes the left one.
        return Horizon{double(height - 1) - horizon.y_right, double(height - 1) - horizon.y_left};
    case Orientation::Clockwise90:
    case Orientation::Clockwise270:
        return std::nullopt;
    }
    return std::nullopt;
}

} // namespace fieldsight
