// Atomic file writes: every save in Fieldsight goes through here, so a crash never leaves a
// half-written file.
#pragma once

#include "visioncore/result.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace fieldsight {

/// Writes `size` bytes to a temporary file in the same folder, flushes it, then renames it over
/// `path`. On failure `path` is untouched and the error names the file and the problem.
Status writeFileAtomically(const std::string& path, const void* data, std::size_t size);
inline Status writeFileAtomically(const std::string& path, std::string_view text)
{
    return writeFileAtomically(path, text.data(), text.size());
}

/// Reads a whole file; the error names the file and the problem.
Result<std::string> readWholeFile(const std::string& path);

} // namespace fieldsight
