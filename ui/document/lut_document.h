// The LUT being edited: its own undo stack, where every edit is a command that stores only the
// cells it changed (a brush stroke is one step, merged while the mouse is down); atomic saves;
// an autosave to a recovery file at most 30 s after an edit, offered again after a crash.
#pragma once

#include "ui/document/disk_state.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/basics/result.h"
#include "visioncore/services/lut_editing.h"

#include <QObject>
#include <QString>
#include <QTimer>
#include <QUndoStack>

#include <memory>
#include <optional>
#include <vector>

namespace fieldsight::ui {

/// A recovery file left by a session that did not save its LUT edits.
struct LutRecovery
{
    QString lut_file; ///< the recovered table
    QString path;     ///< the file it was edited from (may be empty)
    QString stream;   ///< the stream open at the time (may be empty)
    QString saved_at; ///< ISO 8601
};

class LutDocument : public QObject
{
    Q_OBJECT
public:
    explicit LutDocument(QObject* parent = nullptr);
    /// Quiet: the undo stack's last signals do not reach a window being destroyed.
    ~LutDocument() override;

    /// A table loaded from `path` (empty: not from a file): clean, with an empty undo stack.
    /// `read` is the file as it was before it was read (default: as it is now), what
    /// changedOnDisk() compares with.
    void reset(std::shared_ptr<const ColourLut> lut, const QString& path,
               const std::optional<FileFingerprint>& read = std::nullopt);
    /// Drops the unsaved edits: back to the table as loaded or last saved.
    void revert();
    const ColourLut& table() const { return m_table; }
    /// The current table as an immutable version for the worker (one copy per change).
    std::shared_ptr<const ColourLut> version() const;
    QString path() const { return m_path; }
    bool modified() const { return m_recovered || !m_undo.isClean(); }
    QUndoStack& undoStack() { return m_undo; }

    /// Applies `changes` as one undo step named `text`; edits with the same nonzero `stroke`
    /// merge into one step (a brush stroke while the mouse is down). False when nothing changes.
    bool edit(const QString& text, std::vector<CellChange> changes, int stroke = 0);
    /// A fresh stroke id for edit().
    int newStroke() { return ++m_last_stroke; }
    /// The table before the last edit, undo or redo (a whole brush stroke counts as one edit);
    /// null after a reset. What the whole-stream effect compares the current table with.
    std::shared_ptr<const ColourLut> editBase() const { return m_edit_base; }

    /// Saves to path() (atomically); an Error names the file and keeps the edits in memory. A
    /// file another window or program changed since it was read or saved here (changedOnDisk())
    /// is not written over: saveAs() (the same path overwrites) or reload().
    Status save();
    Status saveAs(const QString& path);
    /// The file was written (or made, or removed) by someone else since it was read or saved.
    bool changedOnDisk() const { return m_disk.changed(); }
    /// Reads path() again as one undo step ("Reload LUT from disk", the cells that differ; Undo
    /// brings the edits before it back, unsaved): the table is then clean and what is on disk.
    /// A file gone or unreadable is an Error and changes nothing.
    Status reload();

    /// Where the recovery files go (<dir>/lut-recovery.lut and .json); the app data folder by
    /// default. The autosave runs `delay_ms` after the first unsaved edit (30 s by default).
    void setRecoveryDir(const QString& dir) { m_recovery_dir = dir; }
    void setAutosaveDelay(int delay_ms) { m_autosave.setInterval(delay_ms); }
    /// The stream named in the recovery file.
    void setStream(const QString& stream) { m_stream = stream; }
    /// Writes the recovery files now.
    Status writeRecovery();
    /// A recovery file in the recovery folder, if one was left.
    std::optional<LutRecovery> findRecovery() const;
    /// Loads a recovery: the table becomes modified (to be saved to its path).
    Status recover(const LutRecovery& recovery);
    /// Removes the recovery files (after a save, or when the user declines them).
    void discardRecovery();
    /// The same: the table's recovery file is offered once, at the start.
    void discardOwnRecovery() { discardRecovery(); }

signals:
    /// The table changed: an edit, undo, redo, reset or recovery.
    void changed();
    void modifiedChanged(bool modified);
    /// A background problem (the autosave failed), for the window's message bar.
    void problem(const QString& message);

private:
    friend class LutCellsCommand;
    void apply(const std::vector<CellChange>& changes, bool forwards);
    QString recoveryBase() const;

    ColourLut m_table;
    mutable std::shared_ptr<const ColourLut> m_version;
    std::shared_ptr<const ColourLut> m_saved; ///< as loaded or last saved
    QString m_path;
    DiskState m_disk; ///< the file as read or last saved
    QString m_stream;
    QUndoStack m_undo;
    QTimer m_autosave;
    QString m_recovery_dir;
    bool m_recovered = false;
    int m_last_stroke = 0;
    std::shared_ptr<const ColourLut> m_edit_base;
    bool m_in_edit = false; ///< inside edit(): the push's redo is the edit itself
    int m_top_stroke = 0;   ///< the stroke of the command on top, while it may still merge
    int m_top_index = -1;
};

} // namespace fieldsight::ui
