#include "gl/gl_errors.h"

#include <mutex>
#include <utility>

namespace shadowlab::gl {

namespace {

std::mutex debugMutex;
std::vector<std::string> debugErrors;

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void* userParam) {
    (void)source;
    (void)id;
    (void)severity;
    (void)userParam;
    if (type != GL_DEBUG_TYPE_ERROR) return;
    std::lock_guard lock(debugMutex);
    debugErrors.emplace_back(message, length > 0 ? std::size_t(length) : std::char_traits<char>::length(message));
}

}  // namespace

void enableDebugOutput() {
    if (!glDebugMessageCallback) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

std::vector<std::string> takeDebugErrors() {
    std::lock_guard lock(debugMutex);
    return std::exchange(debugErrors, {});
}

const char* errorName(GLenum error) {
    switch (error) {
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
        case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
        default: return "GL error";
    }
}

std::string drainErrors() {
    std::string names;
    for (int guard = 0; guard < 32; ++guard) {
        GLenum e = glGetError();
        if (e == GL_NO_ERROR) break;
        if (!names.empty()) names += ", ";
        names += errorName(e);
    }
    return names;
}

}  // namespace shadowlab::gl
