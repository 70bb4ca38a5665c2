// Where the bundled sample stream is, and the user's own copy of it that a first run opens.
#include "ui/actions/session_files.h"

#include "ui/adapters/local_path.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

#include <filesystem>

namespace fieldsight::ui {

QString SessionFiles::bundledSampleStream(const QString& exe_dir)
{
    const QString app = exe_dir.isEmpty() ? QCoreApplication::applicationDirPath() : exe_dir;
    const QStringList candidates{
        qEnvironmentVariable("FIELDSIGHT_SAMPLE_STREAM"),
        app + QStringLiteral("/" FIELDSIGHT_DATA_FROM_BIN "/sample_streams/lab1"),
        app + QStringLiteral("/../../sample_streams/lab1"),
        app + QStringLiteral("/../sample_streams/lab1"),
        QStringLiteral(FIELDSIGHT_SOURCE_SAMPLE_STREAMS "/lab1"),
    };
    for (const QString& c : candidates)
        if (isLocalFolder(c))
            return QDir::cleanPath(QFileInfo(c).absoluteFilePath());
    return {};
}

QString SessionFiles::sampleStreamCopy(QString* problem)
{
    const QString sample = bundledSampleStream();
    if (sample.isEmpty())
        return {};
    const QString data = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    const QString copy = data + QStringLiteral("/sample_streams/lab1");
    if (QFileInfo(copy + QStringLiteral("/stream.json")).isFile())
        return copy;
    // Copied beside, then named: a half-made copy is never taken for the sample.
    const QString partial = copy + QStringLiteral(".partial");
    QDir(partial).removeRecursively(); // our own leftover, made only here
    std::error_code ec;
    std::filesystem::create_directories(toLocalPath(partial), ec);
    if (!ec)
        std::filesystem::copy(toLocalPath(sample), toLocalPath(partial),
                              std::filesystem::copy_options::recursive, ec);
    if (!ec)
        std::filesystem::rename(toLocalPath(partial), toLocalPath(copy), ec);
    if (ec) {
        QDir(partial).removeRecursively();
        if (problem)
            *problem = tr("Could not copy the sample stream to %1 (%2): it opens where it is "
                          "bundled; Save As somewhere else to keep your edits")
                           .arg(copy, QString::fromStdString(ec.message()));
        return sample;
    }
    return copy;
}

} // namespace fieldsight::ui
