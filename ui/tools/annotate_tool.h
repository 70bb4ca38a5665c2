// Drawing ground truth: one tool per percept kind the pipeline draws by hand, made from the kind's
// ShapeForm alone (it names no kind). A circle is pressed at its centre and dragged to its rim, a
// box dragged corner to corner, a segment end to end; a polyline (at most one a frame) is clicked
// point by point and ended with a double click or Enter (Escape drops it). A click selects the
// nearest object of the kind, a drag moves it, its handles resize it (a polyline's points move,
// a click on its line adds one), Edit > Delete removes it: each an undoable edit of the
// annotations document, a drag one step. A new object starts a track of its own; an object
// edited by hand on a track with keyframes becomes a keyframe, and the track is interpolated
// again.
#pragma once

#include "ui/tools/tool.h"

#include "visioncore/io/annotations.h"

#include <optional>
#include <string>
#include <vector>

namespace fieldsight::ui {

class AnnotateTool : public Tool
{
    Q_OBJECT
public:
    /// The tool for `kind`, the `ordinal`-th kind drawn by hand (its shortcut is Shift+ordinal).
    AnnotateTool(ToolContext& context, const PerceptKind& kind, int ordinal);

    ToolInfo info() const override;
    void press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    void release(const ToolEvent& event) override;
    void hover(std::optional<QPoint> pixel) override;
    bool key(int key) override;
    void deactivate() override;
    ToolPreview preview(std::optional<QPoint> pixel) const override;
    ToolOutline outline() const override;
    bool deleteSelection() override;

    const PerceptKind& kind() const { return m_kind; }
    /// The selected object's index on the frame shown, if it is one of this tool's kind.
    std::optional<std::size_t> selected() const;
    /// The points of a polyline being drawn (empty: none).
    const std::vector<PointF>& draft() const { return m_draft; }

private:
    /// A drag of an existing object: moving it whole, or one of its handles.
    struct Drag
    {
        std::size_t index = 0;
        std::optional<std::size_t> handle; ///< none: the whole object moves
        PointF from;                       ///< where the press was
        EditShape start;                   ///< the shape when the drag began
        ObjectFlags flags;                 ///< the object's flags after the edit
        QString text;                      ///< the undo step's name
        int merge = 0;                     ///< the document's merge id: the drag is one step
        bool edited = false;
    };

    std::vector<EditShape> currentShapes() const;
    /// The object of the kind nearest `p` within `tolerance` px (inside a shape is nearest, the
    /// smallest one first).
    std::optional<std::size_t> objectAt(const std::vector<EditShape>& shapes, PointF p,
                                        double tolerance) const;
    void select(std::size_t index);
    /// Writes `shape` as object `index` of the frame shown, as part of the drag.
    void dragTo(const EditShape& shape);
    /// After a drag: the object's track is interpolated again (in the drag's step).
    void finishDrag();
    void finishDraft();
    void cancel();
    /// The selection follows its track to the frame now shown, or is dropped.
    void followTrack();
    /// The flags of an object edited by hand: on a track with keyframes it becomes one.
    ObjectFlags touched(ObjectFlags flags) const;

    const PerceptKind& m_kind;
    int m_ordinal;
    std::string m_frame; ///< the frame shown (the stream's name), for following the selection
    std::optional<Drag> m_drag;
    std::optional<PointF> m_create_from; ///< a new object's first point, while dragging
    PointF m_create_to;
    std::vector<PointF> m_draft; ///< a polyline being drawn
    std::optional<PointF> m_hover;
    /// The polyline point pressed last on the selected line: Delete removes that point alone.
    std::optional<std::size_t> m_point;
    double m_zoom = 1; ///< screen px per image px at the last press
};

/// One AnnotateTool per kind of the pipeline drawn by hand (ShapeForm not None), in the
/// pipeline's order: the one line the tool list has for them.
ToolFactory annotateTools();

} // namespace fieldsight::ui
