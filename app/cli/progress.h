#pragma once
// Progress of long CLI work (sweep, tune, hardcases, check, measure) on a terminal: one line on stderr, redrawn a few
// times a second, "sweep 12/40 points, 00:31 elapsed, ~01:10 left (timing pcf 2048)", erased when the work ends.
// Quiet when stderr is not a terminal (piped, a log file) or the CI environment variable is set: the output of a
// script or a CI job never holds it.
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace shadowlab::cli {

// What one line shows. total 0: the work has no count, only a fraction ("measure 45 %, ...").
struct ProgressState {
    std::string what;      // "sweep"
    std::size_t done = 0;  // finished units
    std::size_t total = 0;
    std::string unit;      // "points"
    double partial = 0.0;  // 0..1 of the unit under way (of the whole work when total is 0)
    double elapsedSeconds = 0.0;
    std::string stage;     // what the work is doing now; "" for none
};

// "00:31", "01:10", "1:02:03": minutes and seconds, hours when there are any (rounded to the second).
std::string clockText(double seconds);

// The line: "sweep 12/40 points, 00:31 elapsed, ~01:10 left (stage)". Time left = elapsed x (1 - f) / f with f the
// finished share (done + partial) / total; "estimating time left" until some work is finished.
std::string progressLine(const ProgressState& state);

// Whether progress is drawn: stderr is a terminal and `ciVariable` (the CI environment variable) is unset or empty.
bool showsProgress(bool stderrIsTerminal, const char* ciVariable);

// The line for one piece of work. Drawn only when showsProgress(isatty(stderr), getenv("CI")); otherwise every call is
// a no-op. `partial` and `stage` (optional) are read from the drawing thread: they must be thread-safe (an
// AccuracyProgress's fraction and stage are).
class ProgressLine {
public:
    ProgressLine(std::string what, std::size_t total, std::string unit, std::function<double()> partial = {},
                 std::function<std::string()> stage = {});
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    void setDone(std::size_t done);
    void setTotal(std::size_t total);
    // Runs `print` (which writes whole lines to stdout or stderr) with the line erased, then draws it again below.
    void above(const std::function<void()>& print);
    // Erases the line until resume(): for a stretch of output between two pieces of work.
    void pause();
    void resume();
    // Erases the line and stops drawing (the destructor does it too).
    void finish();

private:
    void draw();  // with mutex_ held

    std::string what_, unit_;
    std::function<double()> partial_;
    std::function<std::string()> stage_;
    std::atomic<std::size_t> done_{0}, total_{0};
    bool enabled_ = false;
    bool drawn_ = false;
    bool stop_ = false;
    bool paused_ = false;
    double start_ = 0.0;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::thread ticker_;
};

}  // namespace shadowlab::cli
