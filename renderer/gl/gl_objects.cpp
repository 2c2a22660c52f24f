#include "gl/gl_objects.h"

namespace shadowlab::gl {

namespace {

// Every glCreate* call has the shape (count, names) once any target is bound in.
template <typename Owner, typename CreateNames>
Owner create(CreateNames createNames) {
    GLuint id = 0;
    createNames(1, &id);
    return Owner(id);
}

}  // namespace

Buffer createBuffer() { return create<Buffer>(glCreateBuffers); }
VertexArray createVertexArray() { return create<VertexArray>(glCreateVertexArrays); }
Sampler createSampler() { return create<Sampler>(glCreateSamplers); }
Framebuffer createFramebuffer() { return create<Framebuffer>(glCreateFramebuffers); }
Renderbuffer createRenderbuffer() { return create<Renderbuffer>(glCreateRenderbuffers); }

Texture createTexture(GLenum target) {
    return create<Texture>([target](GLsizei n, GLuint* ids) { glCreateTextures(target, n, ids); });
}

Query createQuery(GLenum target) {
    return create<Query>([target](GLsizei n, GLuint* ids) { glCreateQueries(target, n, ids); });
}

}  // namespace shadowlab::gl
