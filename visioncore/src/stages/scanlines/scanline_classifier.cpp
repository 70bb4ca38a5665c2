// Scanline classification: the hot loop of the pipeline (every LUT lookup the system makes).
#include "stages/scanlines/scanline_classifier.h"

#include "stages/common/stage_util.h"
#include "visioncore/framework/blackboard.h"

#include <algorithm>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <cmath>

namespace fieldsight {

namespace {

/// Run-length encodes `count` pixels starting at `px`, `stride` bytes apart, into `scan`. Segment
/// ends are exclusive; `x0,y0` is the first pixel and (dx, dy) the step. Three tight passes: the
/// lookups alone into `classes` (branch-free, as fast as the lookups can be), the positions where
/// the class changes (found 16 at a time) into `ends`, then the segments, written by index.
void classifyLine(const ColourLut& lut, const std::uint8_t* px, std::ptrdiff_t stride, int count,
                  int x0, int y0, int dx, int dy, ScanlineBuffers& buffers, Scan& scan)
{
    if (count <= 0)
        return;
    if (buffers.classes.size() < std::size_t(count) + 16) {
        buffers.classes.resize(std::size_t(count) + 16);
        buffers.ends.resize(std::size_t(count) + 1);
    }
    std::uint8_t* c = buffers.classes.data();
    lut.classifyRun(px, stride, count, c);

    int* ends = buffers.ends.data();
    int n = 0;
    int i = 1;
#if defined(__SSE2__)
    for (; i + 16 <= count; i += 16) {
        const __m128i here = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + i));
        const __m128i before = _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + i - 1));
        unsigned changes = ~unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(here, before))) & 0xFFFFu;
        while (changes) {
            ends[n++] = i + __builtin_ctz(changes);
            changes &= changes - 1;
        }
    }
#endif
    for (; i < count; ++i) {
        ends[n] = i;
        n += c[i] != c[i - 1];
    }
    ends[n++] = count;

    scan.resize(std::size_t(n));
    ColourSegment* out = scan.data();
    int start = 0;
    for (int k = 0; k < n; ++k) {
        const int end = ends[k];
        out[k] = {std::int16_t(x0 + start * dx), std::int16_t(y0 + start * dy),
                  std::int16_t(x0 + end * dx), std::int16_t(y0 + end * dy), Colour(c[start])};
        start = end;
    }
}

} // namespace

const StageInfo& ScanlineClassifier::info() const
{
    static const StageInfo info{
        "scanlines",
        "Scanline classifier",
        "Classifies the pixels along horizontal and vertical scan lines through the LUT into runs "
        "of one colour (segments).",
        false,
        {"image", "lut", "green_horizon"},
        {"scan_lines", "segments"},
        {},
        {{"scanlines.horizontal", "Horizontal scan lines", debug_colour::kGrey},
         {"scanlines.vertical", "Vertical scan lines", debug_colour::kGrey},
         {"scanlines.segments", "Segments", {}, true}}};
    return info;
}

void ScanlineClassifier::run(Blackboard& bb)
{
    const cv::Mat& image = bb.image();
    const int w = image.cols;
    const int h = image.rows;
    const ColourLut& lut = bb.lut();
    const int hs = m_horizontal_spacing;
    const int vs = m_vertical_spacing;

    // Horizontal lines cover the whole image (goalposts rise above the green horizon), from the
    // bottom row up, as in the original.
    for (int y = h - 1; y >= 0; y -= hs) {
        bb.horizontal_scan_ys.push_back(y);
        classifyLine(lut, image.ptr<std::uint8_t>(y), 3, w, 0, y, 1, 0, m_buffers,
                     bb.horizontal_segments.addScan());
    }
    // Vertical lines only below the green horizon.
    const std::ptrdiff_t step = std::ptrdiff_t(image.step[0]);
    for (int x = 0; x < w; x += vs) {
        const int y0 = bb.green_horizon.yAt(x);
        bb.vertical_scan_starts.push_back({x, y0});
        classifyLine(lut, image.ptr<std::uint8_t>(y0) + 3 * x, step, h - y0, x, y0, 0, 1, m_buffers,
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
