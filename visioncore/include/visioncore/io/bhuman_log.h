// A B-Human log folder as the reference data keeps one (frames_ycbcr/fNNN.png, YCbCr in the PNG's
// channels; frames.csv, one row a frame with its timestamp, camera matrix validity and kinematic
// horizon; coltable.c64, the team's colour table): read into what a stream folder needs, so
// `fieldsight import` can make one whose manifest carries each frame's kinematic horizon.
#pragma once

#include "visioncore/basics/geometry.h"
#include "visioncore/basics/result.h"

#include <optional>
#include <string>
#include <vector>

namespace fieldsight {

struct LoggedFrame
{
    std::string path; ///< the frame's PNG in the log folder
    double timestamp_ms = 0;
    /// The kinematic horizon; none where the log marks the camera matrix invalid.
    std::optional<Horizon> horizon;
};

struct BhumanLog
{
    std::vector<LoggedFrame> frames; ///< in frames.csv's order
    int width = 0;                   ///< px, of the first frame
    int height = 0;
    std::string colour_table; ///< the folder's coltable.c64; empty when it has none
    std::size_t invalid = 0;  ///< frames whose camera matrix the log marks invalid
};

/// The horizon (y at x = 0 and at x = width-1) of the line through `origin` with direction
/// `direction`, as B-Human's ImageCoordinateSystem gives it; none for a direction too close to
/// vertical, or a horizon beyond Horizon::kMaxRows.
std::optional<Horizon> horizonOfLine(PointF origin, PointF direction, int width);

/// Whether `folder` looks like a B-Human log folder (frames.csv and frames_ycbcr/).
bool isBhumanLogFolder(const std::string& folder);

/// Reads the log folder: every row of frames.csv (frame, timestamp_ms, ..., cam_matrix_valid,
/// horizon_origin_x, horizon_origin_y, horizon_dir_x, horizon_dir_y: columns found by their
/// header names; a UTF-8 byte order mark before them is skipped) with its frame
/// frames_ycbcr/fNNN.png, which must decode whole at the first frame's size. Errors name the
/// file, the line and the problem (a missing column, a value that is not a number, a frame on
/// a second row, a frame missing, not a regular file, damaged or of another size). The text is
/// read in place: memory is the file's size and the frames' list.
Result<BhumanLog> readBhumanLog(const std::string& folder);

} // namespace fieldsight
