#include "cli/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace shadowlab::cli {

namespace {

double now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Redraws per second: the elapsed time moves visibly, the terminal is not flooded.
constexpr auto kTick = std::chrono::milliseconds(250);

}  // namespace

std::string clockText(double seconds) {
    const long s = std::lround(std::max(0.0, std::min(seconds, 359999.0)));
    char text[32];
    if (s >= 3600)
        std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else
        std::snprintf(text, sizeof text, "%02ld:%02ld", s / 60, s % 60);
    return text;
}

std::string progressLine(const ProgressState& s) {
    const double partial = std::clamp(std::isfinite(s.partial) ? s.partial : 0.0, 0.0, 1.0);
    std::string line = s.what + " ";
    double finished = partial;  // the finished share of the whole work
    if (s.total > 0) {
        const std::size_t done = std::min(s.done, s.total);
        line += std::to_string(done) + "/" + std::to_string(s.total) + " " + s.unit;
        finished = (double(done) + (done < s.total ? partial : 0.0)) / double(s.total);
    } else {
        line += std::to_string(int(std::floor(partial * 100.0))) + " %";
    }
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "~" + std::string here.
    line.append(", ").append(clockText(s.elapsedSeconds)).append(" elapsed, ");
    if (finished > 0.0)
        line.append("~").append(clockText(s.elapsedSeconds * (1.0 - finished) / finished)).append(" left");
    else
        line.append("estimating time left");
    if (!s.stage.empty()) line.append(" (").append(s.stage).append(")");
    return line;
}

bool showsProgress(bool stderrIsTerminal, const char* ciVariable) {
    return stderrIsTerminal && (ciVariable == nullptr || *ciVariable == '\0');
}

ProgressLine::ProgressLine(std::string what, std::size_t total, std::string unit, std::function<double()> partial,
                           std::function<std::string()> stage)
    : what_(std::move(what)), unit_(std::move(unit)), partial_(std::move(partial)), stage_(std::move(stage)),
      total_(total), enabled_(showsProgress(::isatty(STDERR_FILENO) == 1, std::getenv("CI"))), start_(now()) {
    if (!enabled_) return;
    ticker_ = std::thread([this] {
        std::unique_lock<std::mutex> lock(mutex_);
        while (!stop_) {
            draw();
            wake_.wait_for(lock, kTick, [this] { return stop_; });
        }
    });
}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::setDone(std::size_t done) { done_ = done; }
void ProgressLine::setTotal(std::size_t total) { total_ = total; }

void ProgressLine::draw() {
    if (paused_) return;
    ProgressState state{what_, done_.load(), total_.load(), unit_, partial_ ? partial_() : 0.0, now() - start_,
                        stage_ ? stage_() : std::string()};
    std::string line = progressLine(state);
    // One terminal row: a wrapped line could not be erased by the carriage return.
    winsize size{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 1 && line.size() >= size.ws_col)
        line.resize(size.ws_col - 1);
    std::fprintf(stderr, "\r%s\033[K", line.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressLine::above(const std::function<void()>& print) {
    if (!enabled_) {
        print();
        return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (drawn_) std::fputs("\r\033[K", stderr);
    print();
    std::fflush(stdout);
    std::fflush(stderr);
    if (!stop_) draw();
}

void ProgressLine::pause() {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    if (drawn_) std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    drawn_ = false;
    paused_ = true;
}

void ProgressLine::resume() {
    if (!enabled_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    paused_ = false;
    if (!stop_) draw();
}

void ProgressLine::finish() {
    if (!enabled_) return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stop_) return;
        stop_ = true;
        if (drawn_) std::fputs("\r\033[K", stderr);
        std::fflush(stderr);
        drawn_ = false;
    }
    wake_.notify_all();
    if (ticker_.joinable()) ticker_.join();
}

}  // namespace shadowlab::cli
