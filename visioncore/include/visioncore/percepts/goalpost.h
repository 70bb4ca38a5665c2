// Goalpost percept: the image box of one post and the point where it meets the field.
#pragma once

namespace fieldsight {

enum class GoalpostSide { Unknown, Left, Right };

struct Goalpost
{
    int left = 0;       ///< px, leftmost column of the post (inclusive)
    int right = 0;      ///< px, rightmost column (inclusive)
    int top = 0;        ///< px, top row (inclusive)
    int bottom = 0;     ///< px, bottom row (inclusive)
    double base_x = 0;  ///< px, where the post meets the field
    double base_y = 0;  ///< px
    GoalpostSide side = GoalpostSide::Unknown;
};

} // namespace fieldsight
