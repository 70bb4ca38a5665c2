// The main window: the frame view with its navigator, and docks made from the stage registry
// (layers, pipeline), the detections, the pixel inspector and the bookmarks. It owns the
// document, opens streams without freezing (progress, cancel), shows every error in the window
// and remembers its layout and choices (QSettings).
#pragma once

#include "ui/document/lut_document.h"
#include "ui/document/stream_document.h"
#include "ui/frame_view/frame_view.h"
#include "visioncore/services/lut_compare.h"

#include <QFutureWatcher>
#include <QMainWindow>

class QLabel;
class QListWidget;
class QMenu;
class QProgressDialog;

namespace fieldsight::ui {

class DetectionsPanel;
class EditEffectScan;
class EffectStrip;
class UvPlanePanel;
class FrameRecorder;
class LutCompareDialog;
class InspectorPanel;
class LayersPanel;
class LutPanel;
class PipelinePanel;
class StreamNavigator;

class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    explicit MainWindow(const Pipeline& pipeline = Pipeline::standard(), QWidget* parent = nullptr);
    ~MainWindow() override;

    StreamDocument& document() { return *m_doc; }
    FrameView& view() { return *m_view; }
    StreamNavigator& navigator() { return *m_navigator; }
    LayersPanel& layersPanel() { return *m_layers; }
    PipelinePanel& pipelinePanel() { return *m_pipeline; }
    DetectionsPanel& detectionsPanel() { return *m_detections; }
    InspectorPanel& inspector() { return *m_inspector; }
    LutDocument& lutDocument() { return *m_lut_doc; }
    LutPanel& lutPanel() { return *m_lut_panel; }
    EditEffectScan& effectScan() { return *m_effect; }
    FrameRecorder& recorder() { return *m_recorder; }
    /// Opens the compare-and-merge dialog for the table at `path` (any importable format); null,
    /// with a message in the window, when it cannot be read.
    LutCompareDialog* compareLut(const QString& path);
    UvPlanePanel& uvPanel() { return *m_uv; }
    EffectStrip& effectStrip() { return *m_effect_strip; }
    QListWidget& bookmarkList() { return *m_bookmark_list; }

    /// Opens a stream in the background with a progress dialog (cancel keeps the stream open
    /// before); streamOpened() tells how it went. An error shows in the window.
    void openStream(const QString& spec, const QString& lut = {});
    /// Opens the LUT in any importable format; an error shows in the window.
    bool openLut(const QString& path);
    /// Opens the last stream of the previous session (with its LUT) if it still exists, else
    /// the bundled sample stream.
    void openLastSession();
    /// The bundled sample stream (sample_streams/lab1), looked for beside the executable, in
    /// the build tree and in the source tree; empty when not found.
    static QString bundledSampleStream();

    /// The message shown last in the window's message bar (errors and notes).
    QString lastMessage() const { return m_last_message; }
    /// The frame view as shown.
    QImage snapshot();
    /// Saves the view as PNG (atomically); false with a message in the window on failure.
    bool saveSnapshot(const QString& path);
    void copySnapshot();

    void saveSettings() const;

    /// Saves the edited LUT to its file (Save As when it has no .lut file yet); false with a
    /// message in the window when it could not (the edits stay).
    bool saveLut();
    /// Saves the edited LUT to `path` (asks for one when empty).
    bool saveLutAs(const QString& path = {});
    /// Loads the recovery file of a session that ended with unsaved LUT edits.
    bool recoverLut();

signals:
    void streamOpened(bool ok);

public slots:
    void showMessage(const QString& text, bool error = true);

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void buildMenus();
    void buildDocks();
    void restoreSettings();
    void onStreamChanged();
    void onFrameReady();
    void onLutLoaded();
    /// Asks what to do with unsaved LUT edits (save, discard, cancel); true to go on.
    bool confirmLutChanges();
    void offerRecovery();
    /// The detections and inspector panels show the current frame (after the view painted it).
    void refreshPanels();
    /// The LUT tool's preview at the hovered pixel (or none).
    void refreshPreview();
    /// The current frame's pixels in chosen cells (the UV plane's selection, the compare
    /// dialog's row), highlighted in the image.
    void refreshCellHighlights();
    void updateTitle();
    void rememberRecent(const QString& spec);
    void rebuildRecentMenu();
    void addBookmark();
    void jumpBookmark(int direction);
    void refreshBookmarks();
    void setMode(ViewMode mode);
    void openPath(const QString& path);

    StreamDocument* m_doc = nullptr;
    LutDocument* m_lut_doc = nullptr;
    LutPanel* m_lut_panel = nullptr;
    EditEffectScan* m_effect = nullptr;
    UvPlanePanel* m_uv = nullptr;
    std::optional<CellMask> m_compare_cells; ///< the compare dialog's chosen row, if any
    FrameRecorder* m_recorder = nullptr;
    EffectStrip* m_effect_strip = nullptr;
    QWidget* m_recovery_bar = nullptr;
    QLabel* m_recovery_label = nullptr;
    FrameView* m_view = nullptr;
    StreamNavigator* m_navigator = nullptr;
    LayersPanel* m_layers = nullptr;
    PipelinePanel* m_pipeline = nullptr;
    DetectionsPanel* m_detections = nullptr;
    InspectorPanel* m_inspector = nullptr;
    QListWidget* m_bookmark_list = nullptr;
    QLabel* m_message = nullptr;
    QWidget* m_message_bar = nullptr;
    QLabel* m_status_zoom = nullptr;
    QLabel* m_status_time = nullptr;
    QLabel* m_status_effect = nullptr;
    QMenu* m_recent_menu = nullptr;
    QMenu* m_docks_menu = nullptr;
    QList<QAction*> m_mode_actions;
    QAction* m_labels_action = nullptr;
    QString m_last_message;
    QString m_preview_shown; ///< the LUT preview line in the status bar, if any
    QStringList m_recent;
    std::optional<QPoint> m_hover;

    /// A background open: the stream, or why it failed.
    struct Opening
    {
        std::shared_ptr<OpenedStream> stream;
        QString error;
    };
    QFutureWatcher<Opening>* m_open_watcher = nullptr;
    QProgressDialog* m_open_progress = nullptr;
    QString m_opening;
};

} // namespace fieldsight::ui
