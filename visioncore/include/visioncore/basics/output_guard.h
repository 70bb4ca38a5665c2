// The rule every command and the window follow before writing an output: never over what they
// read. One rule, so `run --render`, `eval --json`, a snapshot of the view and a recording agree.
#pragma once

#include "visioncore/basics/result.h"

#include <string>
#include <string_view>
#include <vector>

namespace fieldsight {

/// Refuses an output that is one of `inputs` (a file, or a folder such as a stream), or that would
/// replace a file inside an input folder, after resolving links and `..`: an Error naming both
/// paths, for the caller to give before it writes anything. Empty inputs, "-" and cameras are
/// skipped. `who` starts the message (a command's name, or what the window was saving).
Status checkNotAnInput(std::string_view who, const std::string& output,
                       const std::vector<std::string>& inputs);

/// Refuses a folder to write a new set of files into (a recording) unless it is new or empty:
/// an Error naming it and what is there.
Status checkNewOrEmptyFolder(std::string_view who, const std::string& folder);

} // namespace fieldsight
