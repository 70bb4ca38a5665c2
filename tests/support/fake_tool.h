// A tool for tests, added to the window by a test alone (one line where tool_list.cpp would get
// it): a press in the image bookmarks the current frame with where it was pressed (an undoable
// command, as every tool's edit), its preview lights the 3 x 3 pixels under the cursor, and it
// counts the events it received.
#pragma once

#include "ui/document/editing_session.h"
#include "ui/tools/tool.h"

#include <opencv2/imgproc.hpp>

namespace fieldsight::test {

class FakeTool : public ui::Tool
{
public:
    using Tool::Tool;

    static inline int presses = 0;
    static inline int moves = 0;
    static inline int releases = 0;

    ui::ToolInfo info() const override
    {
        return {QStringLiteral("fake"), QStringLiteral("Fake"),
                QStringLiteral("Marks the frame where it is pressed"), QKeySequence(Qt::Key_J)};
    }
    void press(const ui::ToolEvent& event) override
    {
        ++presses;
        if (event.button != Qt::LeftButton)
            return;
        ui::StreamDocument& stream = m_context.session.stream();
        m_context.session.bookmarks().setBookmark(
            stream.currentIndex(), stream.frameName(stream.currentIndex()),
            QStringLiteral("fake at %1,%2").arg(event.point.x()).arg(event.point.y()));
    }
    void move(const ui::ToolEvent&) override { ++moves; }
    void release(const ui::ToolEvent&) override { ++releases; }
    ui::ToolPreview preview(std::optional<QPoint> pixel) const override
    {
        ui::ToolPreview p;
        const auto& out = m_context.session.stream().current();
        if (!pixel || !out || out->frame.ycbcr.empty())
            return p;
        p.pixels = cv::Mat(out->frame.ycbcr.rows, out->frame.ycbcr.cols, CV_8U, cv::Scalar(0));
        cv::rectangle(p.pixels, cv::Rect(pixel->x() - 1, pixel->y() - 1, 3, 3), cv::Scalar(255),
                      cv::FILLED);
        p.text = QStringLiteral("Fake at %1,%2").arg(pixel->x()).arg(pixel->y());
        return p;
    }
    ui::ToolOutline outline() const override { return {3, {}}; }
};

} // namespace fieldsight::test
