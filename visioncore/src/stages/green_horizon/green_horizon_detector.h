// Green horizon (design note §2.1): where the field starts, as the upper convex hull of the first
// green run in evenly spaced columns scanned down from the kinematic horizon.
#pragma once

#include "visioncore/framework/stage.h"
#include "stages/green_horizon/edge_lines.h"
#include "visioncore/basics/geometry.h"

#include <optional>
#include <utility>
#include <vector>

namespace fieldsight {

class GreenHorizonDetector : public Stage
{
public:
    const StageInfo& info() const override;
    void run(Blackboard& bb) override;

private:
    std::vector<PointF> m_hull;       ///< per-frame scratch, kept so a frame allocates nothing
    std::vector<int> m_run_rows;      ///< the green rows of the run being scanned (scratch)
    using Span = std::pair<int, int>; ///< a green run's first and last row
    std::vector<Span> m_runs;         ///< a column's green runs (scratch)
    EdgeFitScratch m_edge_scratch;    ///< the edge lines' fit (scratch)

    /// The row where the field starts in column `x` (scanned from `y0` down; `horizon`: the
    /// kinematic horizon's row there; none when the stream gives none), if it has one. Green
    /// runs above the field it rejects are added to the thrown points.
    std::optional<int> fieldStart(Blackboard& bb, int x, int y0, std::optional<double> horizon);
    /// The thrown-points layer, if asked for: the first `above_gaps` points were green above a
    /// gap, those up to `above_edge` above the edge's lines, the rest outliers.
    void drawThrown(Blackboard& bb, std::size_t above_gaps, std::size_t above_edge) const;
    /// With edge_lines: moves the scan points above the field's edge lines to the thrown points.
    void throwAboveEdge(Blackboard& bb);

    Param<int> m_scan_spacing{this,
                              11,
                              {"scan_spacing", "px", 1, 64, 1,
                               "Distance between the columns scanned for green.", true, -1}};
    Param<int> m_min_green_pixels{
        this,
        5,
        {"min_green_pixels", "px", 1, 50, 1,
         "How many green pixels in a column (gaps bridged) mark the start of the field."}};
    Param<int> m_max_gap{this,
                         3,
                         {"max_gap", "px", 0, 20, 1,
                          "Non-green pixels (a field line, noise) a green run may bridge."}};
    Param<double> m_min_density{
        this,
        0.0,
        {"min_green_density", "", 0, 1, 0.05,
         "Share of a green run's pixels that must be green: the field is solid, a wall or a "
         "shirt that the table calls green in places is speckled (0: any run)."}};
    Param<double> m_max_field_gap{
        this,
        0.0,
        {"max_field_gap", "px", 0, 120, 1,
         "The widest non-green gap (a field line) within the field at the image's bottom row, "
         "shrinking with the square of the depth below the horizon: green above a wider gap is "
         "a wall, not the field (0: the first green run from the top is the field)."}};
    Param<double> m_edge_lines{
        this,
        0.0,
        {"edge_lines", "px", 0, 20, 0.5,
         "The carpet's edge is straight: scan points more than this far above the line through "
         "most of them (two lines where a corner is in view) are green behind the field, a wall "
         "or a seat, however many columns they span (0: off)."}};
    Param<double> m_upper_threshold_mult{
        this,
        2.5,
        {"upper_threshold_mult", "sigma", 0, 10, 0.1,
         "Scan points more than this many standard deviations above the mean are thrown out "
         "(green above the field: posters, shirts)."}};
};

} // namespace fieldsight
