#pragma once
// Per-pass timing. On a real GPU: a ring of GL_TIME_ELAPSED queries read back a few frames later, so the frame
// never stalls. On a software rasterizer (where timer queries return garbage): CPU time around glFinish, labelled.
#include "gl/gl_objects.h"

#include <array>
#include <chrono>
#include <map>
#include <optional>

namespace shadowlab {

enum class TimedPass { Shadow = 0, Main = 1, DepthBounds = 2, Moments = 3, Blur = 4, Mips = 5 };
enum class TimingSource { GpuQueries, CpuAroundFinish };

class PassTimer {
public:
    explicit PassTimer(TimingSource source);

    TimingSource source() const { return source_; }
    const char* sourceLabel() const;

    // A pass is TimedPass or any other number (the renderer times each shadow view as kFirstViewPass + index).
    // Passes must not nest (one GL_TIME_ELAPSED query at a time).
    static constexpr int kFirstViewPass = 16;
    void begin(TimedPass pass) { begin(int(pass)); }
    void end(TimedPass pass) { end(int(pass)); }
    void begin(int pass);
    void end(int pass);

    // The newest finished measurement of a pass in milliseconds, if any. With GPU queries it may be from an earlier
    // frame; `wait` blocks until the newest one is ready (for one-shot CLI renders and benchmarks).
    std::optional<double> latestMilliseconds(TimedPass pass, bool wait = false) {
        return latestMilliseconds(int(pass), wait);
    }
    std::optional<double> latestMilliseconds(int pass, bool wait = false);

private:
    static constexpr int kRing = 4;
    struct PassQueries {
        std::array<gl::Query, kRing> queries;
        std::array<bool, kRing> pending{};
        int next = 0;
        std::optional<double> latest;
        std::chrono::steady_clock::time_point cpuStart;
    };
    void collect(PassQueries& pass, bool wait);
    PassQueries& pass(int which);

    TimingSource source_;
    std::map<int, PassQueries> passes_;
};

}  // namespace shadowlab
