// Layer lists, layer selection and the drawing order of a frame's overlay.
#include "visioncore/services/layers.h"

#include <algorithm>

namespace fieldsight {

std::vector<LayerInfo> allLayers(const Pipeline& pipeline)
{
    std::vector<LayerInfo> layers = pipeline.layers();
    const std::vector<const PerceptKind*> kinds = pipeline.perceptKinds();
    const std::vector<std::string> truth_ids = perceptLayerIds(kinds, true);
    const std::vector<std::string> percept_ids = perceptLayerIds(kinds, false);
    for (std::size_t i = 0; i < kinds.size(); ++i)
        layers.push_back({truth_ids[i], std::string(kinds[i]->title) + " (truth)", kTruthColour});
    for (std::size_t i = 0; i < kinds.size(); ++i)
        layers.push_back({percept_ids[i], std::string(kinds[i]->title), kinds[i]->colour});
    return layers;
}

Result<LayerSet> selectLayers(const std::string& list, const Pipeline& pipeline)
{
    const std::vector<LayerInfo> layers = allLayers(pipeline);
    LayerSet selected;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t comma = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, comma - start);
        start = comma + 1;
        if (name.empty())
            continue;
        bool known = false;
        for (const LayerInfo& layer : layers) {
            if (name == "all" || layer.id == name || layer.id.rfind(name + ".", 0) == 0) {
                selected.insert(layer.id);
                known = true;
            }
        }
        if (!known)
            return Error{"unknown layer '" + name +
                         "' (use all, truth, percepts, a "
                         "stage id (" +
                         pipeline.idList() + ") or a layer id)"};
    }
    return selected;
}

std::vector<DebugDrawing> frameDrawings(const Pipeline& pipeline, const LayerSet& wanted,
                                        const DebugCanvas& canvas, const PerceptSet& percepts,
                                        const PerceptSet* truth)
{
    std::vector<DebugDrawing> out;
    for (const LayerInfo& layer : pipeline.layers()) {
        if (!wanted.count(layer.id))
            continue;
        const auto it = canvas.drawings().find(layer.id);
        if (it != canvas.drawings().end())
            out.push_back(it->second);
    }
    for (DebugDrawing& d : percepts.drawings(false))
        if (wanted.count(d.layer))
            out.push_back(std::move(d));
    // The truth goes over the detections: drawn dashed and thin, it shows where the two lie on
    // top of each other (a detection drawn last would hide it).
    if (truth)
        for (DebugDrawing& d : truthDrawings(wanted, *truth))
            out.push_back(std::move(d));
    return out;
}

std::vector<DebugDrawing> truthDrawings(const LayerSet& wanted, const PerceptSet& truth)
{
    std::vector<DebugDrawing> out;
    for (DebugDrawing& d : truth.drawings(true))
        if (wanted.count(d.layer))
            out.push_back(std::move(d));
    return out;
}

} // namespace fieldsight
