// Atomic whole-file writes (temporary file + fsync + rename) and whole-file reads.
#include "visioncore/basics/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
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

mode_t currentUmask()
{
    static const mode_t mask = [] {
        const mode_t m = ::umask(0);
        ::umask(m);
        return m;
    }();
    return mask;
}

/// Removes temporaries beside `path` ("<path>.tmp-<pid>-<n>") left by writers that died: a
/// temporary whose process is gone.
void removeStaleTemporaries(const std::string& path)
{
    const std::string folder = folderOf(path);
    const auto slash = path.find_last_of('/');
    const std::string prefix =
        (slash == std::string::npos ? path : path.substr(slash + 1)) + ".tmp-";
    DIR* dir = ::opendir(folder.c_str());
    if (!dir)
        return;
    while (const dirent* entry = ::readdir(dir)) {
        const std::string name = entry->d_name;
        if (name.compare(0, prefix.size(), prefix) != 0)
            continue;
        const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
        if (pid > 0 && pid != long(::getpid()) && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH)
            ::unlink((folder + "/" + name).c_str());
    }
    ::closedir(dir);
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

std::string fileKindName(unsigned mode)
{
    if (S_ISDIR(mode))
        return "a folder";
    if (S_ISFIFO(mode))
        return "a FIFO";
    if (S_ISCHR(mode))
        return "a character device";
    if (S_ISBLK(mode))
        return "a block device";
    if (S_ISSOCK(mode))
        return "a socket";
    if (S_ISLNK(mode))
        return "a symbolic link";
    return "a special file";
}

namespace {

/// Writes to something that is not a regular file (a device such as /dev/null or /dev/full, a
/// FIFO with a reader) as it is: there is nothing to replace atomically.
Status writeStraight(const std::string& path, const void* data, std::size_t size)
{
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0 && errno == ENXIO)
        return Error{"cannot write " + path + ": a FIFO that nothing reads"};
    if (fd < 0)
        return errnoError("write", path, errno);
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0)
        ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    if (!writeAll(fd, static_cast<const char*>(data), size)) {
        const int error = errno;
        ::close(fd);
        return errnoError("write", path, error);
    }
    if (::close(fd) != 0)
        return errnoError("write", path, errno);
    return {};
}

} // namespace

Status writeFileAtomically(const std::string& requested, const void* data, std::size_t size)
{
    if (requested.empty())
        return Error{"cannot write an empty file name"};
    // A symbolic link stays a link: its target is what gets replaced.
    std::string path = requested;
    struct stat link
    {
    };
    if (::lstat(requested.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
        char* resolved = ::realpath(requested.c_str(), nullptr);
        if (resolved) {
            path = resolved;
            std::free(resolved);
        }
    }
    struct stat target
    {
    };
    const bool target_exists = ::stat(path.c_str(), &target) == 0;
    if (target_exists && S_ISDIR(target.st_mode))
        return errnoError("write", requested, EISDIR);
    if (target_exists && !S_ISREG(target.st_mode))
        return writeStraight(requested, data, size);

    removeStaleTemporaries(path);
    const std::string temp = temporaryNameFor(path);
    // The bytes go to an unnamed file (O_TMPFILE) that gets its temporary name only once
    // complete: a writer killed while writing leaves nothing behind. Where the file system has
    // no unnamed files, a named temporary (removed by the next save if its writer died).
    int fd = ::open(folderOf(path).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    const bool unnamed = fd >= 0;
    if (!unnamed)
        fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        return errnoError("write", path, errno);

    auto fail = [&](int error) -> Status {
        ::close(fd);
        ::unlink(temp.c_str());
        return errnoError("write", path, error);
    };
    if (!writeAll(fd, static_cast<const char*>(data), size))
        return fail(errno);
    // Keep the permissions of the file being replaced (an unnamed file starts as 0000).
    const mode_t mode = target_exists ? (target.st_mode & 07777) : (0666 & ~currentUmask());
    if ((target_exists || unnamed) && ::fchmod(fd, mode) != 0)
        return fail(errno);
    if (::fsync(fd) != 0)
        return fail(errno);
    if (unnamed) {
        // Named and at once renamed: the temporary name lives for two system calls, so a writer
        // killed now almost never leaves one (the close, which can take as long as a small
        // write, comes after the rename; the bytes are already on disk).
        const std::string self = "/proc/self/fd/" + std::to_string(fd);
        if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, temp.c_str(), AT_SYMLINK_FOLLOW) != 0)
            return fail(errno);
    } else if (::close(fd) != 0) {
        const int error = errno;
        ::unlink(temp.c_str());
        return errnoError("write", path, error);
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        const int error = errno;
        if (unnamed)
            ::close(fd);
        ::unlink(temp.c_str());
        return errnoError("write", path, error);
    }
    if (unnamed && ::close(fd) != 0) // after fsync, a close error is a report, not lost bytes
        return errnoError("write", path, errno);
    // Make the rename itself durable; failure here does not undo a completed save.
    const int dir = ::open(folderOf(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir >= 0) {
        ::fsync(dir);
        ::close(dir);
    }
    return {};
}

Result<std::string> setAsideUnreadable(const std::string& path)
{
    struct stat st
    {
    };
    if (::lstat(path.c_str(), &st) != 0)
        return errno == ENOENT ? std::string()
                               : Result<std::string>(errnoError("read", path, errno));
    if (!S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode)) // a link moves; its target is untouched
        return Error{"cannot set " + path + " aside: " + fileKindName(st.st_mode) +
                     ", not a regular file"};
    for (int n = 1; n < 1000; ++n) {
        const std::string aside = path + ".unreadable" + (n > 1 ? "-" + std::to_string(n) : "");
        struct stat taken
        {
        };
        if (::lstat(aside.c_str(), &taken) == 0)
            continue;
        if (::rename(path.c_str(), aside.c_str()) != 0)
            return Error{"cannot set " + path + " aside as " + aside + ": " + std::strerror(errno)};
        return aside;
    }
    return Error{"cannot set " + path + " aside: " + path + ".unreadable-1 to -999 all exist"};
}

Result<std::string> saveReplacingUnreadable(const std::string& path, bool& unreadable,
                                            const std::function<Status()>& save)
{
    std::string aside;
    if (unreadable) {
        auto moved = setAsideUnreadable(path);
        if (!moved)
            return Error{moved.error().message + "; not saved over the file it could not read"};
        aside = std::move(moved).value();
        unreadable = false;
    }
    if (Status s = save(); !s) {
        // Nothing was saved: the refused file goes back where it was, to be set aside next time.
        if (aside.empty())
            return s.error();
        if (::rename(aside.c_str(), path.c_str()) != 0)
            return Error{s.error().message + "; the file it could not read is kept as " + aside};
        unreadable = true;
        return s.error();
    }
    if (aside.empty())
        return std::string();
    return path + " could not be read when opened; it is kept as " + aside +
           " and a new one was saved";
}

Error notARegularFile(const std::string& path, unsigned mode)
{
    return Error{"cannot read " + path + ": " + fileKindName(mode) + ", not a regular file"};
}

Result<OpenedFile> openRegularFile(const std::string& path)
{
    // Non-blocking, so opening a FIFO cannot wait for a writer; refused below anyway.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return errnoError("read", path, errno);
    struct stat st
    {
    };
    if (::fstat(fd, &st) != 0) {
        const int error = errno;
        ::close(fd);
        return errnoError("read", path, error);
    }
    if (!S_ISREG(st.st_mode)) {
        ::close(fd);
        return notARegularFile(path, st.st_mode);
    }
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0)
        ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    return OpenedFile{fd, std::uint64_t(st.st_size)};
}

Status checkRegularFile(const std::string& path)
{
    struct stat st
    {
    };
    if (::stat(path.c_str(), &st) != 0)
        return errnoError("read", path, errno);
    if (!S_ISREG(st.st_mode))
        return notARegularFile(path, st.st_mode);
    return {};
}

Result<std::string> readWholeFile(const std::string& path, std::size_t max_bytes,
                                  const std::string& cap_for)
{
    const std::string cap =
        std::to_string(max_bytes) + " bytes" + (cap_for.empty() ? "" : " for " + cap_for);
    auto opened = openRegularFile(path);
    if (!opened)
        return opened.error();
    const auto [fd, size] = opened.value();
    if (size > max_bytes) {
        ::close(fd);
        return Error{"cannot read " + path + ": too large (" + std::to_string(size) +
                     " bytes; at most " + cap + ")"};
    }
    std::string text;
    if (size > 0)
        text.reserve(std::size_t(size));
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
        if (text.size() > max_bytes) { // it grew while being read
            ::close(fd);
            return Error{"cannot read " + path + ": too large (more than " + cap + ")"};
        }
    }
    ::close(fd);
    return text;
}

} // namespace fieldsight
