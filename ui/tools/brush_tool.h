// Brush: every colour under a round brush dragged over the image becomes the class; the stroke,
// however long, is one undo step. The eraser is the brush that unclassifies.
#pragma once

#include "ui/tools/lut_edit_tool.h"

namespace fieldsight::ui {

class BrushTool : public LutEditTool
{
    Q_OBJECT
public:
    using LutEditTool::LutEditTool;
    ToolInfo info() const override;
    /// One dab at `pixel`.
    std::optional<PlannedEdit> plan(QPoint pixel) const override;

protected:
    void pressImage(QPoint pixel) override;
    void dragImage(QPoint pixel) override;
    bool brushOutline() const override { return true; }
    virtual bool erases() const { return false; }
    Colour target() const override;

private:
    /// The edit of brushing `pixels`.
    PlannedEdit stroke(const std::vector<cv::Point>& pixels) const;
};

class EraseTool : public BrushTool
{
    Q_OBJECT
public:
    using BrushTool::BrushTool;
    ToolInfo info() const override;

protected:
    bool erases() const override { return true; }
};

} // namespace fieldsight::ui
