// Annotations as COCO JSON (the object-detection format CVAT, Label Studio and most training
// code read): one image per annotated frame, one category per drawn percept kind, boxes as
// [x, y, w, h]; the field boundary and lines as polylines in an extra field (docs/formats.md).
#pragma once

#include "visioncore/io/annotations.h"
#include "visioncore/io/stream_reader.h"

#include <string>
#include <vector>

namespace fieldsight {

/// The frames annotations are exported for: their names and size as served (upright).
struct CocoStream
{
    std::string path;
    std::vector<std::string> frame_names; ///< by stream index
    int width = 0;                        ///< px
    int height = 0;                       ///< px
    Orientation orientation = Orientation::Upright;

    static CocoStream of(const StreamReader& reader);
};

/// COCO JSON text of every annotated frame of `annotations`, the frames found in `stream` by
/// name or by stem (frameStem). Categories are the kinds of `kinds` an annotator draws
/// (PerceptKind::form not None), in that order, named by truth key. A frame the stream lacks is
/// an Error naming `source` (the annotations file) and the frame.
Result<std::string> cocoJson(const Annotations& annotations, const CocoStream& stream,
                             const std::vector<const PerceptKind*>& kinds,
                             const std::string& source);

} // namespace fieldsight
