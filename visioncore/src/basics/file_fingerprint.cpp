#include "visioncore/basics/file_fingerprint.h"

#include <chrono>
#include <filesystem>
#include <fstream>

namespace fieldsight {

namespace {

/// FNV-1a 64 over the file's bytes; 0 when it cannot be read.
std::uint64_t hashFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return 0;
    std::uint64_t h = 14695981039346656037ull;
    char buffer[1 << 16];
    while (in) {
        in.read(buffer, sizeof buffer);
        for (std::streamsize i = 0; i < in.gcount(); ++i) {
            h ^= static_cast<unsigned char>(buffer[i]);
            h *= 1099511628211ull;
        }
    }
    return in.bad() ? 0 : h;
}

} // namespace

FileFingerprint fingerprintFile(const std::string& path)
{
    namespace fs = std::filesystem;
    FileFingerprint f;
    std::error_code ec;
    if (path.empty() || !fs::is_regular_file(path, ec))
        return f;
    f.exists = true;
    f.size = fs::file_size(path, ec);
    if (ec)
        f.size = 0;
    const auto time = fs::last_write_time(path, ec);
    if (!ec)
        f.mtime_ns =
            std::chrono::duration_cast<std::chrono::nanoseconds>(time.time_since_epoch()).count();
    f.hash = hashFile(path);
    return f;
}

bool fileChangedSince(const std::string& path, const FileFingerprint& known)
{
    // The time alone is not a change: the same bytes written or touched again are none.
    const FileFingerprint now = fingerprintFile(path);
    return now.exists != known.exists || now.size != known.size || now.hash != known.hash;
}

} // namespace fieldsight
