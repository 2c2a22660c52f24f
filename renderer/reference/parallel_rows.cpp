#include "reference/parallel_rows.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace shadowlab {

namespace {
std::atomic<int> forcedWorkers{0};  // 0: every core
}  // namespace

int workerCount() {
    const int forced = forcedWorkers.load();
    return forced > 0 ? forced : std::max(1, int(std::thread::hardware_concurrency()));
}

ScopedWorkerCount::ScopedWorkerCount(int threads) : previous_(forcedWorkers.exchange(std::max(threads, 1))) {}
ScopedWorkerCount::~ScopedWorkerCount() { forcedWorkers.store(previous_); }

void parallelRows(int rows, const std::function<void(int row)>& work) { parallelRows(rows, work, workerCount()); }

void parallelRows(int rows, const std::function<void(int row)>& work, int threadCount) {
    std::atomic<int> next{0};
    auto worker = [&] {
        for (int row = next++; row < rows; row = next++) work(row);
    };
    const int threads = std::min(std::max(threadCount, 1), std::max(rows, 1));
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& thread : pool) thread.join();
}

}  // namespace shadowlab
