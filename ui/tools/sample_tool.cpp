#include "ui/tools/sample_tool.h"

#include "ui/adapters/image_adapter.h"
#include "ui/adapters/local_path.h"
#include "ui/document/editing_session.h"
#include "ui/tools/lut_edit_tool.h"
#include "ui/tools/lut_tool_settings.h"

#include <QRect>

#include <opencv2/imgproc.hpp>

namespace fieldsight::ui {

ToolInfo SampleTool::info() const
{
    return {QStringLiteral("sample"), tr("Sample"),
            tr("Drag a rectangle: a sample region of the class, kept beside the stream to build "
               "the LUT from (and again after the light changes)"),
            QKeySequence(Qt::Key_S)};
}

void SampleTool::press(const ToolEvent& event)
{
    if (event.button == Qt::RightButton)
        pickColourAt(m_context, event.point);
    if (event.button != Qt::LeftButton)
        return;
    m_from = m_to = event.point;
    emit previewChanged();
}

void SampleTool::move(const ToolEvent& event)
{
    if (!m_from)
        return;
    m_to = event.point;
    emit previewChanged();
}

void SampleTool::release(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton || !m_from || !m_to)
        return;
    const QRect r = QRect(*m_from, *m_to).normalized();
    const auto& out = m_context.session.stream().current();
    if (out && r.width() >= 2 && r.height() >= 2)
        m_context.session.samples().addRect(fromLocalPath(out->frame.name),
                                            m_context.settings.colour(), r);
    deactivate();
}

void SampleTool::deactivate()
{
    m_from.reset();
    m_to.reset();
    emit previewChanged();
}

ToolPreview SampleTool::preview(std::optional<QPoint>) const
{
    ToolPreview p;
    const auto& out = m_context.session.stream().current();
    if (!m_from || !m_to || !out || out->frame.ycbcr.empty())
        return p;
    // The rectangle so far, in the image.
    const cv::Mat& image = out->frame.ycbcr;
    p.pixels = cv::Mat(image.rows, image.cols, CV_8U, cv::Scalar(0));
    const QRect r = QRect(*m_from, *m_to).normalized();
    cv::rectangle(p.pixels, cv::Rect(r.left(), r.top(), r.width(), r.height()), cv::Scalar(255),
                  cv::FILLED);
    p.text = tr("Sample %1 × %2 px → %3")
                 .arg(r.width())
                 .arg(r.height())
                 .arg(colourLabel(m_context.settings.colour()));
    return p;
}

} // namespace fieldsight::ui
