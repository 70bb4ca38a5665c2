// The scans' gate (see scan_gate.h).
#include "ui/scans/scan_gate.h"

#include <algorithm>

namespace fieldsight::ui {

namespace {

/// How often a waiting scan thread looks at its stop flag (a cancel sets it without a signal).
constexpr std::chrono::milliseconds kGateStopPoll{10};

} // namespace

void ScanGate::setTimes(std::chrono::milliseconds quiet, std::chrono::milliseconds longest)
{
    std::lock_guard lock(m_mutex);
    m_quiet = quiet;
    m_longest = longest;
}

void ScanGate::hold()
{
    std::lock_guard lock(m_mutex);
    m_until = std::max(m_until, Clock::now() + m_quiet);
}

void ScanGate::release()
{
    {
        std::lock_guard lock(m_mutex);
        m_until = {};
    }
    m_changed.notify_all();
}

bool ScanGate::held() const
{
    std::lock_guard lock(m_mutex);
    return Clock::now() < m_until;
}

void ScanGate::pass(const std::atomic<bool>* stop)
{
    std::unique_lock lock(m_mutex);
    const Clock::time_point start = Clock::now();
    if (start >= m_until)
        return;
    ++m_waits;
    ++m_waiting;
    const Clock::time_point give_up = start + m_longest;
    for (;;) {
        const Clock::time_point now = Clock::now();
        if (now >= m_until || now >= give_up || (stop && stop->load()))
            break;
        m_changed.wait_until(lock, std::min({m_until, give_up, now + kGateStopPoll}));
    }
    --m_waiting;
}

} // namespace fieldsight::ui
