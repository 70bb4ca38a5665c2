// The LUT editor's dock: the class palette (keys 0-9), the tools (click with a tolerance box,
// brush, erase, magic wand; right-click picks a class), the tolerance per channel and for all,
// the brush size, cells per class, and the undo history. It turns what the frame view reports
// (toolPressed, toolDragged, toolReleased, pixelPicked) into edits of the LUT document.
#pragma once

#include "ui/document/lut_document.h"
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

enum class LutTool { Navigate, Click, Brush, Erase, Wand };

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
    /// The palette's actions (one per class, keys 0-9), for the window's menu.
    QList<QAction*> colourActions() const;

    // What the frame view reports, in image px.
    void press(QPoint pixel);
    void drag(QPoint pixel);
    void release();
    void pick(QPoint pixel);

signals:
    /// The tool changed: whether the view's left button edits, and the brush outline.
    void toolChanged(bool editing, int brush_radius);
    void problem(const QString& message);

private:
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
    QLabel* m_stats = nullptr;
    int m_stroke = 0;
    std::optional<QPoint> m_last;
};

} // namespace fieldsight::ui
