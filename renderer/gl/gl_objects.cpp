#include "gl/gl_objects.h"

namespace shadowlab::gl {

Buffer createBuffer() {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return Buffer(id);
}

VertexArray createVertexArray() {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return VertexArray(id);
}

Texture createTexture(GLenum target) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return Texture(id);
}

Sampler createSampler() {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    return Sampler(id);
}

Framebuffer createFramebuffer() {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return Framebuffer(id);
}

Renderbuffer createRenderbuffer() {
    GLuint id = 0;
    glCreateRenderbuffers(1, &id);
    return Renderbuffer(id);
}

Query createQuery(GLenum target) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return Query(id);
}

}  // namespace shadowlab::gl
