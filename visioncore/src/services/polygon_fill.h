// A polygon's pixels in time linear in its points and the area it spans (cv::fillPoly keeps its
// edges in a list sorted again on every row: a sample polygon of 200k points took 50 s to over
// ten minutes).
#pragma once

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <vector>

namespace fieldsight {

/// Sets to `value` every pixel of `image` (CV_8U) that `polygon` covers: its inside by the
/// even-odd rule and its outline, exactly the pixels of cv::fillPoly followed by cv::polylines
/// (OpenCV 4.6, 8-connected), inside the image and across its border (test_polygon_fill compares
/// them on thousands of random polygons). Time: the points, plus the polygon's bounding box
/// within the image, plus for each edge the smaller of its width and height within the image
/// (each edge is cut into the runs of rows or columns over which it does not change). Vertices
/// further than 2^24 px out are first moved to that distance.
void fillPolygon(cv::Mat& image, const std::vector<cv::Point>& polygon, std::uint8_t value);

} // namespace fieldsight
