// A tool: what the left mouse button does in the frame view and the UV plane. The views forward
// their mouse events to the active tool (ToolManager); a tool edits documents only through their
// undoable commands, says what it would change under the cursor (its preview), and gives its
// cursor and the outline drawn around it. Adding a tool is its class and one line in
// tool_list.cpp.
#pragma once

#include "visioncore/services/lut_editing.h"

#include <QColor>
#include <QCursor>
#include <QPolygonF>
#include <QKeySequence>
#include <QObject>
#include <QPoint>
#include <QPointF>
#include <QString>

#include <opencv2/core/mat.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QMouseEvent;

namespace fieldsight::ui {

class AnnotationSelection;
class EditingSession;
class LutToolSettings;

/// Where an event happened.
enum class ToolSurface {
    Image,   ///< the frame view: `point` is an image pixel
    UvPlane, ///< the UV plane: `point` is a cell (x = Cb, y = Cr, 7-bit)
};

struct ToolEvent
{
    ToolSurface surface = ToolSurface::Image;
    QPoint point;
    /// `point` to a fraction of a pixel, in the same coordinates (pixel centres at whole
    /// numbers): where in the pixel the pointer is, for tools that place shapes finer than a
    /// pixel (the frame view sets it; else `point`).
    QPointF position;
    Qt::MouseButton button = Qt::NoButton; ///< the button pressed or released (none on a move)
    Qt::MouseButtons buttons = Qt::NoButton;
    Qt::KeyboardModifiers modifiers = Qt::NoModifier;
    int y_lo = 0; ///< the UV plane's Y cells, inclusive
    int y_hi = 127;
    double zoom = 1;           ///< screen px per image px (how near "near" is)
    bool double_click = false; ///< the press is the second of a double click

    /// The event at `point` of `surface` with `mouse`'s buttons and modifiers.
    static ToolEvent of(ToolSurface surface, const QMouseEvent& mouse, QPoint point);
};

/// What a tool would change at the cursor, or has changed in the stroke so far.
struct ToolPreview
{
    cv::Mat pixels;                   ///< CV_8U mask of the frame's pixels affected (or empty)
    std::vector<std::uint32_t> cells; ///< LUT cells it would change
    std::vector<CellChange> changes;  ///< the same, with their classes before and after
    QString text;                     ///< one line for people (empty when none)
};

/// A shape a tool shows over the image (a sample region, an annotated object), in image px with
/// pixel centres at whole numbers.
struct OutlineShape
{
    QPolygonF polygon;  ///< a polygon's corners (corner pixels inclusive), a polyline's points
                        ///< (`closed` false), or a circle's centre
    double radius = -1; ///< >= 0: a circle of this radius around the polygon's one point
    bool closed = true;
    QColor colour;
    bool selected = false;  ///< drawn thicker, with its handles marked
    bool dashed = false;    ///< made by the program (interpolated), not placed by hand
    QPolygonF handles;      ///< marked when selected (empty: the polygon's points)
    int chosen_handle = -1; ///< >= 0: this handle is chosen (Delete acts on it), marked apart
};

struct ToolOutline
{
    int brush_radius = -1; ///< image px (UV plane: cells); < 0: no brush outline
    std::vector<OutlineShape> shapes;
};

/// What the window shows of a tool: its button, menu item and shortcut.
struct ToolInfo
{
    QString id; ///< stable, for settings and tests ("brush")
    QString name;
    QString tooltip;
    QKeySequence shortcut;
    QString icon{};  ///< its icon's name in resources/icons/tools (empty: the id)
    QString group{}; ///< where its button is: empty for the LUT editor's, "annotate"
};

/// What every tool may use.
struct ToolContext
{
    EditingSession& session;
    LutToolSettings& settings;
    AnnotationSelection& selection; ///< the annotated object the annotation tools selected
};

class Tool : public QObject
{
    Q_OBJECT
public:
    explicit Tool(ToolContext& context) : m_context(context) {}

    virtual ToolInfo info() const = 0;
    /// The left button pans the view instead of reaching the tool (and selects in the UV plane).
    virtual bool pans() const { return false; }
    virtual bool accepts(ToolSurface surface) const { return surface == ToolSurface::Image; }

    virtual void press(const ToolEvent&) {}
    /// The mouse moved with a button down.
    virtual void move(const ToolEvent&) {}
    virtual void release(const ToolEvent&) {}
    /// The pointer is over image pixel `pixel` with no button down (none: off the image).
    virtual void hover(std::optional<QPoint> pixel) { (void)pixel; }
    /// A key pressed in the frame view (Qt::Key); true when the tool used it.
    virtual bool key(int key)
    {
        (void)key;
        return false;
    }
    /// The tool stops being the active one (a stroke in progress ends).
    virtual void deactivate() {}

    /// What the tool would do at image pixel `pixel` (none: the cursor is off the image).
    virtual ToolPreview preview(std::optional<QPoint> pixel) const
    {
        (void)pixel;
        return {};
    }
    virtual QCursor cursor() const { return Qt::CrossCursor; }
    /// Edit > Delete: removes what the tool has selected (as an undoable edit); false when
    /// nothing was selected.
    virtual bool deleteSelection() { return false; }
    virtual ToolOutline outline() const { return {}; }

signals:
    /// The tool's own preview changed without the cursor moving (a stroke, a rectangle).
    void previewChanged();

protected:
    ToolContext& m_context;
};

/// Makes the tools of one line of the tool list: one tool, or one per something of the pipeline
/// (annotateTools(): one per kind drawn by hand).
using ToolFactory = std::function<std::vector<std::unique_ptr<Tool>>(ToolContext&)>;

template <class T> ToolFactory toolFactory()
{
    return [](ToolContext& context) {
        std::vector<std::unique_ptr<Tool>> one;
        one.push_back(std::make_unique<T>(context));
        return one;
    };
}

/// THE tools, in the order of their buttons (tool_list.cpp).
std::vector<ToolFactory> standardTools();

} // namespace fieldsight::ui
