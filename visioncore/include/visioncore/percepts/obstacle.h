// Obstacle percept: an image box of something standing on the field (robots, people).
#pragma once

namespace fieldsight {

struct Obstacle
{
    int left = 0;   ///< px, inclusive
    int right = 0;  ///< px, inclusive
    int top = 0;    ///< px, inclusive
    int bottom = 0; ///< px, inclusive; where it stands on the field
};

} // namespace fieldsight
