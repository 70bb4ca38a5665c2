// Worker threads that survive a failed start.
#include "visioncore/services/worker_pool.h"

#include <algorithm>
#include <exception>
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
    // Threads are joined whatever `work` does here, so an escaping exception cannot end the
    // program through a joinable std::thread's destructor.
    std::exception_ptr escaped;
    try {
        work(0);
        for (int t : not_started)
            work(t);
    } catch (...) {
        escaped = std::current_exception();
    }
    for (std::thread& thread : threads)
        thread.join();
    if (escaped)
        std::rethrow_exception(escaped);
}

} // namespace fieldsight
