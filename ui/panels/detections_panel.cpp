#include "ui/panels/detections_panel.h"

#include <nlohmann/json.hpp>

namespace fieldsight::ui {

namespace {
constexpr int kBoundsRole = Qt::UserRole + 1;
}

DetectionsPanel::DetectionsPanel(QWidget* parent) : QTreeWidget(parent)
{
    setObjectName(QStringLiteral("detections"));
    setHeaderHidden(true);
    setColumnCount(1);
    connect(this, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item, int) {
        const QVariant bounds = item->data(0, kBoundsRole);
        if (bounds.isValid())
            emit detectionActivated(bounds.toRectF());
    });
}

void DetectionsPanel::showOutput(const FrameOutput* out)
{
    setUpdatesEnabled(false);
    clear();
    if (out) {
        if (!out->error.isEmpty())
            new QTreeWidgetItem(this, {tr("Frame not processed: %1").arg(out->error)});
        for (const PerceptEntry* entry : out->result.percepts.entries()) {
            const QString title = QString::fromUtf8(entry->kind().title.data(),
                                                    qsizetype(entry->kind().title.size()));
            auto* top = new QTreeWidgetItem(
                this, {QStringLiteral("%1 (%2)").arg(title).arg(entry->size())});
            const std::string layer =
                std::string(kPerceptLayerPrefix) + "." + std::string(entry->kind().key);
            bool listed = false;
            for (const PerceptItem& item : out->items) {
                if (item.layer != layer)
                    continue;
                auto* row = new QTreeWidgetItem(
                    top, {item.details.section('\n', 1).replace('\n', QStringLiteral(", "))});
                row->setToolTip(0, item.details);
                row->setData(0, kBoundsRole, item.bounds);
                listed = true;
            }
            if (!listed && entry->size() > 0) {
                nlohmann::ordered_json list; // a polyline: say how many points it has
                entry->toJson(PerceptNames::Results, list);
                new QTreeWidgetItem(top, {tr("%1 points").arg(qsizetype(list.size()))});
            }
            top->setExpanded(true);
        }
        auto* diag = new QTreeWidgetItem(
            this, {tr("Diagnostics (%1)").arg(qsizetype(out->result.diagnostics.size()))});
        for (const Diagnostic& d : out->result.diagnostics) {
            auto* row =
                new QTreeWidgetItem(diag, {QString::fromStdString(d.stage + ": " + d.message)});
            row->setForeground(0, QColor(200, 40, 40));
        }
        diag->setExpanded(true);
    }
    setUpdatesEnabled(true);
}

QStringList DetectionsPanel::topLevelTexts() const
{
    QStringList texts;
    for (int i = 0; i < topLevelItemCount(); ++i)
        texts << topLevelItem(i)->text(0);
    return texts;
}

} // namespace fieldsight::ui
