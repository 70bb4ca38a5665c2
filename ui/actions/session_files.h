// What the File menu does, apart from the window: opening streams in the background (progress,
// cancel, the stream before stays until the new one is in), opening and comparing tables, saving
// the table (Save As for one that has no .lut yet), asking before unsaved edits are replaced,
// offering a crashed session's edits back, the recent streams and snapshots of the view. Every
// question goes through the Dialogs seam and every error to the window's message bar.
#pragma once

#include "ui/actions/menus.h"
#include "ui/document/lut_document.h"

#include <QHash>
#include <QObject>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

class QMenu;
class QProgressDialog;

namespace fieldsight::ui {

class AnnotationsFile;
class FrameView;
class LutCompareDialog;
class OfferBar;
struct WindowSettings;

class SessionFiles : public QObject
{
    Q_OBJECT
public:
    /// Asks about `annotations`' unsaved edits before another stream opens, snapshots `view`
    /// and offers a crashed session's table edits in `recovery_bar`.
    SessionFiles(const MenuTarget& target, AnnotationsFile& annotations, FrameView& view,
                 OfferBar& recovery_bar);

    /// Opens a stream in the background with a progress dialog (cancel keeps the stream open
    /// before); streamOpened() tells how it went. An error shows in the window.
    /// False when it did not start (the user kept unsaved edits, or another open runs).
    bool openStream(const QString& spec, const QString& lut = {});
    /// Opens the LUT in any importable format; an error shows in the window.
    bool openLut(const QString& path);
    /// A dropped or given path: a table by its suffix, else a stream.
    void openPath(const QString& path);
    /// Opens the compare-and-merge dialog for the table at `path`; null, with a message in the
    /// window, when it cannot be read.
    LutCompareDialog* compareLut(const QString& path);
    /// Opens `stream` with `lut` if it still exists, else the bundled sample stream.
    void openLastSession(const QString& stream, const QString& lut);
    /// The bundled sample stream (sample_streams/lab1): $FIELDSIGHT_SAMPLE_STREAM, else where
    /// `cmake --install` puts it as seen from the executable in `exe_dir`
    /// (../share/fieldsight/sample_streams/lab1), else the build tree's source tree; empty when
    /// not found. `exe_dir` defaults to the running executable's folder.
    static QString bundledSampleStream(const QString& exe_dir = {});
    /// The user's own copy of the bundled sample stream, in the app data folder, made from it
    /// the first time (a later copy is the user's, kept as it is): a first run's saved table or
    /// annotations never edit the project's or the installed sample. Empty when there is no
    /// sample; the bundled one itself (and `problem` says why) when it cannot be copied.
    static QString sampleStreamCopy(QString* problem = nullptr);

    /// Starts an empty, untitled table (after asking about unsaved edits); false when the user
    /// kept them.
    bool newLut();
    /// File > Save (Ctrl+S): the annotations when they have unsaved edits, and the LUT as
    /// before (when it has unsaved edits, or when the annotations had none).
    bool saveAll();
    /// Saves the edited LUT to its file (Save As when it has no .lut file yet; a question when
    /// another window or program changed the file since: reload, Save As, overwrite, cancel);
    /// false with a message in the window when edits are left unsaved.
    bool saveLut();
    /// Reads the LUT's file again as one undo step (Undo brings the edits before it back).
    bool reloadLut();
    /// Saves the edited LUT to `path` (asks for one when empty).
    bool saveLutAs(const QString& path = {});
    /// Asks what to do with unsaved LUT edits (save, discard, cancel); true to go on.
    bool confirmLutChanges();
    /// Shows the offer of a recovery file, if one was left.
    void offerRecovery();
    /// Loads the recovery file of a session that ended with unsaved LUT edits onto the stream it
    /// belongs to: at once when that stream is open, else after opening it; refused, saying why
    /// and keeping the file, when it cannot be (never applied to another stream's table).
    bool recoverLut();
    void discardRecovery();

    /// Saves the view as PNG (atomically); false with a message in the window on failure.
    bool saveSnapshot(const QString& path);
    void copySnapshot();

    QStringList recent() const { return m_recent; }
    void setRecent(const QStringList& recent);
    /// The frame each recent stream was last on (the open one's now), one per recent() entry.
    QList<int> recentFrames() const;
    void setRecentFrames(const QList<int>& frames);
    /// The Recent streams menu, kept up to date.
    void setRecentMenu(QMenu* menu);
    /// Remembers the recent streams, the frame each was on, and the stream and table open (the
    /// window's settings keep them between sessions); takes the recent ones back.
    void saveSettings(WindowSettings& settings) const;
    void restoreSettings(const WindowSettings& settings);

signals:
    void streamOpened(bool ok);
    /// A stream opened: the window's settings are to be saved now, not only on a clean quit, so
    /// that after a crash the next start reopens it.
    void settingsToSave();
    /// The compare dialog's chosen row: the cells to light in the frame and the UV plane.
    void compareCellsChosen(const std::vector<std::uint32_t>& cells);

private:
    /// The open stream's folder (a file stream's: the folder it is in).
    QString streamFolder() const;
    /// After Save As: offers to make `path` the table the open stream opens with.
    void offerAsStreamTable(const QString& path);
    /// Hides the message `shown` (that every pixel is unclassified) once the table has a class.
    void hideWhenClassified(const QString& shown);
    void onOpened(bool ok, bool cancelled, const QString& error);
    void rememberRecent(const QString& spec);
    /// Notes the open stream's frame, to go back to when it is opened again.
    void rememberFrame();
    static QString recentKey(const QString& spec);
    /// Applies `recovery` to the open stream's table (which must be the one it belongs to).
    bool applyRecovery(const LutRecovery& recovery);
    void rebuildRecentMenu();

    MenuTarget m_target;
    AnnotationsFile& m_annotations;
    FrameView& m_view;
    OfferBar& m_recovery_bar;
    QProgressDialog* m_progress = nullptr;
    QHash<QString, int> m_frames; ///< the frame a stream was last on, by its absolute path
    /// Hides the "no table" warning once the table has a classified cell.
    QMetaObject::Connection m_until_classified;
    QStringList m_recent;
    QMenu* m_recent_menu = nullptr;
    std::optional<LutRecovery> m_recover_after_open; ///< applied once its stream is open
};

} // namespace fieldsight::ui
