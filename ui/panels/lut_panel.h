// The LUT editor's dock: the class palette (keys 0-9), the tools (click with a tolerance box,
// brush, erase, magic wand; right-click picks a class), the tolerance per channel and for all,
// the brush size, cells per class, and the undo history. It turns what the frame view reports
// (toolPressed, toolDragged, toolReleased, pixelPicked) into edits of the LUT document.
#pragma once

#include "ui/document/lut_document.h"
#include "ui/document/lut_sampler.h"
#include "ui/document/stream_document.h"

#include <QWidget>

class QActionGroup;
class QButtonGroup;
class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QSpinBox;

namespace fieldsight::ui {

enum class LutTool { Navigate, Click, Brush, Erase, Wand, Sample };

/// What a tool would do: the changes and the undo step's name.
struct PlannedEdit
{
    QString text;
    std::vector<CellChange> changes;
};

class LutPanel : public QWidget
{
    Q_OBJECT
public:
    LutPanel(LutDocument& lut, StreamDocument& stream, QWidget* parent = nullptr);

    LutTool tool() const { return m_tool; }
    void setTool(LutTool tool);
    Colour colour() const { return m_colour; }
    void setColour(Colour colour);
    Tolerance tolerance() const;
    void setTolerance(const Tolerance& tolerance);
    int brushRadius() const;
    void setBrushRadius(int radius);
    /// Edits leave cells of other classes alone.
    bool keepOthers() const;
    /// Where pink or yellow meets orange, edits make the soft class (pink_orange, yellow_orange).
    bool softClasses() const;
    void setSoftClasses(bool on);
    /// The palette's actions (one per class, keys 0-9), for the window's menu.
    QList<QAction*> colourActions() const;

    // What the frame view reports, in image px.
    void press(QPoint pixel);
    void drag(QPoint pixel);
    void release();
    void pick(QPoint pixel);
    /// Shows what the tool would do at `pixel` (the cursor): the pixels of the frame whose class
    /// would change, and how many of the cells now belong to another class. An empty point
    /// clears it.
    void preview(std::optional<QPoint> pixel);
    /// What the current tool would do at `pixel` of the current frame (a brush: one dab).
    std::optional<PlannedEdit> planAt(QPoint pixel) const;
    /// The preview's summary line (empty when none).
    QString previewText() const;
    /// The cells the preview would change.
    const std::vector<CellChange>& previewChanges() const { return m_preview; }
    /// Retargeting to a venue: the shift that moves the table's green onto the current frame's
    /// field, taken as the bottom third of the frame (`samples`: how many pixels that was).
    ColourShift estimateRetarget(std::size_t* samples = nullptr) const;
    /// Moves the whole table by `shift` as one undoable edit; false when nothing changes.
    bool retarget(const ColourShift& shift);
    /// Asks (showing the estimate and the cells it moves) and retargets.
    void askRetarget();
    LutSampler& sampler() { return *m_sampler; }
    /// Builds from the samples in the background, with a progress dialog.
    void buildFromSamples();
    /// Cells the last edit changed (a whole stroke), for the UV view.
    const std::vector<std::uint32_t>& lastEditCells() const { return m_last_edit_cells; }

signals:
    /// The tool changed: whether the view's left button edits, and the brush outline.
    void toolChanged(bool editing, int brush_radius);
    void problem(const QString& message);
    /// The preview changed: a CV_8U mask of the frame's pixels whose class would change (empty
    /// when none), and the cells.
    void previewChanged(const cv::Mat& pixels, const std::vector<std::uint32_t>& cells);
    /// Cells to outline in the UV plane (the last build's ambiguous cells).
    void cellsToOutline(const std::vector<std::uint32_t>& cells);

private:
    /// The changes of brushing (or erasing) `pixels` with the current settings.
    PlannedEdit brushEdit(const std::vector<cv::Point>& pixels) const;
    /// Emits toolChanged for the current tool and brush radius.
    void announceTool();
    void paintAt(QPoint pixel);
    void refreshStats();
    const cv::Mat* frame() const;

    LutDocument& m_lut;
    StreamDocument& m_stream;
    LutTool m_tool = LutTool::Navigate;
    Colour m_colour = Colour::Orange;
    QActionGroup* m_colours = nullptr;
    QButtonGroup* m_tools = nullptr;
    QSpinBox* m_tol_y = nullptr;
    QSpinBox* m_tol_cb = nullptr;
    QSpinBox* m_tol_cr = nullptr;
    QSlider* m_tol_all = nullptr;
    QSpinBox* m_radius = nullptr;
    QCheckBox* m_keep_others = nullptr;
    QCheckBox* m_soft = nullptr;
    QLabel* m_stats = nullptr;
    QLabel* m_preview_label = nullptr;
    QCheckBox* m_preview_on = nullptr;
    std::vector<CellChange> m_preview;
    std::vector<std::uint32_t> m_last_edit_cells;
    LutSampler* m_sampler = nullptr;
    QLabel* m_samples_info = nullptr;
    QCheckBox* m_samples_annotations = nullptr;
    std::optional<QPoint> m_sample_from;
    std::optional<QPoint> m_sample_to;
    int m_stroke = 0;
    std::optional<QPoint> m_last;
};

} // namespace fieldsight::ui
