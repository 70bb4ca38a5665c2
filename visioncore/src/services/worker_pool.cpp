// Worker threads that survive a failed start.
#include "visioncore/services/worker_pool.h"

#include <algorithm>
#include <system_error>
#include <thread>
#include <vector>

namespace fieldsight {

int workerCount(int requested, std::size_t items)
{
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const int wanted = requested <= 0 ? cores : std::min(requested, cores);
    return int(std::min<std::size_t>(std::size_t(wanted), std::max<std::size_t>(1, items)));
}

void runOnWorkers(int workers, const std::function<void(int)>& work)
{
    std::vector<std::thread> threads;
    std::vector<int> not_started;
    for (int t = 1; t < workers; ++t) {
        try {
            threads.emplace_back(work, t);
        } catch (const std::system_error&) {
            not_started.push_back(t);
        }
    }
    work(0);
    for (int t : not_started)
        work(t);
    for (std::thread& thread : threads)
        thread.join();
}

} // namespace fieldsight
