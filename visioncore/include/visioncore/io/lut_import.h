// Colour tables of other RoboCup teams (SPEC §3), mapped onto Fieldsight's colour ids.
#pragma once

#include "visioncore/basics/colour_lut.h"
#include "visioncore/basics/result.h"

#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

/// Loads a colour table, choosing the format by the file name's ending (case-insensitive):
///  - `.lut`      native NUbots/Fieldsight table (SPEC §3);
///  - `.c64`      B-Human 2009 ColorTable64: run-length coded 64^3 table;
///  - `.nnmc.bz2` rUNSWift 2014 bzip2-compressed 128^3 table (`.nnmc`: the same, unpacked);
///  - `.raw`      UPennalizers 2012 64^3 table of class bit flags.
/// Every 128^3 cell takes the class of the source cell covering it. Classes without a Fieldsight
/// counterpart become unclassified. Errors name the file and the problem.
Result<ColourLut> importLut(const std::string& path);

/// The file name endings importLut() understands, e.g. for an "Import LUT" file dialog filter.
std::vector<std::string_view> importableLutSuffixes();

} // namespace fieldsight
