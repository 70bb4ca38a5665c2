// Field line percept: one straight white line as an image segment.
#pragma once

namespace fieldsight {

struct FieldLine
{
    double x1 = 0; ///< px
    double y1 = 0; ///< px
    double x2 = 0; ///< px
    double y2 = 0; ///< px
};

} // namespace fieldsight
