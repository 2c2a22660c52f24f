#pragma once
// Runs a function for every row of an image on all cores (std::thread; rows are handed out one at a time, so a
// slow row does not hold up a thread's whole share).
#include <functional>

namespace shadowlab {

int workerCount();  // hardware threads, at least 1 (or what a ScopedWorkerCount set)

// Calls work(row) for row in [0, rows) on workerCount() threads; returns when all are done.
void parallelRows(int rows, const std::function<void(int row)>& work);
// The same on `threads` threads (at least 1): tests prove a result does not depend on the count.
void parallelRows(int rows, const std::function<void(int row)>& work, int threads);

// While it lives, workerCount() answers `threads` (at least 1) in the whole process, so a test can run a whole
// measurement on 1 thread and on several and prove the results equal. Not for concurrent use with other counts.
class ScopedWorkerCount {
public:
    explicit ScopedWorkerCount(int threads);
    ~ScopedWorkerCount();
    ScopedWorkerCount(const ScopedWorkerCount&) = delete;
    ScopedWorkerCount& operator=(const ScopedWorkerCount&) = delete;

private:
    int previous_;
};

}  // namespace shadowlab
