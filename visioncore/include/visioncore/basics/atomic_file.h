// Atomic file writes: every save in Fieldsight goes through here, so a crash never leaves a
// half-written file.
#pragma once

#include "visioncore/basics/result.h"

#include <cstddef>
#include <functional>
#include <new>
#include <cstdint>
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
/// memory without bound or block; a file over the cap is refused unread, saying the cap and,
/// when given, what it is for: "... at most 1079296 bytes for a stream.json of 30 frames").
Result<std::string> readWholeFile(const std::string& path, std::size_t max_bytes = kMaxReadBytes,
                                  const std::string& cap_for = {});

/// Opens `path` for reading as a regular file: without waiting (a FIFO with no writer does not
/// block the caller), then refused unless it is a regular file. The descriptor (blocking, to be
/// closed by the caller) or the Error of every read ("cannot read <path>: a FIFO, not a regular
/// file", or the system's reason: a link loop, a name too long, no permission).
/// An open regular file: its descriptor (the caller closes it) and its size when opened.
struct OpenedFile
{
    int fd = -1;
    std::uint64_t size = 0; ///< bytes
};
Result<OpenedFile> openRegularFile(const std::string& path);

/// The same check for a reader that opens `path` by name itself (OpenCV's video back ends): an
/// Error unless `path` is, after links, a regular file. Nothing is opened, so nothing can wait.
Status checkRegularFile(const std::string& path);

/// Runs `read` (the reading of the file `path`, returning a Result), with running out of memory
/// while reading or parsing it an Error naming the file instead of a std::bad_alloc: a file
/// within its size cap can still need more memory than is left.
template <class Read>
auto readingWithinMemory(const std::string& path, Read&& read) -> decltype(read())
{
    try {
        return read();
    } catch (const std::bad_alloc&) {
        return Error{"cannot read " + path + ": not enough memory to read it"};
    }
}

/// What kind of thing `mode` (a stat st_mode) is, for messages: "a folder", "a FIFO", ...
std::string fileKindName(unsigned mode);
/// "cannot read <path>: a FIFO, not a regular file": the refusal of every read of a non-file.
Error notARegularFile(const std::string& path, unsigned mode);

} // namespace fieldsight
