// Stream folders over the frames in ../shared/reference_data (linked, never copied), and the
// B-Human 2009 log's per-frame camera rows, for the tests on real robot frames.
#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QString>

#include <array>
#include <optional>
#include <vector>

namespace fieldsight::test {

/// reference_data/<relative>, or an empty string when reference_data is absent.
QString referencePath(const QString& relative);

/// One row of bhuman2009_log_coltable/frames.csv: a frame's time and its kinematic horizon from
/// B-Human's ImageCoordinateSystem.
struct BhumanFrameRow
{
    int index = 0;
    double timestamp_ms = 0;
    std::array<double, 2> origin{};    ///< px, where the horizon crosses x = 159.5
    std::array<double, 2> direction{}; ///< unit direction of the horizon in the image
    bool valid = false;                ///< cam_matrix_valid: B-Human trusted the camera matrix
    /// SPEC §4's horizon, [y at x = 0, y at x = width-1] in px, from origin and direction.
    std::array<double, 2> horizon(int width) const;
};

/// The rows of frames.csv in file order; nothing when it cannot be read, lacks a column or has a
/// vertical horizon (the head would be rolled by 90 degrees).
std::optional<std::vector<BhumanFrameRow>> readBhumanFramesCsv(const QString& path);

/// Makes the new folder `folder` a stream over `frames_dir`: links every `frames[i]["file"]` from
/// there and writes stream.json as `manifest` with `frames` added. An empty string on success,
/// else what failed.
QString makeLinkedStream(const QString& folder, const QString& frames_dir, const QJsonArray& frames,
                         QJsonObject manifest);

/// Which table a B-Human stream made by makeBhumanStream reads.
enum class BhumanTable { Team, None };

/// Makes the new folder `folder` a stream over the B-Human log's frames that the `frames` object
/// of a fieldsight-horizons/1 manifest names (tests/data/real/bhuman2009/horizons.json), each with
/// its timestamp and, where the log marks the camera matrix valid, its kinematic horizon (as
/// `fieldsight import` takes them), and with the team's table as default.lut or no table. An
/// empty string on success, else what failed.
QString makeBhumanStream(const QString& folder, const QJsonObject& horizons, BhumanTable table);

/// Converts another team's colour table (any format `lut convert` reads) to `out` (.lut). An empty
/// string on success, else the message.
QString convertLut(const QString& in, const QString& out);

} // namespace fieldsight::test
