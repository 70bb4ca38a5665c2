#include "ui/panels/layers_panel.h"

#include "ui/adapters/image_adapter.h"

#include <QHeaderView>
#include <QPainter>

namespace fieldsight::ui {

namespace {

constexpr int kIdRole = Qt::UserRole + 1;

QIcon swatch(const LayerInfo& layer)
{
    QPixmap pixmap(16, 16);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setPen(QColor(20, 20, 20));
    if (layer.by_colour_class) {
        // Coloured by class: a strip of the class colours.
        const int classes[] = {1, 2, 6, 8, 9};
        for (int i = 0; i < 5; ++i)
            p.fillRect(1 + i * 3, 2, 3, 12, toQColor(colourDisplayRgb(Colour(classes[i]))));
    } else {
        p.fillRect(2, 2, 12, 12, toQColor(layer.colour));
    }
    p.drawRect(1, 1, 14, 14);
    return QIcon(pixmap);
}

QString group(const std::string& id)
{
    return QString::fromStdString(id.substr(0, id.find('.')));
}

} // namespace

LayersPanel::LayersPanel(const Pipeline& pipeline, QWidget* parent) : QTreeWidget(parent)
{
    setObjectName(QStringLiteral("layers"));
    setHeaderHidden(true);
    setColumnCount(1);
    setUniformRowHeights(true);

    std::map<QString, QTreeWidgetItem*> groups;
    auto groupItem = [&](const QString& key, const QString& title) {
        auto it = groups.find(key);
        if (it != groups.end())
            return it->second;
        auto* item = new QTreeWidgetItem(this, {title});
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsAutoTristate);
        item->setCheckState(0, Qt::Unchecked);
        item->setExpanded(true);
        return groups[key] = item;
    };
    for (const StageDescriptor& stage : pipeline.descriptors())
        if (!stage.info.layers.empty())
            groupItem(QString::fromStdString(stage.info.id),
                      QString::fromStdString(stage.info.name));
    for (const LayerInfo& layer : allLayers(pipeline)) {
        const QString key = group(layer.id);
        QString title = key;
        if (key == QLatin1String(kTruthLayerPrefix.data(), qsizetype(kTruthLayerPrefix.size())))
            title = tr("Ground truth");
        else if (key ==
                 QLatin1String(kPerceptLayerPrefix.data(), qsizetype(kPerceptLayerPrefix.size())))
            title = tr("Detections");
        auto* item =
            new QTreeWidgetItem(groupItem(key, title), {QString::fromStdString(layer.name)});
        item->setData(0, kIdRole, QString::fromStdString(layer.id));
        item->setToolTip(0, QString::fromStdString(layer.id));
        item->setIcon(0, swatch(layer));
        item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable);
        item->setCheckState(0, Qt::Unchecked);
    }

    auto* legend = new QTreeWidgetItem(this, {tr("Colour classes (classified view)")});
    legend->setFlags(Qt::ItemIsEnabled);
    for (int c = 0; c < kColourCount; ++c) {
        auto* item = new QTreeWidgetItem(
            legend, {QStringLiteral("%1  %2").arg(c).arg(colourLabel(Colour(c)))});
        item->setIcon(0, colourSwatch(Colour(c)));
        item->setFlags(Qt::ItemIsEnabled);
    }
    legend->setExpanded(false);

    connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem*, int) {
        if (!m_updating)
            emit visibleLayersChanged(visibleLayers());
    });
}

LayerSet LayersPanel::visibleLayers() const
{
    LayerSet layers;
    for (QTreeWidgetItemIterator it(const_cast<LayersPanel*>(this)); *it; ++it) {
        const QString id = (*it)->data(0, kIdRole).toString();
        if (!id.isEmpty() && (*it)->checkState(0) == Qt::Checked)
            layers.insert(id.toStdString());
    }
    return layers;
}

void LayersPanel::setVisibleLayers(const LayerSet& layers)
{
    m_updating = true;
    for (QTreeWidgetItemIterator it(this); *it; ++it) {
        const QString id = (*it)->data(0, kIdRole).toString();
        if (!id.isEmpty())
            (*it)->setCheckState(0, layers.count(id.toStdString()) ? Qt::Checked : Qt::Unchecked);
    }
    m_updating = false;
    emit visibleLayersChanged(visibleLayers());
}

QTreeWidgetItem* LayersPanel::layerItem(const QString& id) const
{
    for (QTreeWidgetItemIterator it(const_cast<LayersPanel*>(this)); *it; ++it)
        if ((*it)->data(0, kIdRole).toString() == id)
            return *it;
    return nullptr;
}

LayerSet LayersPanel::defaultLayers(const Pipeline& pipeline)
{
    // What was found and what is true; the stages' own layers (every scan line, segment and
    // point) are switched on by the user, stage by stage, when looking into one.
    LayerSet layers;
    for (const LayerInfo& layer : allLayers(pipeline)) {
        const std::string_view id = layer.id;
        if (id.rfind(kPerceptLayerPrefix, 0) == 0 || id.rfind(kTruthLayerPrefix, 0) == 0)
            layers.insert(layer.id);
    }
    return layers;
}

} // namespace fieldsight::ui
