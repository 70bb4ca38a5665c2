// Ball percept: where a ball was seen in the image.
#pragma once

namespace fieldsight {

struct Ball
{
    double x = 0;      ///< px, centre
    double y = 0;      ///< px, centre
    double radius = 0; ///< px
};

} // namespace fieldsight
