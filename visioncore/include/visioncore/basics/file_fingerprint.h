// What a file was when a program read or wrote it (present, size, modification time, a hash of
// its bytes), so a later save can tell whether another writer changed it in between.
#pragma once

#include <cstdint>
#include <string>

namespace fieldsight {

struct FileFingerprint
{
    bool exists = false;       ///< a file (or a link to one) was there
    std::uint64_t size = 0;    ///< bytes
    std::int64_t mtime_ns = 0; ///< modification time, nanoseconds since the epoch
    std::uint64_t hash = 0;    ///< FNV-1a 64 of the bytes (0 when absent or unreadable)
    bool operator==(const FileFingerprint&) const = default;
};

/// The fingerprint of `path` now. A file that cannot be read counts by its size and time alone.
FileFingerprint fingerprintFile(const std::string& path);

/// Whether the file at `path` is no longer what `known` says: appeared, vanished, or other
/// bytes. A touch that leaves the bytes as they were is not a change (the hash decides when the
/// size matches and the time does not).
bool fileChangedSince(const std::string& path, const FileFingerprint& known);

} // namespace fieldsight
