// What the tools that change the colour table share: the plan of an edit at a pixel becomes both
// the preview and the undoable edit; the right button picks the class under the cursor; in the UV
// plane the left button paints the tool's class on the cells under a round brush.
#pragma once

#include "ui/tools/tool.h"

namespace fieldsight::ui {

/// What a tool would do: the changes and the undo step's name.
struct PlannedEdit
{
    QString text;
    std::vector<CellChange> changes;
};

class LutEditTool : public Tool
{
    Q_OBJECT
public:
    using Tool::Tool;

    bool accepts(ToolSurface) const override { return true; }
    void press(const ToolEvent& event) override;
    void move(const ToolEvent& event) override;
    void release(const ToolEvent& event) override;
    void deactivate() override;
    ToolPreview preview(std::optional<QPoint> pixel) const override;
    ToolOutline outline() const override;

    /// What the tool would do at image pixel `pixel` of the current frame (none off the frame).
    virtual std::optional<PlannedEdit> plan(QPoint pixel) const = 0;

protected:
    /// The class the tool paints (unclassified for the eraser).
    virtual Colour target() const;
    /// The image press of a tool that applies its plan once (a brush strokes instead).
    virtual void pressImage(QPoint pixel);
    virtual void dragImage(QPoint pixel) { (void)pixel; }
    virtual bool brushOutline() const { return false; }

    /// The current frame's Y, Cb, Cr pixels (null before the first frame).
    const cv::Mat* frame() const;
    /// The same, when `pixel` is inside it (null otherwise).
    const cv::Mat* frameAt(QPoint pixel) const;
    /// Applies `plan` as one undo step (merged into `stroke` when nonzero); remembers its cells.
    void apply(PlannedEdit plan, int stroke = 0);
    /// The changes setting `cells` to the target class makes with the shared settings.
    std::vector<CellChange> changesFor(const std::vector<std::uint32_t>& cells, bool erase) const;

    int m_stroke = 0;                          ///< the stroke under way (0: none)
    std::vector<std::uint32_t> m_stroke_cells; ///< what it has changed so far
    std::optional<cv::Point> m_last;           ///< the stroke's last point
    ToolSurface m_stroke_surface = ToolSurface::Image;

private:
    void dabUv(const ToolEvent& event);
};

/// Makes the class under image pixel `pixel` of the current frame the one the tools paint (what
/// the right button does with every LUT tool).
void pickColourAt(ToolContext& context, QPoint pixel);

/// The preview of `changes` on `frame`: their pixels, cells and the cells taken by class.
ToolPreview previewOfChanges(std::vector<CellChange> changes, const cv::Mat* frame);

} // namespace fieldsight::ui
