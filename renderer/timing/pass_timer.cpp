#include "timing/pass_timer.h"

namespace shadowlab {

PassTimer::PassTimer(TimingSource source) : source_(source) {}

PassTimer::PassQueries& PassTimer::pass(int which) {
    auto [it, created] = passes_.try_emplace(which);
    if (created && source_ == TimingSource::GpuQueries)
        for (gl::Query& query : it->second.queries) query = gl::createQuery(GL_TIME_ELAPSED);
    return it->second;
}

const char* PassTimer::sourceLabel() const {
    return source_ == TimingSource::GpuQueries ? "GPU (timer queries)" : "CPU (software rasterizer, around glFinish)";
}

void PassTimer::begin(int which) {
    PassQueries& pass = this->pass(which);
    if (source_ == TimingSource::CpuAroundFinish) {
        glFinish();
        pass.cpuStart = std::chrono::steady_clock::now();
        return;
    }
    collect(pass, false);
    if (pass.pending[std::size_t(pass.next)]) collect(pass, true);  // ring full: only after kRing frames in flight
    glBeginQuery(GL_TIME_ELAPSED, pass.queries[std::size_t(pass.next)].id());
}

void PassTimer::end(int which) {
    PassQueries& pass = this->pass(which);
    if (source_ == TimingSource::CpuAroundFinish) {
        glFinish();
        pass.latest = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - pass.cpuStart).count();
        return;
    }
    glEndQuery(GL_TIME_ELAPSED);
    pass.pending[std::size_t(pass.next)] = true;
    pass.next = (pass.next + 1) % kRing;
}

void PassTimer::collect(PassQueries& pass, bool wait) {
    // Oldest first, so `latest` ends at the newest finished query.
    for (int i = 0; i < kRing; ++i) {
        const int slot = (pass.next + i) % kRing;
        if (!pass.pending[std::size_t(slot)]) continue;
        const GLuint id = pass.queries[std::size_t(slot)].id();
        GLint available = GL_FALSE;
        if (!wait) glGetQueryObjectiv(id, GL_QUERY_RESULT_AVAILABLE, &available);
        if (!wait && available != GL_TRUE) break;
        GLuint64 nanoseconds = 0;
        glGetQueryObjectui64v(id, GL_QUERY_RESULT, &nanoseconds);
        pass.latest = double(nanoseconds) * 1e-6;
        pass.pending[std::size_t(slot)] = false;
    }
}

std::optional<double> PassTimer::latestMilliseconds(int which, bool wait) {
    PassQueries& pass = this->pass(which);
    if (source_ == TimingSource::GpuQueries) collect(pass, wait);
    return pass.latest;
}

}  // namespace shadowlab
