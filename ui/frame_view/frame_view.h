// The frame view: one frame with its overlay layers, painted by the one overlay painter, with
// wheel zoom around the cursor, drag to pan, crisp pixels at every zoom, and hover tooltips on
// detections.
#pragma once

#include "ui/document/annotations_document.h"
#include "ui/worker/frame_worker.h"
#include "ui/document/stream_document.h"
#include "ui/tools/tool_manager.h"
#include "visioncore/services/layers.h"

#include <QPoint>
#include <QPointF>
#include <QWidget>

#include <map>
#include <memory>

namespace fieldsight::ui {

enum class ViewMode {
    Raw,        ///< the frame as a person sees it
    Classified, ///< every pixel through the LUT, in its class's display colour
    SideBySide, ///< raw on the left, classified on the right, both with the overlay
    Blend,      ///< the classified frame over the raw one, half transparent
};

class FrameView : public QWidget
{
    Q_OBJECT
public:
    explicit FrameView(QWidget* parent = nullptr);

    void setOutput(std::shared_ptr<const FrameOutput> output);
    /// Shows `stream`'s frames as they come (a new stream fits the window).
    void setStream(StreamDocument& stream);
    const std::shared_ptr<const FrameOutput>& output() const { return m_output; }

    /// The ground truth drawn over each frame is `annotations`' own, as it is now: an edit is
    /// painted at once, without running the frame again.
    void setAnnotations(const AnnotationsDocument& annotations);

    void setVisibleLayers(LayerSet layers);
    const LayerSet& visibleLayers() const { return m_visible; }
    void setMode(ViewMode mode);
    ViewMode mode() const { return m_mode; }
    void setLabelsShown(bool shown);
    bool labelsShown() const { return m_labels; }

    double zoom() const { return m_zoom; }
    /// Zooms to `zoom` keeping the image point under `anchor` (widget px) where it is.
    void setZoom(double zoom, QPointF anchor);
    void setZoom(double zoom) { setZoom(zoom, rect().center()); }
    void zoomIn();
    void zoomOut();
    /// The whole frame (both panels side by side) fills the view; kept so on resizing.
    void fitToWindow();
    bool fitted() const { return m_fit; }
    /// Where image pixel (0, 0)'s top-left corner is, in widget px (whole pixels).
    QPoint imageOrigin() const { return m_origin; }
    void setImageOrigin(QPoint origin);
    /// Puts image point `point` (pixels) at the view's centre.
    void centreOn(QPointF point);
    /// Image rectangle `rect` (pixels) is wholly in sight.
    bool shows(const QRectF& rect) const;

    /// The image pixel under widget point `pos`, if any.
    std::optional<QPoint> pixelAt(QPointF pos) const;
    /// The detection under widget point `pos`, if any.
    const PerceptItem* itemAt(QPointF pos) const;
    /// The tools the mouse reaches: the left and right buttons go to the active tool (unless it
    /// pans), the middle button always pans; its cursor, outline and preview show here.
    void setTools(ToolManager* tools);

    /// A highlight over the frame, under the overlay: an image of the frame's size, transparent
    /// where nothing is highlighted (a null image removes it). Kept across frames until changed.
    void setHighlight(const QString& id, const QImage& image);
    const QImage& highlight(const QString& id) const;

    /// The detections are drawn faint: an annotation tool is active.
    bool detectionsDimmed() const;

    /// The serial of the output painted last.
    std::uint64_t paintedSerial() const { return m_painted_serial; }
    /// How long the last paint took, ms.
    double lastPaintMs() const { return m_paint_ms; }

signals:
    void pixelHovered(QPoint pixel);
    void hoverLeft();
    void zoomChanged(double zoom);
    void modeChanged(ViewMode mode);
    void labelsShownChanged(bool shown);
    void painted(std::uint64_t serial);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void leaveEvent(QEvent* event) override;
    bool event(QEvent* event) override;

private:
    void followPointer();
    /// The shown frame's truth drawings, from the annotations document.
    void refreshTruth();
    QSize imageSize() const;
    int panelCount() const { return m_mode == ViewMode::SideBySide ? 2 : 1; }
    /// Widget x of panel `panel`'s image origin.
    int panelX(int panel) const;
    /// Image coordinates (pixel-centre convention) of widget point `pos`, and its panel.
    std::optional<QPointF> imagePoint(QPointF pos) const;
    void applyFit();
    bool toolPans() const;
    /// `event` at image pixel `pixel`, for the tools.
    ToolEvent toolEvent(const QMouseEvent& event, QPoint pixel) const;
    /// The active tool's brush outline (image px; < 0: none).
    int brushRadius() const;

    std::shared_ptr<const FrameOutput> m_output;
    const AnnotationsDocument* m_annotations = nullptr;
    std::vector<DebugDrawing> m_truth; ///< the shown frame's, of the visible truth layers
    LayerSet m_visible;
    ViewMode m_mode = ViewMode::Raw;
    bool m_labels = true;
    double m_zoom = 1;
    QPoint m_origin{0, 0};
    bool m_fit = true;
    QSize m_last_size;
    std::optional<QPoint> m_drag_from;
    QPoint m_drag_origin;
    ToolManager* m_tools = nullptr;
    bool m_tool_down = false;
    std::optional<QPoint> m_cursor_pixel; ///< for the brush outline
    std::map<QString, QImage> m_highlights;
    std::uint64_t m_painted_serial = 0;
    double m_paint_ms = 0;
    int m_wheel_delta = 0; ///< eighths of a degree not yet turned into a zoom step
};

} // namespace fieldsight::ui
