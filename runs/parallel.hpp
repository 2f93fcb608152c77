// The worker pool of the suite and the studies: items 0..count-1 handed out in order to `jobs`
// threads. The first exception a worker throws (an output file that cannot be written, a bug)
// stops the handing out of further items and is rethrown here once every thread has joined, so
// it reaches main's one-line report instead of std::terminate.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rotbeam::cli {

template <typename Work>
void for_each_parallel(size_t count, int jobs, Work&& work) {
    std::atomic<size_t> next{0};
    std::atomic<bool> failed{false};
    std::exception_ptr first;
    std::mutex guard;
    auto worker = [&] {
        for (size_t i = next++; i < count && !failed; i = next++) {
            try {
                work(i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(guard);
                if (!first) first = std::current_exception();
                failed = true;
            }
        }
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < std::max(1, jobs); ++t) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
    if (first) std::rethrow_exception(first);
}

}  // namespace rotbeam::cli
