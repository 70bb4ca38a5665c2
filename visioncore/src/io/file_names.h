// Frame file names: lower case for extensions, and the natural order frames are numbered in.
#pragma once

#include <string>

namespace fieldsight::io {

std::string lowercase(std::string s);
/// Natural order: digit runs compare as numbers, so "frame_2" sorts before "frame_10".
bool naturalLess(const std::string& a, const std::string& b);

} // namespace fieldsight::io
