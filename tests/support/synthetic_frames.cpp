// Small synthetic frames with known answers for the core tests.
#include "support/synthetic_frames.h"

#include <opencv2/imgproc.hpp>

#include <filesystem>

namespace fieldsight::test {

ClassPixel pixelFor(Colour colour)
{
    switch (colour) {
    case Colour::White:
        return {230, 128, 128};
    case Colour::Green:
        return {100, 90, 80};
    case Colour::Orange:
        return {140, 70, 200};
    case Colour::Yellow:
        return {190, 40, 150};
    case Colour::Blue:
        return {60, 200, 90};
    case Colour::Pink:
        return {120, 150, 210};
    case Colour::ShadowObject:
        return {40, 128, 128};
    default:
        return {10, 10, 10};
    }
}

ColourLut testLut()
{
    ColourLut lut;
    for (int c = 1; c < kColourCount; ++c) {
        const ClassPixel p = pixelFor(Colour(c));
        if (p.y == 10 && p.cb == 10)
            continue;
        for (int dy = -4; dy <= 4; dy += 2)
            for (int db = -4; db <= 4; db += 2)
                for (int dr = -4; dr <= 4; dr += 2)
                    lut.setCell(ColourLut::index(std::uint8_t(p.y + dy), std::uint8_t(p.cb + db),
                                                 std::uint8_t(p.cr + dr)),
                                Colour(c));
    }
    return lut;
}

static cv::Scalar scalarFor(Colour colour)
{
    const ClassPixel p = pixelFor(colour);
    return cv::Scalar(p.y, p.cb, p.cr);
}

cv::Mat filledFrame(int width, int height, Colour colour)
{
    return cv::Mat(height, width, CV_8UC3, scalarFor(colour));
}

void fillRect(cv::Mat& frame, int left, int top, int right, int bottom, Colour colour)
{
    cv::rectangle(frame, cv::Point(left, top), cv::Point(right, bottom), scalarFor(colour),
                  cv::FILLED);
}

void fillCircle(cv::Mat& frame, double cx, double cy, double radius, Colour colour)
{
    // Sub-pixel accurate disc: 4 fractional bits.
    cv::circle(frame, cv::Point(int(cx * 16 + 0.5), int(cy * 16 + 0.5)), int(radius * 16 + 0.5),
               scalarFor(colour), cv::FILLED, cv::LINE_8, 4);
}

void drawLine(cv::Mat& frame, int x1, int y1, int x2, int y2, int thickness, Colour colour)
{
    cv::line(frame, cv::Point(x1, y1), cv::Point(x2, y2), scalarFor(colour), thickness);
}

std::string referenceDataDir()
{
    const std::filesystem::path dir =
        std::filesystem::path(FIELDSIGHT_SHARED_DIR) / "reference_data";
    return std::filesystem::is_directory(dir) ? dir.string() : std::string();
}

std::string sampleStreamsDir()
{
    return FIELDSIGHT_SAMPLE_STREAMS_DIR;
}

std::string bigEndian32(std::uint32_t v)
{
    return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

std::string pngChunk(const std::string& type, const std::string& data)
{
    const std::string body = type + data;
    std::uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char b : body) {
        crc ^= b;
        for (int k = 0; k < 8; ++k)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return bigEndian32(std::uint32_t(data.size())) + body + bigEndian32(crc ^ 0xFFFFFFFFu);
}

std::string pngHeaderClaiming(std::uint32_t width, std::uint32_t height)
{
    return std::string("\x89PNG\r\n\x1a\n", 8) +
           pngChunk("IHDR", bigEndian32(width) + bigEndian32(height) +
                                std::string("\x08\x02\x00\x00\x00", 5));
}

} // namespace fieldsight::test
