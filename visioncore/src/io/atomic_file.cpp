// Atomic whole-file writes (temporary file + fsync + rename) and whole-file reads.
#include "visioncore/io/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fieldsight {

namespace {

Error errnoError(const char* verb, const std::string& path, int error)
{
    return Error{std::string("cannot ") + verb + " " + path + ": " + std::strerror(error)};
}

std::string folderOf(const std::string& path)
{
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? std::string("/") : path.substr(0, slash);
}

/// A name beside `path` that no other writer (thread or process) uses at the same time.
std::string temporaryNameFor(const std::string& path)
{
    static std::atomic<unsigned> counter{0};
    return path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

bool writeAll(int fd, const char* data, std::size_t size)
{
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            return false;
        }
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

} // namespace

Status writeFileAtomically(const std::string& path, const void* data, std::size_t size)
{
    if (path.empty())
        return Error{"cannot write an empty file name"};
    struct stat target
    {
    };
    const bool target_exists = ::stat(path.c_str(), &target) == 0;
    if (target_exists && S_ISDIR(target.st_mode))
        return errnoError("write", path, EISDIR);

    const std::string temp = temporaryNameFor(path);
    // 0666 lets the umask decide, as for any newly created file.
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        return errnoError("write", path, errno);

    auto fail = [&](int error) -> Status {
        ::close(fd);
        ::unlink(temp.c_str());
        return errnoError("write", path, error);
    };
    if (!writeAll(fd, static_cast<const char*>(data), size))
        return fail(errno);
    // Keep the permissions of the file being replaced.
    if (target_exists && ::fchmod(fd, target.st_mode & 07777) != 0)
        return fail(errno);
    if (::fsync(fd) != 0)
        return fail(errno);
    if (::close(fd) != 0) {
        const int error = errno;
        ::unlink(temp.c_str());
        return errnoError("write", path, error);
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        const int error = errno;
        ::unlink(temp.c_str());
        return errnoError("write", path, error);
    }
    // Make the rename itself durable; failure here does not undo a completed save.
    const int dir = ::open(folderOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return {};
}

Result<std::string> readWholeFile(const std::string& path)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return errnoError("read", path, errno);
    struct stat st
    {
    };
    if (::fstat(fd, &st) != 0 || S_ISDIR(st.st_mode)) {
        const int error = S_ISDIR(st.st_mode) ? EISDIR : errno;
        ::close(fd);
        return errnoError("read", path, error);
    }
    std::string text;
    if (st.st_size > 0)
        text.reserve(std::size_t(st.st_size));
    char chunk[65536];
    for (;;) {
        const ssize_t n = ::read(fd, chunk, sizeof chunk);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            const int error = errno;
            ::close(fd);
            return errnoError("read", path, error);
        }
        if (n == 0)
            break;
        text.append(chunk, std::size_t(n));
    }
    ::close(fd);
    return text;
}

} // namespace fieldsight
