// The one worker pool: runs a piece of work per worker thread and waits for all of them.
#pragma once

#include <cstddef>
#include <functional>

namespace fieldsight {

/// How many workers to use: `requested` (0: one per core), never more than `items` (at least
/// one) nor more than the machine's cores.
int workerCount(int requested, std::size_t items);

/// Calls work(t) exactly once for every t in [0, workers): worker 0 on the calling thread, the
/// others on threads of their own. A thread that cannot be started (the system is out of
/// threads) is not an error: the calling thread runs that worker's share after its own. `work`
/// must not throw on the other threads; what it throws on the calling thread is rethrown once
/// every thread has been joined.
void runOnWorkers(int workers, const std::function<void(int worker)>& work);

} // namespace fieldsight
