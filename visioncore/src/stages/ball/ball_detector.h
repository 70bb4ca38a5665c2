// Ball (design note §2.7, fixed): the edge points of ball-coloured transitions below the green
// horizon are clustered and a circle is fitted to the largest cluster by RANSAC.
#pragma once

#include "stages/common/stage_util.h"
#include "visioncore/framework/stage.h"
#include "visioncore/basics/segments.h"

#include <cstdint>
#include <string>
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

    /// Whether `centre`, `radius` cannot be the ball, by size, place and colour; `why`, when
    /// given, is set to the reason (for the rejected layer).
    bool rejects(const Blackboard& bb, PointF centre, double radius, Colour colour,
                 std::string* why) const;

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
        this, 100, {"iterations", "", 1, 10000, 1, "Circle RANSAC samples, at most.", true, +1}};
    Param<double> m_min_edge_support{
        this,
        0.25,
        {"min_edge_support", "", 0, 1, 0.05,
         "A partly hidden ball needs this share of the edge points its outline would give the "
         "scan lines."}};
    Param<double> m_max_radius{
        this,
        0.5,
        {"max_radius", "", 0.05, 2, 0.05,
         "Largest radius as a share of the image height; a ball's centre must also lie in the "
         "image."}};
    Param<double> m_min_diameter_balance{
        this,
        0.5,
        {"min_diameter_balance", "", 0, 1, 0.05,
         "How far the ball colour must reach across the vertical diameter against across the "
         "horizontal one, or the inverse: a ball is a disc, a rim or a highlight band on a "
         "robot's arm or foot is thin one way (0: off)."}};
    Param<double> m_min_field_around{
        this,
        0.1,
        {"min_field_around", "", 0, 1, 0.05,
         "Share of carpet or line pixels needed on two rings just outside a ball (those in the "
         "image): a ball lies on the field, not inside a robot's red arm."}};
    Param<double> m_max_chord_spacings{
        this,
        3,
        {"max_chord_spacings", "", 0, 20, 0.5,
         "A ball found by one run alone (too small for three edge points) is at most this many "
         "scan line spacings wide (0: any width)."}};
    Param<double> m_focal_length{
        this,
        0,
        {"focal_length", "px", 0, 5000, 1,
         "The camera's focal length. With a kinematic horizon it sets the radius a ball may have "
         "where it stands (0: no size rule)."}};
    Param<double> m_radius_at_nadir{
        this,
        40,
        {"radius_at_nadir", "px", 1, 1000, 1,
         "A ball's radius straight below the camera (focal length x ball radius / (camera height - "
         "ball radius)); further away it shrinks with the sine of its angle below the horizon."}};
    Param<double> m_radius_tolerance{
        this,
        0.3,
        {"radius_tolerance", "", 0, 1, 0.05,
         "How far, as a share, a ball's radius may be from the one expected where it stands."}};
    Param<double> m_radius_slack{
        this,
        2.5,
        {"radius_slack", "px", 0, 50, 0.5,
         "Widens the expected radius range both ways (a small ball's fit is a pixel or two off)."}};
    Param<std::uint32_t> m_seed{this, 1, kRansacSeed};
};

} // namespace fieldsight
