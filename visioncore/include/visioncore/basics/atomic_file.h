// Atomic file writes: every save in Fieldsight goes through here, so a crash never leaves a
// half-written file.
#pragma once

#include "visioncore/basics/result.h"

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace fieldsight {

/// Writes `size` bytes to a temporary file in the same folder, flushes it, then renames it over
/// `path`. On failure `path` is untouched and the error names the file and the problem. Only a
/// regular file (or none) is replaced: a symbolic link's target is replaced and the link kept,
/// and anything else (a device, a FIFO) is written straight, never replaced by a file; a FIFO
/// without a reader is an error, not a wait.
Status writeFileAtomically(const std::string& path, const void* data, std::size_t size);
inline Status writeFileAtomically(const std::string& path, std::string_view text)
{
    return writeFileAtomically(path, text.data(), text.size());
}

/// Sets aside a file a reader refused (damaged, or of a newer format) before a save replaces it:
/// renames `path` to `<path>.unreadable` (`.unreadable-2`, ... when taken), never removing
/// anything, and returns the new name (empty when there is no file at `path`). Only a regular file
/// or a symbolic link (the link moves, its target is untouched) is moved; anything else is an
/// error.
Result<std::string> setAsideUnreadable(const std::string& path);

/// The one rule for a document kept in a file the window saves as it changes (bookmarks, LUT
/// samples): when the file was refused on opening (`unreadable`), it is set aside before the
/// first `save`, and `unreadable` cleared. Returns what to tell the user (empty: nothing), or
/// the error (then nothing was saved, and the file at `path` is as it was, or where the error
/// says it is kept).
Result<std::string> saveReplacingUnreadable(const std::string& path, bool& unreadable,
                                            const std::function<Status()>& save);

/// The largest file readWholeFile() reads unless told otherwise.
inline constexpr std::size_t kMaxReadBytes = std::size_t(256) << 20;

/// Reads a whole regular file of at most `max_bytes`; the error names the file and the problem
/// (a folder, a FIFO or a device is refused before reading, so /dev/zero or a pipe cannot grow
/// memory without bound or block).
Result<std::string> readWholeFile(const std::string& path, std::size_t max_bytes = kMaxReadBytes);

/// What kind of thing `mode` (a stat st_mode) is, for messages: "a folder", "a FIFO", ...
std::string fileKindName(unsigned mode);
/// "cannot read <path>: a FIFO, not a regular file": the refusal of every read of a non-file.
Error notARegularFile(const std::string& path, unsigned mode);

} // namespace fieldsight
