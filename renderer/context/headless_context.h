#pragma once
// A GL 4.5 core context with no window and no X: EGL on a device (NVIDIA, Mesa) or Mesa's surfaceless platform.
// Used by the CLI, tests and benchmarks; rendering goes to framebuffer objects.
#include <memory>
#include <string>

namespace shadowlab {

class HeadlessContext {
public:
    // Throws std::runtime_error naming the EGL step that failed.
    explicit HeadlessContext(bool debug = false);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    void makeCurrent();
    const std::string& platform() const { return platform_; }  // how the display was found, for `shadowlab info`

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string platform_;
};

}  // namespace shadowlab
