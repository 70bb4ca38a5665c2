// Building a colour LUT from samples (issue 9): regions of frames marked with a colour class, by
// hand or from a stream's annotations, voted into the table's cells and smoothed into their
// neighbours. The samples are a file (fieldsight-lut-samples/1) kept beside the stream, so the
// table can be rebuilt after the light changes. Shared by `fieldsight lut build` and the GUI.
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/io/annotations.h"
#include "visioncore/io/stream_reader.h"
#include "visioncore/basics/result.h"

#include <opencv2/core/types.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace fieldsight {

/// A region of one frame whose pixels show one colour class. Within a frame, samples are painted
/// in order: where two overlap, the later one decides what a pixel votes for, and a pixel votes
/// once.
struct LutSample
{
    std::string frame; ///< the frame's name in the stream, matched by frameStem()
    Colour colour = Colour::Unclassified; ///< Unclassified: background, which votes against classes
    std::vector<cv::Point> polygon;       ///< px, >= 3 vertices; edges and vertices are inside
    bool exclude = false; ///< a hole: its pixels vote for nothing (`colour` is ignored)
    /// The sample's keys this version does not read, as the text of a JSON object ("" none):
    /// written back after the known ones.
    std::string unknown = {};
};

/// The contents of a samples file.
struct LutSamples
{
    int smoothing = 1; ///< cells, the smoothing the table was (or is to be) built with
    std::vector<LutSample> samples;
    /// The file's top-level keys this version does not read, as the text of a JSON object (""
    /// none): written back after "samples".
    std::string unknown = {};
};

inline constexpr const char* kLutSamplesFormat = "fieldsight-lut-samples/1";
/// The samples file kept beside a stream (in its folder, or the folder holding the file).
std::string defaultLutSamplesPath(const std::string& stream);

/// Reads fieldsight-lut-samples/1:
///
///     {"format": "fieldsight-lut-samples/1", "smoothing": 1,
///      "samples": [{"frame": "frame_000000.png", "colour": "orange",
///                   "polygon": [[x, y], ...]},
///                  {"frame": "frame_000000.png", "exclude": true, "polygon": [...]}]}
///
/// Errors name `source` and the problem (the sample's index and field).
Result<LutSamples> lutSamplesFromJson(const std::string& text, const std::string& source);
/// The largest samples file read for a stream of `frames` frames (0: not known): 16 MiB and
/// 4 KiB a frame. A sample drawn by hand is a few points; those made from a frame's annotations
/// take 1 to 3 KB.
std::size_t maxLutSamplesBytes(std::size_t frames);
/// Reads a samples file; one over maxLutSamplesBytes(`frames`) is refused unread, and running
/// out of memory is an Error naming the file.
Result<LutSamples> loadLutSamples(const std::string& path, std::size_t frames = 0);
std::string lutSamplesToJson(const LutSamples& samples);
Status saveLutSamples(const std::string& path, const LutSamples& samples); ///< atomic

/// How annotations (SPEC §5.2) become samples. Regions are pulled in from their edges by
/// `shrink_px` so that pixels blended with what surrounds them do not vote.
struct AnnotationSampleRules
{
    Colour goal_colour = Colour::Yellow;
    double shrink_px = 1;       ///< px, off balls' radii, posts' sides and the field boundary
    double line_half_width = 1; ///< px, of the strip sampled along each field line
    bool background = true;     ///< above the field boundary votes unclassified
    /// What obstacles' boxes vote for: unclassified (robots and people are no class, and their
    /// colours must not become white or green), a class of their own (shadow_object), or
    /// nothing (a hole in the field's green).
    std::optional<Colour> obstacle_colour = Colour::Unclassified;
    /// Balls, posts and lines, grown by shrink_px, are holes in the green too (their shrunk
    /// regions are sampled over them), so their blended rims vote for nothing.
    bool objects_out = true;
};

/// The samples of every done frame of `annotations`, in `frame_size` images, painted in this
/// order (later wins): above the boundary unclassified (with `background`), the field below it
/// green, the rows around a post's top left out (the unannotated crossbar is goal-coloured),
/// obstacles, field lines white, goalposts `goal_colour`, balls orange; a concealed object's
/// outline votes for nothing (it holds the pixels of what hides it). Frames without a boundary
/// give no background or green.
std::vector<LutSample> samplesFromAnnotations(const Annotations& annotations, cv::Size frame_size,
                                              const AnnotationSampleRules& rules = {});

/// How votes become a table.
struct LutBuildOptions
{
    /// Cells: every cell's votes also count in the cells up to this far in Y, Cb and Cr, with
    /// weight 2^-|d| per channel (so a face neighbour 1/2, an edge 1/4, a corner 1/8). 0: none.
    int smoothing = 1;
    /// The weight a class needs to take a cell (one vote in the cell itself weighs 1): by default
    /// two, so a lone noisy pixel takes no cells, while four votes next door (or 16 at a corner)
    /// do. Measured on the bundled streams: 0.5 gave fewer goalposts in lab1 and difficult.
    double min_weight = 2;
    /// Where orange and pink (or yellow) are both strong, the soft class pink_orange
    /// (yellow_orange) instead of the winner.
    bool soft = false;
    /// Two classes are "both strong" when the runner-up has at least this share of the winner.
    double ambiguity_ratio = 0.5;
};

/// A cell that two classes' samples both claim.
struct AmbiguousCell
{
    std::uint32_t cell = 0;
    Colour winner = Colour::Unclassified;
    Colour runner_up = Colour::Unclassified;
    float winner_weight = 0;
    float runner_up_weight = 0;
};

/// Votes per (cell, class), for the cells that have any.
class LutVotes
{
public:
    using Counts = std::array<std::uint32_t, kColourCount>;

    /// Adds the votes of the pixels of `samples` in a CV_8UC3 Y, Cb, Cr frame (their frame names
    /// are not checked); pixels outside the frame are ignored. Returns the pixels that voted.
    std::size_t addFrame(const cv::Mat& ycbcr, const std::vector<const LutSample*>& samples);
    void add(std::uint32_t cell, Colour colour, std::uint32_t votes = 1);

    std::size_t pixels() const { return m_pixels; } ///< votes cast
    const std::unordered_map<std::uint32_t, Counts>& cells() const { return m_votes; }

    /// The table: each cell the class with the most smoothed weight, if that is at least
    /// min_weight and more than any other (background included); else unclassified.
    ColourLut build(const LutBuildOptions& options = {}) const;
    /// The cells whose runner-up class (unclassified background included) has at least
    /// ambiguity_ratio of the winner's smoothed weight, ascending by cell.
    std::vector<AmbiguousCell> ambiguousCells(const LutBuildOptions& options = {}) const;

private:
    std::unordered_map<std::uint32_t, Counts> m_votes;
    std::size_t m_pixels = 0;
};

/// Called after every frame; returning false cancels.
using LutBuildProgress = std::function<bool(std::size_t done, std::size_t total)>;

struct LutVoteRun
{
    LutVotes votes;
    std::size_t frames = 0; ///< frames read
    bool cancelled = false; ///< frames were left unread; `votes` holds those read before
};

/// Reads every frame of `reader` that a sample names (by frameStem(), in stream order) and adds
/// its samples' votes. A sample naming a frame the stream lacks is bad input.
Result<LutVoteRun> collectLutVotes(StreamReader& reader, const std::vector<LutSample>& samples,
                                   const LutBuildProgress& progress = {});

} // namespace fieldsight
