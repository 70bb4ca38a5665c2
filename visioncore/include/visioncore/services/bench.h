// The benchmark behind `fieldsight bench`: ms per frame as in the paper's Table 1, next to two
// references measured on the same frames in the same run: the LUT lookups the scan lines need (a
// floor for any scan-line design) and a full-frame classification with OpenCV connected
// components (a common baseline).
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/basics/geometry.h"
#include "visioncore/basics/result.h"
#include "visioncore/services/stream_runner.h"

#include <opencv2/core/mat.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace fieldsight {

struct BenchOptions
{
    int repeat = 1;        ///< passes over the stream
    int threads = 1;       ///< 0: one per core
    std::size_t limit = 0; ///< only the first `limit` frames; 0: all
};

/// Streams with fewer frames than this are decoded once and kept in memory for all passes.
inline constexpr std::size_t kBenchInMemoryFrames = 2000;

struct BenchResults
{
    std::string stream;
    std::string lut_path;
    int width = 0;  ///< px
    int height = 0; ///< px
    std::size_t frames = 0;
    int repeat = 1;
    int threads = 1;
    bool in_memory = false;
    TimingStats pipeline; ///< ControlWrapper::runFrame, wall clock
    std::vector<std::pair<std::string, TimingStats>> stages; ///< pipeline order, runs only
    /// Only the LUT lookups of the pixels the scan lines touch (a lower bound for any scan-line
    /// design on these frames).
    TimingStats floor;
    double floor_pixels_per_frame = 0;
    /// Every pixel through the LUT into a class image, then OpenCV connected components of the
    /// ball and goal classes (what one would write without scan lines).
    TimingStats baseline;
};

/// Several streams benched with the same options, laid out as the paper's Table 1: one row per
/// stream and a combined row over all frames of all streams.
struct MultiBenchResults
{
    std::vector<std::string> names;    ///< row labels (benchStreamName), in the order given
    std::vector<BenchResults> streams; ///< same order as names
    /// Every run of every stream pooled (TimingStats::pooled), per stage too; frames is the sum,
    /// stream and lut are empty, width and height are 0 unless all streams share a size.
    BenchResults combined;
};

/// Times the pipeline of `input` (its LUT and parameters) on its first frames, `options.threads`
/// cores side by side, each frame followed by the two references. A frame that cannot be read or
/// parameters the pipeline refuses are an Error; a frame the pipeline fails on, or an exception,
/// is thrown as std::runtime_error naming the stream.
Result<BenchResults> runBench(StreamInput& input, const BenchOptions& options);

/// The floor: only the lookups of the pixels the pipeline's scan lines touch (full-width rows at
/// `rows`, and columns from each start down to the bottom), through the scan lines' own lookup
/// loop. Returns a checksum of the classes so the work cannot be optimised away; `pixels`
/// receives the number of lookups.
std::uint32_t floorLookups(const cv::Mat& image, const ColourLut& lut, const std::vector<int>& rows,
                           const std::vector<PixelPoint>& starts,
                           std::vector<std::uint8_t>& classes, std::size_t& pixels);

/// What fullFrameBaseline allocates, kept from frame to frame.
struct BaselineBuffers
{
    cv::Mat classes, mask, labels, stats, centroids;
};

/// The baseline: a class image of the whole frame, then for the ball (orange) and goal (yellow)
/// classes a mask and connected components, keeping the largest blob. Returns a checksum.
std::uint32_t fullFrameBaseline(const cv::Mat& image, const ColourLut& lut, BaselineBuffers& b);

/// A stream's row label: its folder or file name ("camera:N" as given).
std::string benchStreamName(const std::string& stream);

/// The results of `streams` (in that order) as one table: names that two streams share (or
/// "combined") are replaced by the stream as given, and the combined row pools every run.
MultiBenchResults combineBenches(const std::vector<std::string>& streams,
                                 std::vector<BenchResults> results);

} // namespace fieldsight
