// The percept kinds the suites look up: the standard pipeline's, and the kind drawn as a form.
#pragma once

#include "visioncore/framework/controller.h"
#include "visioncore/percepts/percept_set.h"

#include <vector>

namespace fieldsight::test {

/// The standard pipeline's percept kinds (what a stream's annotations hold).
inline std::vector<const PerceptKind*> standardKinds()
{
    return Pipeline::standard().perceptKinds();
}

/// The first of `kinds` drawn as `form`; null when none is.
inline const PerceptKind* kindOfForm(const std::vector<const PerceptKind*>& kinds, ShapeForm form)
{
    for (const PerceptKind* kind : kinds)
        if (kind->form == form)
            return kind;
    return nullptr;
}

/// The first kind of a document (anything with kinds()) drawn as `form`.
template <typename Document> const PerceptKind* kindOfForm(const Document& doc, ShapeForm form)
{
    return kindOfForm(doc.kinds(), form);
}

} // namespace fieldsight::test
