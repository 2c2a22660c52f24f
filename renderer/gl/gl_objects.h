#pragma once
// RAII owners for GL object names: each deletes its object when destroyed; move-only.
#include "gl/gl.h"

#include <utility>

namespace shadowlab::gl {

template <typename Deleter>
class Handle {
public:
    Handle() = default;
    explicit Handle(GLuint id) : id_(id) {}
    ~Handle() { reset(); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_ != 0) Deleter{}(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

struct BufferDeleter { void operator()(GLuint id) const { glDeleteBuffers(1, &id); } };
struct VertexArrayDeleter { void operator()(GLuint id) const { glDeleteVertexArrays(1, &id); } };
struct TextureDeleter { void operator()(GLuint id) const { glDeleteTextures(1, &id); } };
struct SamplerDeleter { void operator()(GLuint id) const { glDeleteSamplers(1, &id); } };
struct FramebufferDeleter { void operator()(GLuint id) const { glDeleteFramebuffers(1, &id); } };
struct RenderbufferDeleter { void operator()(GLuint id) const { glDeleteRenderbuffers(1, &id); } };
struct ProgramDeleter { void operator()(GLuint id) const { glDeleteProgram(id); } };
struct ShaderDeleter { void operator()(GLuint id) const { glDeleteShader(id); } };
struct QueryDeleter { void operator()(GLuint id) const { glDeleteQueries(1, &id); } };

using Buffer = Handle<BufferDeleter>;
using VertexArray = Handle<VertexArrayDeleter>;
using Texture = Handle<TextureDeleter>;
using Sampler = Handle<SamplerDeleter>;
using Framebuffer = Handle<FramebufferDeleter>;
using Renderbuffer = Handle<RenderbufferDeleter>;
using Program = Handle<ProgramDeleter>;
using Shader = Handle<ShaderDeleter>;
using Query = Handle<QueryDeleter>;

// Creation with DSA (GL 4.5): the object exists (and has its type) as soon as it is created.
Buffer createBuffer();
VertexArray createVertexArray();
Texture createTexture(GLenum target);
Sampler createSampler();
Framebuffer createFramebuffer();
Renderbuffer createRenderbuffer();
Query createQuery(GLenum target);

}  // namespace shadowlab::gl
