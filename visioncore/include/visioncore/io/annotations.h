// Ground-truth annotations (SPEC §5.2, fieldsight-annotations/1): per frame, the true percepts.
#pragma once

#include "visioncore/framework/controller.h"
#include "visioncore/percepts/percept_set.h"
#include "visioncore/result.h"

#include <map>
#include <string>

namespace fieldsight {

struct FrameAnnotation
{
    bool done = false; ///< fully annotated: what is absent is truly absent
    PerceptSet truth;  ///< read and written with the percepts' truth keys ("field_boundary")
};

struct Annotations
{
    std::map<std::string, FrameAnnotation> frames; ///< by frame name

    /// Reads the percept kinds of `pipeline`; other keys of a frame are ignored.
    static Result<Annotations> load(const std::string& path,
                                    const Pipeline& pipeline = Pipeline::standard());
    static Result<Annotations> fromJson(const std::string& text, const std::string& source,
                                        const Pipeline& pipeline = Pipeline::standard());
    std::string toJson() const;
    Status save(const std::string& path) const; ///< atomic
};

} // namespace fieldsight
