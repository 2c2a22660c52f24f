#include "reference/parallel_rows.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace shadowlab {

int workerCount() { return std::max(1, int(std::thread::hardware_concurrency())); }

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
