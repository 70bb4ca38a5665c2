// What every document of a session shares, written once: its undo stack, its file and whether
// that file changed on disk since it was read or saved here, whether it holds unsaved edits, save
// and save-as, and, for a document saved by the user, the autosave to a recovery file at most
// 30 s after the first unsaved edit. Each kind of document says only how its data is written.
#pragma once

#include "ui/document/disk_state.h"
#include "visioncore/basics/result.h"

#include <QObject>
#include <QString>
#include <QTimer>
#include <QUndoStack>

#include <functional>
#include <optional>
#include <string>

namespace fieldsight::ui {

class Document : public QObject
{
    Q_OBJECT
public:
    /// Quiet: the undo stack's last signals do not reach observers being destroyed.
    ~Document() override;

    /// The document's file (empty: it has none yet, or none at all).
    QString path() const { return m_path; }
    QUndoStack& undoStack() { return m_undo; }
    /// Edits not in the file yet: the undo stack is not at the step last saved, or the data came
    /// from a recovery file.
    bool modified() const { return m_recovered || !m_undo.isClean(); }
    /// The file was written (or made, or removed) by someone else since it was read or saved.
    bool changedOnDisk() const { return m_disk.changed(); }

    /// Saves to path() (atomically); an Error names the file and keeps the edits in memory. A
    /// file saveRefusal() names, or one another window or program changed since it was read or
    /// saved here (changedOnDisk()), is not written over: saveAs() (the same path overwrites) or
    /// reload.
    Status save();
    /// Writes the data to `path`, which becomes the document's file; the document is then clean.
    Status saveAs(const QString& path);

    /// Where the recovery files go; the app data folder by default. The autosave runs `delay_ms`
    /// after the first unsaved edit (30 s by default).
    void setRecoveryDir(const QString& dir) { m_recovery_dir = dir; }
    QString recoveryDir() const { return m_recovery_dir; }
    void setAutosaveDelay(int delay_ms) { m_autosave.setInterval(delay_ms); }
    /// Writes the recovery file now (a document without autosave has none).
    virtual Status writeRecovery() { return {}; }
    /// Removes the recovery file (after a save, or when the user declines it).
    virtual void discardRecovery() {}
    /// Removes the recovery file of this session's edits (they were saved or dropped).
    virtual void discardOwnRecovery() { discardRecovery(); }

    /// A fresh id for edits that merge into one undo step while they share it (a brush stroke or
    /// a drag while the mouse is down).
    int newMerge() { return ++m_last_merge; }

signals:
    void modifiedChanged(bool modified);
    /// A background problem (an autosave or a save at a change failed), for the message bar.
    void problem(const QString& message);

protected:
    /// Whether the user saves the document (with an autosave to a recovery file between saves)
    /// or it is written at every change.
    enum class Saving {
        None,        ///< no file of its own
        ByUser,      ///< save() and saveAs(); an autosave to a recovery file
        EveryChange, ///< writeAtChange() after every edit
    };
    explicit Document(Saving saving, QObject* parent = nullptr);

    /// Writes the data to `path` for saveAs(); an Error keeps the document as it was.
    virtual Status writeFile(const QString& path);
    /// What save() says when the document has no file yet.
    virtual QString noFileMessage() const { return tr("the document has no file yet"); }
    /// Why save() must not write over path() even if it is unchanged on disk (empty: it may).
    virtual QString saveRefusal() const { return {}; }

    /// `path` is the document's file, as it is now or as `read` (taken before it was read).
    void setFile(const QString& path, const std::optional<FileFingerprint>& read = std::nullopt);
    /// The file as read or last saved: kept across a revert, taken before a reload reads it.
    const DiskState& disk() const { return m_disk; }
    void setDisk(const DiskState& disk) { m_disk = disk; }
    /// A new history: no undo steps, nothing recovered, no autosave due.
    void clearHistory();
    /// The data came from a recovery file: modified until saved.
    void setRecovered() { m_recovered = true; }
    /// Starts the autosave unless it runs already: at most its delay after the first unsaved edit.
    void noteEdit();
    /// What the document holds is what its file holds (saved, or read again).
    void markClean();

    /// Pushes `command`; with the same nonzero `merge` as the command on top it merges into it.
    void pushEdit(QUndoCommand* command, int merge);
    /// Edits with `merge` would merge into the command on top.
    bool mergesWithTop(int merge) const
    {
        return merge > 0 && merge == m_top_merge && m_undo.index() == m_top_index;
    }
    /// The command on top takes no more merges (an undo, a redo, a reload).
    void endMerge() { m_top_merge = 0; }
    /// A fresh history's merge tracking.
    void resetMerge()
    {
        m_top_merge = 0;
        m_top_index = -1;
    }

    /// For documents written at every change: whether `path()` is to be set aside before the
    /// next write (it could not be read).
    void setUnreadable(bool unreadable) { m_unreadable = unreadable; }
    /// Writes with `save` (given the local path) at a change, setting an unreadable file aside
    /// first; the file is then remembered as saved. The value says what was set aside (empty:
    /// nothing).
    Result<std::string> writeAtChange(const std::function<Status(const std::string&)>& save);

private:
    Saving m_saving;
    QString m_path;
    DiskState m_disk; ///< the file as read or last saved
    QUndoStack m_undo;
    QTimer m_autosave;
    QString m_recovery_dir;
    bool m_recovered = false;
    bool m_unreadable = false; ///< the file was refused: set aside before a save
    int m_last_merge = 0;
    int m_top_merge = 0; ///< the merge id of the command on top, while it may still merge
    int m_top_index = -1;
};

} // namespace fieldsight::ui
