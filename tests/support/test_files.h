// Files the window tests read: the bundled sample stream and a file's bytes (what landed on disk).
#pragma once

#include "support/synthetic_frames.h"

#include <QByteArray>
#include <QFile>
#include <QString>

namespace fieldsight::test {

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

} // namespace fieldsight::test
