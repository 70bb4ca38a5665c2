// The ideal LUT for a generated stream, voted from the renderer's own pixel labels.
//
// Votes come from "core" pixels only: every supersample of every pixel within `kCoreMargin` px
// saw the same class, so blur and 4:2:2 chroma cannot have mixed two classes into the vote. Each
// touched 128^3 cell takes its plurality label if that has >= kMinVotes votes and beats the
// runner-up; otherwise (a tie) it stays unclassified. A single vote counts: core pixels are
// certain, and rare colours (a ball in a dark corner) would otherwise never be learnt. Then every
// class grows by one cell (6-neighbourhood) into cells that no background majority claimed, so
// colours just outside the training set still classify. Background (walls, people, floor) votes
// "unclassified", so its cells stay unclassified.
#pragma once

#include "visioncore/basics/colour.h"
#include "visioncore/basics/colour_lut.h"

#include <opencv2/core/mat.hpp>

#include <array>
#include <cstdint>
#include <unordered_map>

namespace fieldsight::synth {

class IdealLutBuilder
{
public:
    static constexpr int kCoreMargin = 1;
    static constexpr std::uint32_t kMinVotes = 1;

    /// `ycbcr` CV_8UC3 (Y, Cb, Cr), `labels` CV_8U from the renderer.
    void addFrame(const cv::Mat& ycbcr, const cv::Mat& labels);
    ColourLut build() const;

    /// Pixels whose whole (2 margin + 1)^2 neighbourhood carries one, unmixed, label.
    static cv::Mat coreMask(const cv::Mat& labels, int margin = kCoreMargin);

private:
    std::unordered_map<std::uint32_t, std::array<std::uint32_t, kColourCount>> m_votes;
};

} // namespace fieldsight::synth
