#include "ui/panels/detections_panel.h"

#include <nlohmann/json.hpp>

namespace fieldsight::ui {

namespace {
constexpr int kBoundsRole = Qt::UserRole + 1;
constexpr int kCollapsedRole = Qt::UserRole + 2; ///< the user closed this list: keep it closed

/// One row as it should read; rows are updated in place, so what the user expanded, collapsed,
/// selected or scrolled to stays while stepping.
struct Row
{
    QString text;
    QString tooltip;
    QVariant bounds;
    QColor foreground;
    std::vector<Row> children;
};
} // namespace

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
    connect(this, &QTreeWidget::itemCollapsed, this,
            [](QTreeWidgetItem* item) { item->setData(0, kCollapsedRole, true); });
    connect(this, &QTreeWidget::itemExpanded, this,
            [](QTreeWidgetItem* item) { item->setData(0, kCollapsedRole, false); });
}

namespace {

void apply(QTreeWidgetItem* item, const Row& row)
{
    if (item->text(0) != row.text)
        item->setText(0, row.text);
    if (item->toolTip(0) != row.tooltip)
        item->setToolTip(0, row.tooltip);
    item->setData(0, kBoundsRole, row.bounds);
    item->setForeground(0, row.foreground.isValid() ? QBrush(row.foreground) : QBrush());
}

/// Makes `parent`'s children read `rows`: reuses the rows there, adds and removes the rest.
template <typename Parent>
void reconcile(Parent* parent, const std::vector<Row>& rows, int (Parent::*count)() const,
               QTreeWidgetItem* (Parent::*child)(int) const)
{
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const int at = int(i);
        QTreeWidgetItem* item = at < (parent->*count)() ? (parent->*child)(at) : nullptr;
        if (!item)
            item = new QTreeWidgetItem(parent);
        apply(item, rows[i]);
        reconcile(item, rows[i].children, &QTreeWidgetItem::childCount, &QTreeWidgetItem::child);
        if (item->childCount() > 0 && !item->isExpanded() &&
            !item->data(0, kCollapsedRole).toBool())
            item->setExpanded(true);
    }
    while ((parent->*count)() > int(rows.size()))
        delete (parent->*child)((parent->*count)() - 1);
}

} // namespace

void DetectionsPanel::showOutput(const FrameOutput* out)
{
    m_serial = out ? out->serial : 0;
    std::vector<Row> rows;
    if (out) {
        if (!out->error.isEmpty())
            rows.push_back({tr("Frame not processed: %1").arg(out->error), out->error, {}, {}, {}});
        for (const PerceptEntry* entry : out->result.percepts.entries()) {
            const QString title = QString::fromUtf8(entry->kind().title.data(),
                                                    qsizetype(entry->kind().title.size()));
            Row top{QStringLiteral("%1 (%2)").arg(title).arg(entry->size()), {}, {}, {}, {}};
            const std::string layer =
                std::string(kPerceptLayerPrefix) + "." + std::string(entry->kind().key);
            for (const PerceptItem& item : out->items) {
                if (item.layer == layer)
                    top.children.push_back(
                        {item.details.section('\n', 1).replace('\n', QStringLiteral(", ")),
                         item.details,
                         item.bounds,
                         {},
                         {}});
            }
            if (top.children.empty() && entry->size() > 0) {
                nlohmann::ordered_json list; // a polyline: say how many points it has
                entry->toJson(PerceptNames::Results, list);
                top.children.push_back(
                    {tr("%1 points").arg(qsizetype(list.size())), {}, {}, {}, {}});
            }
            rows.push_back(std::move(top));
        }
        Row diag{
            tr("Diagnostics (%1)").arg(qsizetype(out->result.diagnostics.size())), {}, {}, {}, {}};
        for (const Diagnostic& d : out->result.diagnostics) {
            const QString text = QString::fromStdString(d.stage + ": " + d.message);
            diag.children.push_back({text, text, {}, QColor(200, 40, 40), {}});
        }
        rows.push_back(std::move(diag));
    }
    setUpdatesEnabled(false);
    reconcile(invisibleRootItem(), rows, &QTreeWidgetItem::childCount, &QTreeWidgetItem::child);
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
