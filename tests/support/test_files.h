// Files the window tests read: the bundled sample stream and a file's bytes (what landed on disk).
#pragma once

#include "support/synthetic_frames.h"

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>

namespace fieldsight::test {

/// Copies every file of the folder `from` (frames, table, annotations) into the folder `to`,
/// made if needed: a stream a test may write. Returns `to`.
inline QString copyFolderFiles(const QString& from, const QString& to)
{
    QDir().mkpath(to);
    for (const QString& file : QDir(from).entryList(QDir::Files))
        QFile::copy(from + "/" + file, to + "/" + file);
    return to;
}

/// The bundled stream the window tests open (sample_streams/lab1).
inline QString sampleStream()
{
    return QString::fromStdString(sampleStreamsDir() + "/lab1");
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
