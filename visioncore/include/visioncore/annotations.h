// Ground-truth annotations (SPEC §5.2, fieldsight-annotations/1).
#pragma once

#include "visioncore/geometry.h"
#include "visioncore/percepts/ball.h"
#include "visioncore/percepts/field_line.h"
#include "visioncore/percepts/goalpost.h"
#include "visioncore/percepts/obstacle.h"
#include "visioncore/result.h"

#include <map>
#include <string>
#include <vector>

namespace fieldsight {

struct FrameAnnotation
{
    bool done = false; ///< fully annotated: what is absent is truly absent
    std::vector<Ball> balls;
    std::vector<Goalpost> goalposts; ///< left/right/top/bottom used; base is derived
    std::vector<Obstacle> obstacles;
    std::vector<PointF> field_boundary; ///< polyline, x ascending
    std::vector<FieldLine> field_lines;
};

struct Annotations
{
    std::map<std::string, FrameAnnotation> frames; ///< by frame name

    static Result<Annotations> load(const std::string& path);
    static Result<Annotations> fromJson(const std::string& text, const std::string& source);
    std::string toJson() const;
    Status save(const std::string& path) const; ///< atomic
};

} // namespace fieldsight
