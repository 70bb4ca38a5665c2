// Scanline classification: the hot loop of the pipeline (every LUT lookup the system makes).
#include "stages/scanlines/scanline_classifier.h"

#include "stages/common/stage_util.h"
#include "visioncore/blackboard.h"

#include <algorithm>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <cmath>

namespace fieldsight {

namespace {

/// The lookups alone. `__restrict`: the class bytes written never alias the pixels or the LUT, so
/// the compiler need not reload them after every store (uint8_t pointers may alias anything).
void lookupRun(const std::uint8_t* __restrict lut, const std::uint8_t* __restrict px,
               std::ptrdiff_t stride, int count, std::uint8_t* __restrict c)
{
    for (int i = 0; i < count; ++i, px += stride)
        c[i] = lut[ColourLut::index(px[0], px[1], px[2])];
}

/// Run-length encodes `count` pixels starting at `px`, `stride` bytes apart, into `scan`. Segment
/// ends are exclusive; `x0,y0` is the first pixel and (dx, dy) the step. Two passes: the lookups
/// alone into `classes` (branch-free, as fast as the lookups can be), then the class changes,
/// found 16 at a time.
void classifyLine(const std::uint8_t* lut, const std::uint8_t* px, std::ptrdiff_t stride, int count,
                  int x0, int y0, int dx, int dy, std::vector<std::uint8_t>& classes, Scan& scan)
{
    if (count <= 0)
        return;
    if (classes.size() < std::size_t(count) + 16)
        classes.resize(std::size_t(count) + 16);
    std::uint8_t* c = classes.data();
    lookupRun(lut, px, stride, count, c);

    int start = 0;
    const auto emit = [&](int end) {
        scan.push_back({std::int16_t(x0 + start * dx), std::int16_t(y0 + start * dy),
                        std::int16_t(x0 + end * dx), std::int16_t(y0 + end * dy),
                        Colour(c[start])});
        start = end;
    };
    int i = 1;
#if defined(__SSE2__)
    for (; i + 16 <= count; i += 16) {
        const __m128i here = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + i));
        const __m128i before = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + i - 1));
        unsigned changes = ~unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(here, before))) & 0xFFFFu;
        while (changes) {
            emit(i + __builtin_ctz(changes));
            changes &= changes - 1;
        }
    }
#endif
    for (; i < count; ++i)
        if (c[i] != c[i - 1])
            emit(i);
    emit(count);
}

} // namespace

ScanlineClassifier::ScanlineClassifier()
{
    addParam(m_horizontal_spacing,
             {"horizontal_spacing", "px", "rows between horizontal scan lines", 4, 1, 64});
    addParam(m_vertical_spacing,
             {"vertical_spacing", "px", "columns between vertical scan lines", 4, 1, 64});
}

const StageInfo& ScanlineClassifier::info() const
{
    static const StageInfo info{
        "scanlines",
        "Scanline classifier",
        false,
        {"image", "lut", "green_horizon"},
        {"horizontal_scan_ys", "vertical_scan_starts", "horizontal_segments", "vertical_segments"},
        {{"scanlines.horizontal", "Horizontal scan lines"},
         {"scanlines.vertical", "Vertical scan lines"},
         {"scanlines.segments", "Segments"}}};
    return info;
}

void ScanlineClassifier::run(Blackboard& bb)
{
    const cv::Mat& image = bb.image();
    const int w = image.cols;
    const int h = image.rows;
    const std::uint8_t* lut = bb.lut().data();
    const int hs = std::max(1, int(std::lround(m_horizontal_spacing)));
    const int vs = std::max(1, int(std::lround(m_vertical_spacing)));

    // Horizontal lines cover the whole image (goalposts rise above the green horizon), from the
    // bottom row up, as in the original.
    for (int y = h - 1; y >= 0; y -= hs) {
        bb.horizontal_scan_ys.push_back(y);
        classifyLine(lut, image.ptr<std::uint8_t>(y), 3, w, 0, y, 1, 0, m_classes,
                     bb.horizontal_segments.addScan());
    }
    // Vertical lines only below the green horizon.
    const std::ptrdiff_t step = std::ptrdiff_t(image.step[0]);
    for (int x = 0; x < w; x += vs) {
        const int y0 = bb.green_horizon.yAt(x);
        bb.vertical_scan_starts.push_back({x, y0});
        classifyLine(lut, image.ptr<std::uint8_t>(y0) + 3 * x, step, h - y0, x, y0, 0, 1, m_classes,
                     bb.vertical_segments.addScan());
    }

    if (auto* d = bb.debug.layer("scanlines.horizontal"))
        for (int y : bb.horizontal_scan_ys)
            d->add(lineShape({0, double(y)}, {double(w - 1), double(y)}, debug_colour::kGrey));
    if (auto* d = bb.debug.layer("scanlines.vertical"))
        for (const PixelPoint& p : bb.vertical_scan_starts)
            d->add(lineShape({double(p.x), double(p.y)}, {double(p.x), double(h - 1)},
                             debug_colour::kGrey));
    if (auto* d = bb.debug.layer("scanlines.segments")) {
        for (const SegmentedRegion* region : {&bb.horizontal_segments, &bb.vertical_segments})
            for (std::size_t i = 0; i < region->size(); ++i)
                for (const ColourSegment& s : (*region)[i]) {
                    const PixelPoint last = s.last();
                    d->add(lineShape({double(s.x0), double(s.y0)}, {double(last.x), double(last.y)},
                                     colourDisplayRgb(s.colour)));
                }
    }
}

} // namespace fieldsight
