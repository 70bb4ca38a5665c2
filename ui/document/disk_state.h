// What a document's file was when the window loaded or last saved it, so a save never writes
// silently over what another window or a command wrote there since (a file absent then and
// present now counts as changed too).
#pragma once

#include "ui/adapters/local_path.h"
#include "visioncore/basics/file_fingerprint.h"

#include <QString>

namespace fieldsight::ui {

class DiskState
{
public:
    /// Notes the file at `path` as it is now (empty: the document has no file).
    void remember(const QString& path)
    {
        m_path = path;
        m_print = path.isEmpty() ? FileFingerprint{} : fingerprintFile(toLocalPath(path));
    }
    /// Notes `print` as what the file at `path` was (taken before it was read elsewhere).
    void remember(const QString& path, const FileFingerprint& print)
    {
        m_path = path;
        m_print = print;
    }
    /// The file noted is no longer as it was (its bytes, or whether it is there).
    bool changed() const
    {
        return !m_path.isEmpty() && fileChangedSince(toLocalPath(m_path), m_print);
    }
    /// The file as noted.
    const FileFingerprint& fingerprint() const { return m_print; }
    QString path() const { return m_path; }

private:
    QString m_path;
    FileFingerprint m_print;
};

} // namespace fieldsight::ui
