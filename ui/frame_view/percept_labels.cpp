// The detections' labels over the frame view.
#include "ui/frame_view/percept_labels.h"

#include <QPainter>

#include <algorithm>

namespace fieldsight::ui {

void paintPerceptLabels(QPainter& p, const std::vector<PerceptItem>& items, const LayerSet& visible,
                        QPointF origin, double zoom, double opacity)
{
    p.save();
    p.setOpacity(opacity);
    p.setPen(Qt::white);
    QFont font = p.font();
    font.setPointSizeF(8);
    p.setFont(font);
    std::vector<QRectF> placed;
    const auto covers = [&placed](const QRectF& r) {
        return std::any_of(placed.begin(), placed.end(),
                           [&r](const QRectF& q) { return q.intersects(r); });
    };
    for (const PerceptItem& item : items) {
        if (!visible.count(item.layer))
            continue;
        QPointF at(origin.x() + (item.bounds.left() + 0.5) * zoom,
                   origin.y() + (item.bounds.top() + 0.5) * zoom - 4);
        QRectF box =
            p.fontMetrics().boundingRect(item.label).translated(at.toPoint()).adjusted(-2, 0, 2, 0);
        for (int line = 0; line < 12 && covers(box); ++line) {
            box.translate(0, box.height() + 1);
            at.ry() += box.height() + 1;
        }
        placed.push_back(box);
        p.fillRect(box, QColor(0, 0, 0, 160));
        p.drawText(at, item.label);
    }
    p.restore();
}

} // namespace fieldsight::ui
