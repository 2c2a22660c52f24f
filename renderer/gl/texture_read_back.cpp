#include "gl/texture_read_back.h"

namespace shadowlab::gl {

bool TextureReadBack::read(GLuint texture, GLenum format, GLenum type, std::size_t bytes,
                           const std::function<void(const void* pixels)>& use) {
    if (!buffer_ || capacity_ != bytes) {
        // Immutable storage the CPU only reads: the driver places it where a mapped read is fast.
        buffer_ = createBuffer();
        glNamedBufferStorage(buffer_.id(), GLsizeiptr(bytes), nullptr, GL_MAP_READ_BIT | GL_CLIENT_STORAGE_BIT);
        capacity_ = bytes;
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer_.id());
    glGetTextureImage(texture, 0, format, type, GLsizei(bytes), nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    const void* pixels = glMapNamedBufferRange(buffer_.id(), 0, GLsizeiptr(bytes), GL_MAP_READ_BIT);
    if (!pixels) return false;
    use(pixels);
    glUnmapNamedBuffer(buffer_.id());
    return true;
}

}  // namespace shadowlab::gl
