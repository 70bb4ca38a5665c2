// The LUT being edited: its own undo stack, where every edit is a command that stores only the
// cells it changed (a brush stroke is one step, merged while the mouse is down); atomic saves;
// an autosave to a recovery file at most 30 s after an edit, offered again after a crash.
#pragma once

#include "ui/document/document.h"
#include "visioncore/basics/colour_lut.h"
#include "visioncore/basics/result.h"
#include "visioncore/services/lut_editing.h"

#include <QString>

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

class LutDocument : public Document
{
    Q_OBJECT
public:
    explicit LutDocument(QObject* parent = nullptr);

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

    /// Applies `changes` as one undo step named `text`; edits with the same nonzero `stroke`
    /// (newMerge()) merge into one step (a brush stroke while the mouse is down). False when
    /// nothing changes.
    bool edit(const QString& text, std::vector<CellChange> changes, int stroke = 0);
    /// Makes every cell of `colour` unclassified, as one undoable edit; the cells it cleared.
    std::size_t clearClass(Colour colour);
    /// Retargeting to a venue: the shift that moves the table's green onto the field of `frame`
    /// (YCbCr; null: no frame), taken as its bottom third (`samples`: how many pixels that was).
    ColourShift estimateRetarget(const cv::Mat* frame, std::size_t* samples = nullptr) const;
    /// Moves the whole table by `shift` as one undoable edit; false when nothing changes.
    bool retarget(const ColourShift& shift);
    /// The table before the last edit, undo or redo (a whole brush stroke counts as one edit);
    /// null after a reset. What the whole-stream effect compares the current table with.
    std::shared_ptr<const ColourLut> editBase() const { return m_edit_base; }

    // Saved with Document::save() and saveAs(), only as .lut (the foreign formats are
    // import-only).
    /// Reads path() again as one undo step ("Reload LUT from disk", the cells that differ; Undo
    /// brings the edits before it back, unsaved): the table is then clean and what is on disk.
    /// A file gone or unreadable is an Error and changes nothing.
    Status reload();

    /// The stream named in the recovery file.
    void setStream(const QString& stream) { m_stream = stream; }
    /// Writes the recovery files now (<recoveryDir()>/lut-recovery.lut and .json).
    Status writeRecovery() override;
    /// A recovery file in the recovery folder, if one was left.
    std::optional<LutRecovery> findRecovery() const;
    /// Loads a recovery: the table becomes modified (to be saved to its path).
    Status recover(const LutRecovery& recovery);
    /// Removes the recovery files (after a save, or when the user declines them); the table's
    /// recovery file is offered once, at the start, so this session's are the same.
    void discardRecovery() override;

signals:
    /// The table changed: an edit, undo, redo, reset or recovery.
    void changed();

protected:
    Status writeFile(const QString& path) override;
    QString noFileMessage() const override;

private:
    friend class LutCellsCommand;
    void apply(const std::vector<CellChange>& changes, bool forwards);
    QString recoveryBase() const;

    ColourLut m_table;
    mutable std::shared_ptr<const ColourLut> m_version;
    std::shared_ptr<const ColourLut> m_saved; ///< as loaded or last saved
    QString m_stream;
    std::shared_ptr<const ColourLut> m_edit_base;
    bool m_in_edit = false; ///< inside edit(): the push's redo is the edit itself
};

} // namespace fieldsight::ui
