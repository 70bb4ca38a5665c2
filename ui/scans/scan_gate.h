// The whole-stream scans give way while the user steps: each frame a scan thread reads or runs
// passes the gate first, and a step holds the gate shut for a short quiet time, so on a 2-core
// machine the frame worker and its read-ahead decode a 1280x720 PNG without the scans' decoding
// beside them. The scans resume once the stepping stops, and finish with the same results.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>

namespace fieldsight::ui {

class ScanGate
{
public:
    using Clock = std::chrono::steady_clock;
    /// How long after the last step the scans stay paused.
    static constexpr std::chrono::milliseconds kQuiet{400};
    /// The longest a scan thread waits at once while the user keeps stepping (playing a long
    /// stream): then it runs one frame, so a scan always gets on, if slowly.
    static constexpr std::chrono::milliseconds kLongestWait{3000};

    /// How long a hold lasts and the longest a scan thread waits at once (tests make them long,
    /// so nothing depends on the time a step takes).
    void setTimes(std::chrono::milliseconds quiet, std::chrono::milliseconds longest);

    /// Thread-safe (the GUI thread). The scans pause for the quiet time from now (or longer).
    void hold();
    /// Thread-safe. Ends the hold now (the waiting scans go on).
    void release();
    bool held() const;

    /// Called by a scan thread before each frame: returns at once when the gate is open; else
    /// when the hold ends, `stop` (may be null) becomes true, or it has waited the longest wait.
    void pass(const std::atomic<bool>* stop = nullptr);

    /// Times pass() waited (each a scan thread that gave way to the user's steps).
    std::uint64_t waits() const { return m_waits.load(); }
    /// Scan threads waiting in pass() now.
    int waiting() const { return m_waiting.load(); }

private:
    mutable std::mutex m_mutex;
    std::condition_variable m_changed;
    Clock::time_point m_until;                          ///< under m_mutex: held until then
    std::chrono::milliseconds m_quiet = kQuiet;         ///< under m_mutex
    std::chrono::milliseconds m_longest = kLongestWait; ///< under m_mutex
    std::atomic<std::uint64_t> m_waits{0};
    std::atomic<int> m_waiting{0};
};

} // namespace fieldsight::ui
