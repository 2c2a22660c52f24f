#include "context/headless_context.h"

#include "gl/gl.h"

#include <glad/egl.h>

#include <map>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace shadowlab {

namespace {

// EGL hands every context on one device the same display, and eglTerminate ends all of them: two headless contexts
// in one process (the editor's accuracy worker beside a test's) must share it, so it is terminated with the last.
std::mutex& displayMutex() {
    static std::mutex mutex;
    return mutex;
}
std::map<void*, int>& displayUsers() {
    static std::map<void*, int> users;
    return users;
}

std::string eglErrorText(const char* step) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", unsigned(eglGetError()));
    return std::string("headless EGL: ") + step + " failed (EGL error " + code + ")";
}

// Tries each EGL device in turn (NVIDIA's GPU, Mesa's software device), then Mesa's surfaceless platform.
EGLDisplay openDisplay(std::string& platform) {
    if (eglQueryDevicesEXT && eglGetPlatformDisplayEXT) {
        EGLint count = 0;
        if (eglQueryDevicesEXT(0, nullptr, &count) && count > 0) {
            std::vector<EGLDeviceEXT> devices(std::size_t(count), nullptr);
            eglQueryDevicesEXT(count, devices.data(), &count);
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[std::size_t(i)], nullptr);
                EGLint major = 0, minor = 0;
                if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor)) {
                    platform = "EGL device " + std::to_string(i) + " of " + std::to_string(count);
                    return dpy;
                }
            }
        }
    }
    if (eglGetPlatformDisplayEXT) {
        EGLDisplay dpy = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        EGLint major = 0, minor = 0;
        if (dpy != EGL_NO_DISPLAY && eglInitialize(dpy, &major, &minor)) {
            platform = "EGL surfaceless (Mesa)";
            return dpy;
        }
    }
    throw std::runtime_error(eglErrorText("finding a display (no EGL device and no surfaceless platform)"));
}

}  // namespace

HeadlessContext::HeadlessContext(bool debug) {
    std::lock_guard<std::mutex> lock(displayMutex());
    // glad's entry points are process-wide: load them only for the first context, so that a second one (the editor's
    // accuracy worker) never rewrites pointers another thread is calling through.
    const bool firstContext = displayUsers().empty();
    // Before eglInitialize glad only sees EGL 1.0 plus client extensions: that is why the EXT entry points are used.
    if (firstContext && !gladLoaderLoadEGL(EGL_NO_DISPLAY)) throw std::runtime_error("headless EGL: cannot load libEGL");
    EGLDisplay dpy = openDisplay(platform_);
    display_ = dpy;
    ++displayUsers()[dpy];
    if (firstContext && !gladLoaderLoadEGL(dpy))
        throw std::runtime_error("headless EGL: cannot load EGL for the display");
    if (!eglBindAPI(EGL_OPENGL_API)) throw std::runtime_error(eglErrorText("eglBindAPI(EGL_OPENGL_API)"));

    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION, 4,
        EGL_CONTEXT_MINOR_VERSION, 5,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
        EGL_NONE,
    };
    EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (ctx == EGL_NO_CONTEXT) throw std::runtime_error(eglErrorText("creating a GL 4.5 core context"));
    context_ = ctx;
    makeCurrent();
    // GL entry points from libglvnd dispatch on the calling thread's current context, whichever API made it (GLX in
    // the editor's window, EGL here): once loaded they serve every context.
    if (!GLAD_GL_VERSION_4_5 && !gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)))
        throw std::runtime_error("headless EGL: cannot load the GL 4.5 functions");
}

HeadlessContext::~HeadlessContext() {
    std::lock_guard<std::mutex> lock(displayMutex());
    auto dpy = static_cast<EGLDisplay>(display_);
    if (dpy != EGL_NO_DISPLAY && dpy != nullptr) {
        // Releases this thread's current context only if it is ours; another thread's context stays current.
        if (eglGetCurrentContext() == static_cast<EGLContext>(context_))
            eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context_) eglDestroyContext(dpy, static_cast<EGLContext>(context_));
        if (--displayUsers()[dpy] <= 0) {
            displayUsers().erase(dpy);
            eglTerminate(dpy);
        }
    }
}

void HeadlessContext::makeCurrent() {
    if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                        static_cast<EGLContext>(context_)))
        throw std::runtime_error(eglErrorText("eglMakeCurrent"));
}

}  // namespace shadowlab
