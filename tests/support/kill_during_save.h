// Crash safety of a document's save (issue 10): a child process saves two versions of a document
// in turn, without end, and is killed at a random moment; afterwards the file must hold one
// version or the other, whole. Used by the LUT and the annotations tests.
#pragma once

#include "support/sanitizer.h"
#include "visioncore/basics/atomic_file.h"

#include <QDir>
#include <QFileInfo>
#include <QString>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <functional>
#include <random>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace fieldsight::test {

struct KillDuringSaveResult
{
    int rounds = 0;
    int saw_second = 0;        ///< kills after which the file held the second version
    int mixes = 0;             ///< kills after which it held neither version whole
    int unreadable = 0;        ///< kills after which it could not be read at all
    qsizetype temporaries = 0; ///< stray temporaries counted after the kills, summed
    std::string first_problem; ///< what the first bad round found
};

/// Where a crash-safety test's files go: a new folder in memory (/dev/shm) where the system has
/// one, else in the system's temporary folder. What a killed writer leaves is a matter of the
/// temporary file and the rename, not of the disk; on a disk, every save's fsync waits on
/// whatever else writes, and on a loaded machine 100 rounds took a minute instead of seconds
/// (each round's delay is a few saves long).
inline QString crashTestDirTemplate()
{
    const QFileInfo shm(QStringLiteral("/dev/shm"));
    const QString base = shm.isDir() && shm.isWritable() ? shm.filePath() : QDir::tempPath();
    return base + QStringLiteral("/fieldsight-crash-XXXXXX");
}

/// Stray temporaries of an atomic save of `path` ("name.tmp-*" beside it).
inline qsizetype temporariesOf(const std::string& path)
{
    const QFileInfo file(QString::fromStdString(path));
    return QDir(file.absolutePath())
        .entryList({file.fileName() + ".tmp-*"}, QDir::Files | QDir::Hidden)
        .size();
}

/// The kills a crash-safety test makes: 100, a quarter under the sanitizer (support/sanitizer.h:
/// there each round is a few saves ten times as slow, and the sanitizer sees a bad address in
/// the saving code in the first rounds as in the last; the normal build makes all 100).
inline constexpr int kKillRounds = repeats(100);

/// Kills a child that calls `save(i % 2 == 0)` for i = 0, 1, 2, ... (the second version first, so
/// that any save that completes shows) at a random moment of up to
/// `max_delay_us` (at least three saves long, timed here, so that a slow build still kills during
/// saves of both versions), `rounds` times. `first` and `second` are the bytes each version saves
/// as; the file at `path` must already hold `first`.
inline KillDuringSaveResult killDuringSaves(const std::string& path,
                                            const std::function<void(bool second)>& save,
                                            const std::string& first, const std::string& second,
                                            int rounds = kKillRounds, unsigned max_delay_us = 30000,
                                            unsigned seed = 11)
{
    KillDuringSaveResult result;
    const auto start = std::chrono::steady_clock::now();
    save(false); // the file already holds the first version
    const auto one_save = std::chrono::duration_cast<std::chrono::microseconds>(
        std::chrono::steady_clock::now() - start);
    max_delay_us = std::max<unsigned>(max_delay_us, unsigned(3 * one_save.count()) + 1);
    std::mt19937 rng(seed);
    for (int round = 0; round < rounds; ++round) {
        const pid_t child = ::fork();
        if (child < 0) {
            result.first_problem = "fork failed";
            return result;
        }
        if (child == 0) {
            for (unsigned i = 0;; ++i)
                save(i % 2 == 0);
        }
        ::usleep(useconds_t(rng() % max_delay_us));
        ::kill(child, SIGKILL);
        ::waitpid(child, nullptr, 0);
        ++result.rounds;
        const auto now = readWholeFile(path);
        if (!now.ok()) {
            ++result.unreadable;
            if (result.first_problem.empty())
                result.first_problem = now.error().message;
        } else if (now.value() == second) {
            ++result.saw_second;
        } else if (now.value() != first) {
            ++result.mixes;
            if (result.first_problem.empty())
                result.first_problem = "round " + std::to_string(round) + ": a mix of two saves (" +
                                       std::to_string(now.value().size()) + " bytes)";
        }
        result.temporaries += temporariesOf(path);
    }
    return result;
}

} // namespace fieldsight::test
