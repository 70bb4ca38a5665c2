// The ideal LUT for a generated stream, voted from the renderer's own pixel labels.
#include "synth/ideal_lut.h"

#include "synth/renderer.h"

#include <vector>

namespace fieldsight::synth {

namespace {
constexpr int kLumaCells = 6; ///< 12 levels of Y
} // namespace

cv::Mat IdealLutBuilder::coreMask(const cv::Mat& labels, int margin)
{
    cv::Mat core(labels.rows, labels.cols, CV_8U, cv::Scalar(0));
    for (int y = margin; y < labels.rows - margin; ++y) {
        for (int x = margin; x < labels.cols - margin; ++x) {
            const std::uint8_t l = labels.at<std::uint8_t>(y, x);
            if (l == kMixedLabel)
                continue;
            bool uniform = true;
            for (int dy = -margin; dy <= margin && uniform; ++dy)
                for (int dx = -margin; dx <= margin && uniform; ++dx)
                    uniform = labels.at<std::uint8_t>(y + dy, x + dx) == l;
            core.at<std::uint8_t>(y, x) = uniform ? 1 : 0;
        }
    }
    return core;
}

void IdealLutBuilder::addFrame(const cv::Mat& ycbcr, const cv::Mat& labels)
{
    const cv::Mat core = coreMask(labels);
    for (int y = 0; y < ycbcr.rows; ++y) {
        for (int x = 0; x < ycbcr.cols; ++x) {
            if (!core.at<std::uint8_t>(y, x))
                continue;
            const cv::Vec3b p = ycbcr.at<cv::Vec3b>(y, x);
            const auto cell = std::uint32_t(ColourLut::index(p[0], p[1], p[2]));
            auto [it, inserted] = m_votes.try_emplace(cell);
            if (inserted)
                it->second.fill(0);
            ++it->second[labels.at<std::uint8_t>(y, x)];
        }
    }
}

ColourLut IdealLutBuilder::build() const
{
    // 0: no decision, 1: decided (including "unclassified" by a background majority).
    std::vector<std::uint8_t> decided(ColourLut::kCells, 0);
    ColourLut lut;
    for (const auto& [cell, votes] : m_votes) {
        int best = 0;
        std::uint32_t best_votes = 0;
        std::uint32_t runner_up = 0;
        for (int c = 0; c < kColourCount; ++c) {
            if (votes[std::size_t(c)] > best_votes) {
                runner_up = best_votes;
                best_votes = votes[std::size_t(c)];
                best = c;
            } else if (votes[std::size_t(c)] > runner_up) {
                runner_up = votes[std::size_t(c)];
            }
        }
        if (best_votes < kMinVotes || best_votes == runner_up)
            continue;
        decided[cell] = 1;
        lut.setCell(cell, Colour(best));
    }

    // One-cell dilation, read from the voted table so it grows by exactly one cell.
    const ColourLut voted = lut;
    for (int y = 0; y < 128; ++y) {
        for (int b = 0; b < 128; ++b) {
            for (int r = 0; r < 128; ++r) {
                const std::size_t cell =
                    std::size_t(y) << 14 | std::size_t(b) << 7 | std::size_t(r);
                if (decided[cell])
                    continue;
                // Most cells have no coloured neighbour: a quick look before counting them.
                const std::uint8_t* v = voted.data();
                if ((y == 0 || !v[cell - (1u << 14)]) && (y == 127 || !v[cell + (1u << 14)]) &&
                    (b == 0 || !v[cell - (1u << 7)]) && (b == 127 || !v[cell + (1u << 7)]) &&
                    (r == 0 || !v[cell - 1]) && (r == 127 || !v[cell + 1]))
                    continue;
                std::array<int, kColourCount> count{};
                auto look = [&](int yy, int bb, int rr) {
                    if (yy < 0 || bb < 0 || rr < 0 || yy > 127 || bb > 127 || rr > 127)
                        return;
                    const std::size_t n =
                        std::size_t(yy) << 14 | std::size_t(bb) << 7 | std::size_t(rr);
                    const int c = int(voted.cell(n));
                    if (c != 0)
                        ++count[std::size_t(c)];
                };
                look(y - 1, b, r);
                look(y + 1, b, r);
                look(y, b - 1, r);
                look(y, b + 1, r);
                look(y, b, r - 1);
                look(y, b, r + 1);
                int best = 0;
                int best_count = 0;
                bool tie = false;
                for (int c = 1; c < kColourCount; ++c) {
                    if (count[std::size_t(c)] > best_count) {
                        best = c;
                        best_count = count[std::size_t(c)];
                        tie = false;
                    } else if (count[std::size_t(c)] == best_count && best_count > 0) {
                        tie = true;
                    }
                }
                if (best_count > 0 && !tie)
                    lut.setCell(cell, Colour(best));
            }
        }
    }

    // Green, and the ball and goal colours, also grow along Y (brightness) by kLumaCells: blends
    // of carpet with a thin far line, the shaded side of a post or ball, and lamp spots change
    // brightness, not hue, and a person building a LUT at a venue clicks those pixels too. Cells
    // the background won stay as they are.
    const ColourLut grown = lut;
    for (std::size_t cell = 0; cell < ColourLut::kCells; ++cell) {
        if (decided[cell] || grown.cell(cell) != Colour::Unclassified)
            continue;
        const int y = int(cell >> 14);
        for (int d = -kLumaCells; d <= kLumaCells; ++d) {
            const int yy = y + d;
            if (yy < 0 || yy > 127)
                continue;
            const std::size_t n = (std::size_t(yy) << 14) | (cell & 0x3FFF);
            const Colour c = grown.cell(n);
            if ((c == Colour::Green || c == Colour::Yellow || c == Colour::Orange) &&
                voted.cell(n) == c) {
                lut.setCell(cell, c);
                break;
            }
        }
    }
    return lut;
}

} // namespace fieldsight::synth
