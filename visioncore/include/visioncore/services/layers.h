// What a frame's overlay is made of: every layer a host can show (the stages' debug layers, the
// ground truth and the percepts, each with its legend colour), choosing layers by name, and the
// drawings of one frame in drawing order. How to paint them is ui/'s one painter.
#pragma once

#include "visioncore/framework/controller.h"
#include "visioncore/basics/debug_drawing.h"
#include "visioncore/percepts/percept_set.h"
#include "visioncore/basics/result.h"

#include <set>
#include <string>
#include <vector>

namespace fieldsight {

using LayerSet = std::set<std::string, std::less<>>;

/// Every layer, in drawing order: the stages' layers (pipeline order), then the truth layers,
/// then the percept layers on top.
std::vector<LayerInfo> allLayers(const Pipeline& pipeline);

/// Expands a comma-separated list of names into layer ids. A name is "all", a layer id, or a
/// group: a stage id (its layers), "truth" or "percepts". An unknown name is an error that lists
/// the groups.
Result<LayerSet> selectLayers(const std::string& list, const Pipeline& pipeline);

/// The drawings of one frame whose id is in `wanted`, in drawing order: the stage layers the core
/// published into `canvas`, then `percepts`, then `truth` (if any) over them: the painter draws
/// truth dashed, so a detection on its true object does not hide it.
std::vector<DebugDrawing> frameDrawings(const Pipeline& pipeline, const LayerSet& wanted,
                                        const DebugCanvas& canvas, const PerceptSet& percepts,
                                        const PerceptSet* truth);

} // namespace fieldsight
