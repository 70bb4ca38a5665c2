// Running the fieldsight executable in a child process as a user would: arguments as bytes (no
// shell, no Qt decoding), killed after a time, its exit status, output, time and peak memory.
#pragma once

#include <chrono>
#include <csignal>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <grp.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fieldsight::test {

struct Outcome
{
    int status = -1;
    std::string out;
    std::string err;
    double seconds = 0;
    long peak_kb = 0; ///< the child's peak resident memory
};

/// A file's bytes ("" when it cannot be read). Read whole by the library, not a character at a
/// time: the suites are unoptimised, and test_no_overwrite reads 180 MB this way.
inline std::string readAll(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    if (in.peek() != std::ifstream::traits_type::eof())
        bytes << in.rdbuf();
    return std::move(bytes).str();
}

inline void writeBytes(const std::string& path, const std::string& bytes)
{
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

inline bool amRoot()
{
    return ::geteuid() == 0;
}

inline constexpr uid_t kNobody = 65534;
inline constexpr int kCannotBeNobody = 125; ///< the child could not become nobody

/// Runs `exe` with `args` in `cwd`, killing it after `seconds`. Peak memory from wait4(). With
/// `as_nobody`, a root test runs the command as user and group nobody, so that permission bits
/// bind it; `env` adds to its environment ("NAME=value").
inline Outcome runChild(const std::string& exe, const std::vector<std::string>& args,
                        const std::string& cwd, rlim_t file_size_limit = RLIM_INFINITY,
                        bool as_nobody = false, int seconds = 30, std::vector<std::string> env = {})
{
    std::vector<std::string> all{exe};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    for (char** e = environ; *e; ++e)
        env.emplace_back(*e); // after the additions: the first of a name wins
    std::vector<char*> envp;
    for (std::string& e : env)
        envp.push_back(e.data());
    envp.push_back(nullptr);
    const std::string out_path = cwd + "/.stdout", err_path = cwd + "/.stderr";

    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid == 0) {
        if (::chdir(cwd.c_str()) != 0)
            ::_exit(127);
        const int in = ::open("/dev/null", O_RDONLY);
        const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(in, 0);
        ::dup2(out, 1);
        ::dup2(err, 2);
        const rlimit limit{file_size_limit, file_size_limit};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        if (as_nobody && amRoot() &&
            (::setgroups(0, nullptr) != 0 || ::setgid(kNobody) != 0 || ::setuid(kNobody) != 0))
            ::_exit(kCannotBeNobody);
        ::execve(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    Outcome o;
    int status = 0;
    rusage usage{};
    while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(seconds)) {
            ::kill(pid, SIGKILL);
            ::wait4(pid, &status, 0, &usage);
            o.err = "(killed after " + std::to_string(seconds) + " s)";
            return o;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    o.peak_kb = usage.ru_maxrss;
    o.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    o.out = readAll(out_path);
    o.err = readAll(err_path);
    return o;
}

} // namespace fieldsight::test
