// The layer list, made from the stage registry: every stage's debug layers grouped under the
// stage, then the ground truth and the detections, each with its legend colour and a switch; and
// the legend of the colour classes.
#pragma once

#include "visioncore/framework/controller.h"
#include "visioncore/services/layers.h"

#include <QTreeWidget>

namespace fieldsight::ui {

class LayersPanel : public QTreeWidget
{
    Q_OBJECT
public:
    explicit LayersPanel(const Pipeline& pipeline, QWidget* parent = nullptr);

    LayerSet visibleLayers() const;
    void setVisibleLayers(const LayerSet& layers);
    /// The layers shown when nothing was remembered: the detections and the ground truth.
    static LayerSet defaultLayers(const Pipeline& pipeline);
    /// The item of a layer, for tests and for finding a layer by id.
    QTreeWidgetItem* layerItem(const QString& id) const;

signals:
    void visibleLayersChanged(const LayerSet& layers);

private:
    bool m_updating = false;
};

} // namespace fieldsight::ui
