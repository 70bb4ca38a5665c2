// Files the window tests read and write: the bundled sample stream and copies of it, a file's
// bytes (what landed on disk), and the settings and recovery files kept away from the user's.
#pragma once

#include "support/synthetic_frames.h"
#include "visioncore/basics/colour_lut.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QString>
#include <QTemporaryDir>

#include <functional>

namespace fieldsight::test {

/// A colour table's cells as bytes (to compare tables, or a table with a file).
inline QByteArray tableBytes(const ColourLut& table)
{
    return QByteArray(reinterpret_cast<const char*>(table.data()), qsizetype(ColourLut::kCells));
}

/// Which files of a folder a copy takes, by name.
using FileFilter = std::function<bool(const QString& name)>;

/// Copies the files of the folder `from` that `keep` takes (all of them, frames, table and
/// annotations, without one) into the folder `to`, made if needed: a stream a test may write.
/// Returns `to`.
inline QString copyFolderFiles(const QString& from, const QString& to, const FileFilter& keep = {})
{
    QDir().mkpath(to);
    for (const QString& file : QDir(from).entryList(QDir::Files))
        if (!keep || keep(file))
            QFile::copy(from + "/" + file, to + "/" + file);
    return to;
}

/// A stream's frames alone.
inline bool isFrameFile(const QString& name)
{
    return name.startsWith(QLatin1String("frame_"));
}
/// A stream's frames and its table (no manifest, no annotations).
inline bool isFrameOrTable(const QString& name)
{
    return isFrameFile(name) || name == QLatin1String("default.lut");
}
/// Everything of a stream but its annotations: a stream to annotate afresh.
inline bool isNotAnnotations(const QString& name)
{
    return name != QLatin1String("annotations.json");
}

/// The bundled stream the window tests open (sample_streams/lab1).
inline QString sampleStream()
{
    return QString::fromStdString(sampleStreamsDir() + "/lab1");
}

/// What a window suite's initTestCase does first: the window's settings and recovery files go to
/// Qt's test locations under FieldsightTest/`suite`, never the user's. Returns what is wrong,
/// empty when nothing: the suite's scratch folder `dir` not made, or the bundled sample stream
/// missing (it is part of the project: a wrong path must fail, not skip).
inline QString startWindowSuite(const QString& suite, const QTemporaryDir& dir)
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("FieldsightTest"));
    QCoreApplication::setApplicationName(suite);
    if (!dir.isValid())
        return QStringLiteral("no scratch folder: ") + dir.errorString();
    if (!QFileInfo(sampleStream()).isDir())
        return QStringLiteral("the bundled sample stream is missing: ") + sampleStream();
    return {};
}

/// Drops the settings and the recovery files an earlier test left (a suite's init()).
inline void forgetEarlierTests()
{
    QSettings().clear();
    QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
}

/// Every byte of the file at `path` (empty when it cannot be read).
inline QByteArray fileBytes(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

/// A stream in `to` of the sample stream's table and its first `frames` frames, without its
/// annotations; `to` is returned.
inline QString copySampleFrames(const QString& to, int frames)
{
    QDir().mkpath(to);
    QFile::copy(sampleStream() + "/default.lut", to + "/default.lut");
    for (int i = 0; i < frames; ++i) {
        const QString frame = QStringLiteral("frame_%1.png").arg(i, 6, 10, QLatin1Char('0'));
        QFile::copy(sampleStream() + "/" + frame, to + "/" + frame);
    }
    return to;
}

} // namespace fieldsight::test
