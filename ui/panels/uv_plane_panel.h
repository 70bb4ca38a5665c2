// The LUT in the UV (Cb, Cr) plane at a chosen Y range: each cell in its class's colour, the
// current frame's pixels as a scatter, painting of cells with the LUT editor's colour and brush
// (erase unclassifies), and linked both ways with the image: cells the image tool would change
// are outlined here, and a rectangle selected here (right-drag, or left-drag with the Pan tool)
// highlights its pixels in the image.
#pragma once

#include "ui/document/lut_document.h"
#include "ui/document/stream_document.h"
#include "visioncore/services/lut_compare.h"

#include <QImage>
#include <QWidget>

#include <optional>

class QLabel;
class QSpinBox;

namespace fieldsight::ui {

class ToolManager;
struct ToolEvent;

/// The plane itself: 128 x 128 cells, Cb to the right, Cr upwards.
class UvCanvas : public QWidget
{
    Q_OBJECT
public:
    UvCanvas(LutDocument& lut, StreamDocument& stream, ToolManager& tools,
             QWidget* parent = nullptr);

    /// Y range in 7-bit cells, inclusive.
    void setYRange(int lo, int hi);
    int yLow() const { return m_y_lo; }
    int yHigh() const { return m_y_hi; }
    /// Widget position of the centre of cell (cb, cr), and the cell under a widget position.
    QPointF cellCentre(int cb, int cr) const;
    std::optional<QPoint> cellAt(QPointF pos) const;
    /// Cells outlined (what the image tool would change, or changed last).
    void setOutlinedCells(const std::vector<std::uint32_t>& cells);
    /// The selected cells (a UV rectangle over the Y range), if any.
    const std::optional<CellMask>& selection() const { return m_selection; }
    void clearSelection();
    /// The class image (after a LUT change) and the scatter (after a new frame) are out of date:
    /// they are rebuilt when next painted, so a hidden dock costs nothing.
    void refreshPlane();
    void refreshScatter();

signals:
    void selectionChanged();
    void hovered(const QString& text);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void wheelEvent(QWheelEvent* event) override; ///< zooms around the cursor

public:
    double zoom() const { return m_zoom; }
    /// Zooms by `factor` (1 to 8 times) keeping the plane point under `anchor` where it is.
    void zoomBy(double factor, QPointF anchor);

private:
    /// Where the whole 128 x 128 plane lies at the current zoom (extends past the widget when
    /// zoomed in).
    QRectF planeRect() const;
    bool selecting(Qt::MouseButtons buttons) const;
    /// The active tool paints cells here (the left button reaches it).
    bool toolPaints() const;
    ToolEvent toolEvent(const QMouseEvent* event, QPoint cell) const;
    void rebuildPlane();
    void rebuildScatter();

    LutDocument& m_lut;
    StreamDocument& m_stream;
    ToolManager& m_tools;
    double m_zoom = 1;
    QPointF m_pan{0, 0}; ///< widget px the plane is moved by
    int m_y_lo = 0;
    int m_y_hi = 127;
    bool m_plane_dirty = true;
    bool m_scatter_dirty = true;
    QImage m_plane;    ///< 128 x 128, the classes
    QImage m_scatter;  ///< 128 x 128, the frame's pixels
    QImage m_outlined; ///< 128 x 128, cells the image tool would change
    std::optional<CellMask> m_selection;
    std::optional<QPoint> m_select_from; ///< cell where the selection drag began
    std::optional<QPoint> m_select_to;
    bool m_tool_down = false;
    std::optional<QPoint> m_cursor;
};

/// The dock's contents: the Y range and the canvas.
class UvPlanePanel : public QWidget
{
    Q_OBJECT
public:
    UvPlanePanel(LutDocument& lut, StreamDocument& stream, ToolManager& tools,
                 QWidget* parent = nullptr);
    UvCanvas& canvas() { return *m_canvas; }
    /// Y range in 8-bit levels (shown), inclusive.
    void setYLevels(int lo, int hi);

private:
    UvCanvas* m_canvas = nullptr;
    QSpinBox* m_y_lo = nullptr;
    QSpinBox* m_y_hi = nullptr;
    QLabel* m_info = nullptr;
};

} // namespace fieldsight::ui
