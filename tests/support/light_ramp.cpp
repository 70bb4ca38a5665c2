// Copies a stream under a ramping light, frame by frame through the core's reader.
#include "support/light_ramp.h"
#include "support/test_images.h"

#include "visioncore/basics/ycbcr.h"
#include "visioncore/io/stream_reader.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace fieldsight::test {

QString writeLightRamp(const QString& stream, const QString& out,
                       const std::array<double, 3>& end_gain)
{
    auto reader = openStream(stream.toStdString());
    if (!reader)
        return QString::fromStdString(reader.error().message);
    const StreamInfo& info = reader.value()->info();
    if (!QDir().mkpath(out) || !QDir(out).isEmpty())
        return out + ": not a new or empty folder";
    QJsonArray frames;
    const std::size_t n = info.frame_count;
    for (std::size_t i = 0; i < n; ++i) {
        auto frame = reader.value()->read(i);
        if (!frame)
            return QString::fromStdString(frame.error().message);
        const double t = n > 1 ? double(i) / double(n - 1) : 0.0;
        cv::Mat bgr = ycbcrToBgr(frame.value().ycbcr);
        const cv::Scalar gain(1 + t * (end_gain[2] - 1), 1 + t * (end_gain[1] - 1),
                              1 + t * (end_gain[0] - 1));
        cv::Mat lit;
        cv::multiply(bgr, gain, lit); // saturates at 255, as a sensor clips
        // The frame's own name, so the annotations still name it.
        const QString name =
            QFileInfo(QString::fromStdString(frame.value().name)).completeBaseName() +
            QStringLiteral(".png");
        if (!fieldsight::test::imwrite(QDir(out).filePath(name).toStdString(), lit))
            return out + "/" + name + ": cannot write";
        QJsonObject entry{{"file", name}, {"timestamp_ms", frame.value().timestamp_ms}};
        if (const auto& h = frame.value().horizon)
            entry["horizon"] = QJsonArray{h->y_left, h->y_right};
        frames.append(entry);
    }
    QJsonObject manifest{{"format", "fieldsight-stream/1"},
                         {"pixel_format", "rgb"},
                         {"lut", "default.lut"},
                         {"frames", frames}};
    if (!info.default_lut.empty() &&
        !QFile::copy(QString::fromStdString(info.default_lut), QDir(out).filePath("default.lut")))
        return out + ": cannot copy the table " + QString::fromStdString(info.default_lut);
    if (!info.params.empty()) {
        if (!QFile::copy(QString::fromStdString(info.params), QDir(out).filePath("params.json")))
            return out + ": cannot copy " + QString::fromStdString(info.params);
        manifest["params"] = "params.json";
    }
    const QString annotations = QFileInfo(stream).isDir()
                                    ? QDir(stream).filePath("annotations.json")
                                    : QFileInfo(stream).dir().filePath("annotations.json");
    if (QFile::exists(annotations))
        QFile::copy(annotations, QDir(out).filePath("annotations.json"));
    QFile file(QDir(out).filePath("stream.json"));
    if (!file.open(QIODevice::WriteOnly) || file.write(QJsonDocument(manifest).toJson()) < 0)
        return file.fileName() + ": cannot write";
    return {};
}

} // namespace fieldsight::test
