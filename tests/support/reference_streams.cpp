// Stream folders over reference_data's frames, and the B-Human log's frames.csv.
#include "support/reference_streams.h"

#include "support/synthetic_frames.h"
#include "visioncore/io/lut_import.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace fieldsight::test {

QString referencePath(const QString& relative)
{
    const std::string dir = referenceDataDir();
    return dir.empty() ? QString() : QString::fromStdString(dir) + "/" + relative;
}

std::array<double, 2> BhumanFrameRow::horizon(int width) const
{
    auto y_at = [&](double x) { return origin[1] + (x - origin[0]) * direction[1] / direction[0]; };
    return {y_at(0), y_at(width - 1)};
}

std::optional<std::vector<BhumanFrameRow>> readBhumanFramesCsv(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return std::nullopt;
    const QStringList header = QString::fromUtf8(file.readLine()).trimmed().split(',');
    const QStringList names = {
        "frame",         "timestamp_ms",  "horizon_origin_x", "horizon_origin_y",
        "horizon_dir_x", "horizon_dir_y", "cam_matrix_valid"};
    std::vector<qsizetype> column;
    for (const QString& name : names) {
        column.push_back(header.indexOf(name));
        if (column.back() < 0)
            return std::nullopt;
    }
    std::vector<BhumanFrameRow> rows;
    while (!file.atEnd()) {
        const QStringList cells = QString::fromUtf8(file.readLine()).trimmed().split(',');
        if (cells.size() != header.size())
            continue;
        auto cell = [&](int i) { return cells[column[std::size_t(i)]]; };
        BhumanFrameRow row;
        row.index = cell(0).toInt();
        row.timestamp_ms = cell(1).toDouble();
        row.origin = {cell(2).toDouble(), cell(3).toDouble()};
        row.direction = {cell(4).toDouble(), cell(5).toDouble()};
        row.valid = cell(6).toInt() == 1;
        if (std::abs(row.direction[0]) < 1e-6)
            return std::nullopt;
        rows.push_back(row);
    }
    return rows;
}

QString makeLinkedStream(const QString& folder, const QString& frames_dir, const QJsonArray& frames,
                         QJsonObject manifest)
{
    if (!QDir().mkpath(folder))
        return "cannot make " + folder;
    for (const QJsonValue& frame : frames) {
        const QString name = frame.toObject().value("file").toString();
        if (!QFile::link(frames_dir + "/" + name, folder + "/" + name))
            return "cannot link " + frames_dir + "/" + name + " into " + folder;
    }
    manifest.insert("frames", frames);
    QFile file(folder + "/stream.json");
    if (!file.open(QIODevice::WriteOnly) || file.write(QJsonDocument(manifest).toJson()) <= 0)
        return "cannot write " + file.fileName();
    return {};
}

QString convertLut(const QString& in, const QString& out)
{
    auto lut = importLut(in.toStdString());
    if (!lut.ok())
        return QString::fromStdString(lut.error().message);
    if (Status saved = lut.value().save(out.toStdString()); !saved)
        return QString::fromStdString(saved.error().message);
    return {};
}

QString makeBhumanStream(const QString& folder, const QJsonObject& horizons, BhumanTable table)
{
    const QString source = referencePath("bhuman2009_log_coltable");
    QJsonArray frames;
    for (const QString& name : horizons.keys()) {
        const QJsonObject h = horizons.value(name).toObject();
        QJsonObject frame{{"file", name}, {"timestamp_ms", h.value("timestamp_ms")}};
        if (h.value("valid").toBool())
            frame.insert("horizon", h.value("horizon"));
        frames.append(frame);
    }
    QJsonObject manifest{{"format", "fieldsight-stream/1"}, {"pixel_format", "ycbcr"}};
    if (table == BhumanTable::Team)
        manifest.insert("lut", "default.lut");
    QString problem = makeLinkedStream(folder, source + "/frames_ycbcr", frames, manifest);
    if (problem.isEmpty() && table == BhumanTable::Team)
        problem = convertLut(source + "/coltable.c64", folder + "/default.lut");
    return problem;
}

} // namespace fieldsight::test
