#include "ui/document/document.h"

#include "ui/adapters/local_path.h"
#include "ui/recovery/recovery_meta.h"
#include "visioncore/basics/atomic_file.h"

namespace fieldsight::ui {

Document::Document(Saving saving, QObject* parent) : QObject(parent), m_saving(saving)
{
    m_recovery_dir = defaultRecoveryDir();
    if (m_saving != Saving::ByUser)
        return;
    // The autosave fires once, its interval after the first unsaved edit, and writes the
    // recovery file while the edits are still unsaved (a failure goes to problem()); undoing
    // back to the saved state stops it and removes the recovery file.
    m_autosave.setSingleShot(true);
    m_autosave.setInterval(30000);
    connect(&m_autosave, &QTimer::timeout, this, [this] {
        if (!modified())
            return;
        if (Status s = writeRecovery(); !s)
            emit problem(QString::fromStdString(s.error().message));
    });
    connect(&m_undo, &QUndoStack::cleanChanged, this, [this] {
        if (!modified()) { // undone back to what was saved: nothing to recover
            m_autosave.stop();
            discardOwnRecovery();
        }
        emit modifiedChanged(modified());
    });
}

Document::~Document()
{
    QObject::disconnect(&m_undo, nullptr, this, nullptr);
    blockSignals(true);
}

Status Document::save()
{
    if (m_path.isEmpty())
        return Error{noFileMessage().toStdString()};
    if (const QString refusal = saveRefusal(); !refusal.isEmpty())
        return Error{toLocalPath(m_path) + refusal.toStdString()};
    if (changedOnDisk())
        return Error{toLocalPath(m_path) +
                     ": changed on disk since it was read (another window or program wrote "
                     "it), so it is not written over; reload it or save under another name"};
    return saveAs(m_path);
}

Status Document::saveAs(const QString& path)
{
    if (Status s = writeFile(path); !s)
        return s; // the edits stay in memory, and modified
    setFile(path);
    markClean();
    return {};
}

Status Document::writeFile(const QString& path)
{
    return Error{toLocalPath(path) + ": this document is not saved to a file of its own"};
}

void Document::setFile(const QString& path, const std::optional<FileFingerprint>& read)
{
    m_path = path;
    if (read)
        m_disk.remember(path, *read);
    else
        m_disk.remember(path);
}

void Document::clearHistory()
{
    m_recovered = false;
    m_undo.clear();
    m_autosave.stop();
}

void Document::noteEdit()
{
    if (m_saving == Saving::ByUser && !m_autosave.isActive())
        m_autosave.start();
}

void Document::markClean()
{
    m_recovered = false;
    m_undo.setClean();
    m_autosave.stop();
    discardOwnRecovery();
    emit modifiedChanged(false);
}

void Document::pushEdit(QUndoCommand* command, int merge)
{
    m_undo.push(command);
    m_top_merge = merge;
    m_top_index = m_undo.index();
}

Result<std::string> Document::writeAtChange(const std::function<Status(const std::string&)>& save)
{
    const std::string path = toLocalPath(m_path);
    auto saved = saveReplacingUnreadable(path, m_unreadable, [&] { return save(path); });
    if (saved)
        m_disk.remember(m_path);
    return saved;
}

} // namespace fieldsight::ui
