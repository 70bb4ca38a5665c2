// Small synthetic frames with known answers for the core tests, and the test-data paths.
#pragma once

#include "visioncore/basics/colour_lut.h"

#include <opencv2/core/mat.hpp>

#include <string>

namespace fieldsight::test {

/// YCbCr triples that the test LUT maps to each class (one per class, well apart).
struct ClassPixel
{
    unsigned char y, cb, cr;
};
ClassPixel pixelFor(Colour colour);

/// A LUT that maps exactly the cells of pixelFor(c) (and their 7-bit neighbourhood) to c.
ColourLut testLut();

/// A width x height frame filled with `colour`'s pixel.
cv::Mat filledFrame(int width, int height, Colour colour);
void fillRect(cv::Mat& frame, int left, int top, int right, int bottom, Colour colour);
void fillCircle(cv::Mat& frame, double cx, double cy, double radius, Colour colour);
void drawLine(cv::Mat& frame, int x1, int y1, int x2, int y2, int thickness, Colour colour);

/// ../shared/reference_data, or an empty string when it is absent (tests then QSKIP).
std::string referenceDataDir();
std::string sampleStreamsDir();

/// A PNG signature and an IHDR chunk (with a correct checksum) claiming width x height, and no
/// pixel data: a small file promising a huge image.
std::string pngHeaderClaiming(std::uint32_t width, std::uint32_t height);
/// A PNG chunk: its length, `type`, `data` and a correct checksum (to build damaged PNGs that
/// only a decoder can tell are damaged).
std::string pngChunk(const std::string& type, const std::string& data);
/// `v` as 4 big-endian bytes, as PNG stores numbers.
std::string bigEndian32(std::uint32_t v);

} // namespace fieldsight::test
