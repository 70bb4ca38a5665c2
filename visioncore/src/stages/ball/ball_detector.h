// Ball (design note §2.7, fixed): the edge points of ball-coloured transitions below the green
// horizon are clustered and a circle is fitted to the largest cluster by RANSAC.
#pragma once

#include "stages/common/stage_util.h"
#include "visioncore/framework/stage.h"
#include "visioncore/basics/segments.h"

#include <cstdint>
#include <vector>

namespace fieldsight {

class BallDetector : public Stage
{
public:
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    // Per-frame scratch, kept so a frame allocates nothing once they have grown.
    std::vector<PointF> m_edges;
    std::vector<const ColourSegment*> m_chords;
    std::vector<std::size_t> m_parent; ///< the clustering's union-find
    std::vector<int> m_slot;

    Param<double> m_min_radius{
        this, 2.5, {"min_radius", "px", 0, 100, 0.5, "Balls with a smaller radius are ignored."}};
    Param<double> m_min_orange_fraction{
        this,
        0.2,
        {"min_orange_fraction", "", 0, 1, 0.05,
         "Share of ball-coloured pixels needed inside a fitted circle."}};
    Param<double> m_cluster_distance{
        this,
        10,
        {"cluster_distance", "px", 1, 100, 1,
         "Edge points closer than this are taken to belong to the same ball."}};
    Param<double> m_max_fit_error{
        this,
        1.5,
        {"max_fit_error", "px", 0.1, 20, 0.1, "How far an edge point may lie from the circle."}};
    Param<int> m_iterations{
        this, 100, {"iterations", "", 1, 10000, 1, "Circle RANSAC samples, at most."}};
    Param<double> m_min_edge_support{
        this,
        0.25,
        {"min_edge_support", "", 0, 1, 0.05,
         "A partly hidden ball needs this share of the edge points its outline would give the "
         "scan lines."}};
    Param<std::uint32_t> m_seed{this, 1, kRansacSeed};
};

} // namespace fieldsight
