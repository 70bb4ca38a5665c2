#include "ui/tools/sample_tool.h"

#include "ui/adapters/image_adapter.h"
#include "ui/adapters/local_path.h"
#include "ui/document/editing_session.h"
#include "ui/tools/lut_edit_tool.h"
#include "ui/tools/lut_tool_settings.h"

#include <QRect>

#include <utility>

#include <opencv2/imgproc.hpp>

namespace fieldsight::ui {

SampleTool::SampleTool(ToolContext& context) : Tool(context)
{
    // The outline shows the document's samples: redrawn when they change or the frame does.
    SamplesDocument& samples = context.session.samples();
    connect(&samples, &SamplesDocument::samplesChanged, this, [this] {
        if (m_selected && *m_selected >= m_context.session.samples().samples().samples.size())
            m_selected.reset();
        emit previewChanged();
    });
    connect(&context.session.stream(), &StreamDocument::currentIndexChanged, this, [this] {
        m_selected.reset();
        emit previewChanged();
    });
}

ToolInfo SampleTool::info() const
{
    return {QStringLiteral("sample"), tr("Sample"),
            tr("Drag a rectangle: a sample region of the class, kept beside the stream to build "
               "the LUT from (and again after the light changes). Click one to select it, drag "
               "to move it, Delete removes it"),
            QKeySequence(Qt::Key_S)};
}

bool SampleTool::onCurrentFrame(std::size_t index) const
{
    const auto& out = m_context.session.stream().current();
    const auto& all = m_context.session.samples().samples().samples;
    return out && index < all.size() && all[index].frame == out->frame.name;
}

std::optional<std::size_t> SampleTool::sampleAt(QPoint point) const
{
    const auto& all = m_context.session.samples().samples().samples;
    for (std::size_t i = all.size(); i-- > 0;) {
        if (!onCurrentFrame(i))
            continue;
        QPolygon polygon;
        for (const cv::Point& p : all[i].polygon)
            polygon << QPoint(p.x, p.y);
        if (polygon.boundingRect().contains(point))
            return i;
    }
    return std::nullopt;
}

void SampleTool::press(const ToolEvent& event)
{
    if (event.button == Qt::RightButton)
        pickColourAt(m_context, event.point);
    if (event.button != Qt::LeftButton)
        return;
    if (const auto hit = sampleAt(event.point)) {
        m_selected = hit;
        m_grab = event.point;
        m_offset = {};
    } else {
        m_selected.reset();
        m_from = m_to = event.point;
    }
    emit previewChanged();
}

void SampleTool::move(const ToolEvent& event)
{
    if (m_grab)
        m_offset = event.point - *m_grab;
    else if (m_from)
        m_to = event.point;
    else
        return;
    emit previewChanged();
}

void SampleTool::release(const ToolEvent& event)
{
    if (event.button != Qt::LeftButton)
        return;
    SamplesDocument& samples = m_context.session.samples();
    if (m_grab) {
        const QPoint offset = std::exchange(m_offset, QPoint());
        m_grab.reset();
        if (m_selected && !offset.isNull() && onCurrentFrame(*m_selected)) {
            std::vector<LutSample> moved = samples.samples().samples;
            for (cv::Point& p : moved[*m_selected].polygon)
                p += cv::Point(offset.x(), offset.y());
            samples.setSamples(std::move(moved), tr("Move sample"));
        }
        emit previewChanged();
        return;
    }
    if (!m_from || !m_to)
        return;
    const QRect r = QRect(*m_from, *m_to).normalized();
    const auto& out = m_context.session.stream().current();
    if (out && r.width() >= 2 && r.height() >= 2) {
        samples.addRect(fromLocalPath(out->frame.name), m_context.settings.colour(), r);
        m_selected = samples.samples().samples.size() - 1;
    }
    m_from.reset();
    m_to.reset();
    emit previewChanged();
}

void SampleTool::deactivate()
{
    m_from.reset();
    m_to.reset();
    m_grab.reset();
    m_offset = {};
    m_selected.reset();
    emit previewChanged();
}

bool SampleTool::deleteSelection()
{
    if (!m_selected || !onCurrentFrame(*m_selected))
        return false;
    SamplesDocument& samples = m_context.session.samples();
    std::vector<LutSample> kept = samples.samples().samples;
    kept.erase(kept.begin() + std::ptrdiff_t(*m_selected));
    m_selected.reset();
    samples.setSamples(std::move(kept), tr("Delete sample"));
    return true;
}

ToolOutline SampleTool::outline() const
{
    ToolOutline outline;
    const auto& all = m_context.session.samples().samples().samples;
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (!onCurrentFrame(i))
            continue;
        OutlineShape shape;
        const bool selected = m_selected == i;
        const QPoint shift = selected ? m_offset : QPoint();
        for (const cv::Point& p : all[i].polygon)
            shape.polygon << QPoint(p.x, p.y) + shift;
        shape.colour = toQColor(colourDisplayRgb(all[i].colour));
        shape.selected = selected;
        outline.shapes.push_back(std::move(shape));
    }
    return outline;
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
