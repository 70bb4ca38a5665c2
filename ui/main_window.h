// The main window: the frame view with its navigator, the edit-effect strip and the marks of the
// evaluation's disagreements, and docks made from the stage and tool registries (layers,
// pipeline, LUT editor, UV plane), the detections, the pixel inspector, the bookmarks, the undo
// history and the evaluation. It builds these over one editing
// session and wires them; the documents, the tools and the menus' commands hold the state.
#pragma once

#include "ui/document/editing_session.h"
#include "ui/frame_view/frame_view.h"
#include "ui/stream_navigator/timeline.h"
#include "ui/tools/tool_manager.h"
#include "visioncore/services/lut_compare.h"

#include <QMainWindow>

#include <memory>
#include <optional>

class QMenu;

namespace fieldsight::ui {

class AnnotationsFile;
class BookmarksPanel;
class CalibrateActions;
class CellHighlights;
class DetectionsPanel;
class DiskWatch;
class EvaluationPanel;
class FitActions;
class SessionFiles;
class FrameRecorder;
class HistoryPanel;
class InspectorPanel;
class LayersPanel;
class LutPanel;
class MessageBar;
class OfferBar;
class PipelinePanel;
class StreamNavigator;
class UvPlanePanel;

class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    explicit MainWindow(const Pipeline& pipeline = Pipeline::standard(),
                        const std::vector<ToolFactory>& tools = standardTools(),
                        QWidget* parent = nullptr);
    ~MainWindow() override;

    EditingSession& session() { return *m_session; }
    ToolManager& tools() { return *m_tools; }
    SessionFiles& files() { return *m_files; }
    AnnotationsFile& annotationFiles() { return *m_annotation_files; }
    FrameView& view() { return *m_view; }
    StreamNavigator& navigator() { return *m_navigator; }
    LayersPanel& layersPanel() { return *m_layers; }
    PipelinePanel& pipelinePanel() { return *m_pipeline; }
    DetectionsPanel& detectionsPanel() { return *m_detections; }
    InspectorPanel& inspector() { return *m_inspector; }
    LutPanel& lutPanel() { return *m_lut_panel; }
    UvPlanePanel& uvPanel() { return *m_uv; }
    BookmarksPanel& bookmarksPanel() { return *m_bookmarks; }
    EvaluationPanel& evaluationPanel() { return *m_evaluation; }
    /// The strips under the navigator: edit effect, annotations, disagreements, light.
    const Timeline& timeline() const { return *m_timeline; }
    FrameRecorder& recorder() { return *m_recorder; }
    MessageBar& messageBar() { return *m_message_bar; }
    OfferBar& recoveryBar() { return *m_recovery_bar; }
    /// The offer of unsaved annotation edits kept for the open stream (beside the LUT's: a crash
    /// can leave both).
    OfferBar& annotationsRecoveryBar() { return *m_annotations_recovery_bar; }
    /// The offer to reload a document's file another window or a program changed (DiskWatch).
    OfferBar& diskBar() { return *m_disk_bar; }

    /// Shows `text` in the message bar (red for an error, blue for a note) and the status bar.
    void showMessage(const QString& text, bool error = true);
    /// The message shown last in the window's message bar (errors and notes).
    QString lastMessage() const { return m_last_message; }
    /// Hides the message bar, unless a problem that lasts the session (the settings could not
    /// be read) is to be seen: then that is shown again.
    void clearMessage();

    /// Remembers the window, the view and the tools (WindowSettings).
    void saveSettings() const;

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void buildCentre();
    void buildDocks();
    void restoreSettings();
    void onStreamChanged();
    void onFrameReady();
    /// The detections and inspector panels show the current frame (after the view painted it).
    void refreshPanels();
    void updateTitle();
    /// Lights the current frame's pixels in `cells` (the compare dialog's chosen row).
    void showCompareCells(const std::vector<std::uint32_t>& cells);

    EditingSession* m_session = nullptr;
    ToolManager* m_tools = nullptr;
    SessionFiles* m_files = nullptr;
    AnnotationsFile* m_annotation_files = nullptr;
    CalibrateActions* m_calibrate = nullptr;
    FitActions* m_fit = nullptr;
    FrameRecorder* m_recorder = nullptr;
    FrameView* m_view = nullptr;
    StreamNavigator* m_navigator = nullptr;
    std::unique_ptr<Timeline> m_timeline;
    MessageBar* m_message_bar = nullptr;
    OfferBar* m_recovery_bar = nullptr;
    OfferBar* m_annotations_recovery_bar = nullptr;
    OfferBar* m_disk_bar = nullptr;
    DiskWatch* m_disk_watch = nullptr;
    LayersPanel* m_layers = nullptr;
    PipelinePanel* m_pipeline = nullptr;
    DetectionsPanel* m_detections = nullptr;
    InspectorPanel* m_inspector = nullptr;
    LutPanel* m_lut_panel = nullptr;
    UvPlanePanel* m_uv = nullptr;
    BookmarksPanel* m_bookmarks = nullptr;
    HistoryPanel* m_history = nullptr;
    EvaluationPanel* m_evaluation = nullptr;
    QMenu* m_docks_menu = nullptr;
    CellHighlights* m_highlights = nullptr;
    std::optional<QPoint> m_hover;
    QString m_last_message;
    QString m_standing_problem; ///< what clearMessage() shows again (settings not read)
};

} // namespace fieldsight::ui
