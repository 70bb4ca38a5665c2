// The LUT editor's dock: the class palette (keys 0-9 and -), a button per tool (from the tool
// list), the shared tool settings (tolerance per channel and for all, brush size, keep other
// classes, soft classes, preview), what the tool would change under the cursor, buttons for the
// whole-table actions of the menus (the automatic table), the samples and the build from them,
// retargeting to a venue's light, and the cells per class. It edits nothing itself: the tools and
// the documents' commands do.
#pragma once

#include "ui/document/lut_document.h"
#include "ui/document/samples_document.h"
#include "ui/document/stream_document.h"
#include "ui/tools/tool_manager.h"

#include <QWidget>

class QActionGroup;
class QCheckBox;
class QGridLayout;
class QLabel;
class QSlider;
class QSpinBox;

namespace fieldsight::ui {

class LutPanel : public QWidget
{
    Q_OBJECT
public:
    LutPanel(LutDocument& lut, StreamDocument& stream, SamplesDocument& samples, ToolManager& tools,
             QWidget* parent = nullptr);

    /// A button for `action` (a menu's, with its shortcut) after the palette's classes.
    void addTableAction(QAction* action);
    /// The palette's actions (one per class, keys 0-9 and -), for the window's menu.
    QList<QAction*> colourActions() const;
    /// Asks (showing the LUT document's estimate for the frame shown and the cells it moves) and
    /// retargets.
    void askRetarget();
    /// Builds from the samples in the background, with a progress dialog; then asks how the
    /// built table goes in (only unclassified cells, or replace), showing what each changes.
    void buildFromSamples();

signals:
    void problem(const QString& message);
    /// What an action did, for the window's message bar.
    void notice(const QString& message);
    /// Cells to outline in the UV plane (the last build's ambiguous cells).
    void cellsToOutline(const std::vector<std::uint32_t>& cells);

private:
    void askApplyBuild();
    /// The widgets show the shared settings.
    void showSettings();
    void refreshStats();

    LutDocument& m_lut;
    StreamDocument& m_stream;
    SamplesDocument& m_samples;
    ToolManager& m_tools;
    QActionGroup* m_colours = nullptr;
    QSpinBox* m_tol_y = nullptr;
    QSpinBox* m_tol_cb = nullptr;
    QSpinBox* m_tol_cr = nullptr;
    QSlider* m_tol_all = nullptr;
    QSpinBox* m_radius = nullptr;
    QCheckBox* m_keep_others = nullptr;
    QCheckBox* m_soft = nullptr;
    QCheckBox* m_preview_on = nullptr;
    QGridLayout* m_palette = nullptr;
    int m_table_actions = 0; ///< buttons added by addTableAction
    QLabel* m_stats = nullptr;
    QLabel* m_preview_label = nullptr;
    QLabel* m_samples_info = nullptr;
    QCheckBox* m_samples_annotations = nullptr;
};

} // namespace fieldsight::ui
