#include "frame/render_target.h"

namespace shadowlab {

std::string RenderTarget::resize(int width, int height, GLenum colorFormat) {
    if (width == width_ && height == height_ && colorFormat == colorFormat_ && framebuffer_) return {};
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
    if (width < 1 || height < 1 || width > maxSize || height > maxSize)
        return "view size " + std::to_string(width) + "x" + std::to_string(height) + " is outside [1, " +
               std::to_string(maxSize) + "]";
    gl::Texture color = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(color.id(), 1, colorFormat, width, height);
    glTextureParameteri(color.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(color.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    // A texture, not a renderbuffer: the depth-bounds pass reduces it in a compute shader.
    gl::Texture depth = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(depth.id(), 1, GL_DEPTH_COMPONENT32F, width, height);
    gl::Framebuffer framebuffer = gl::createFramebuffer();
    glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, color.id(), 0);
    glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    if (glCheckNamedFramebufferStatus(framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return "view framebuffer incomplete";
    color_ = std::move(color);
    depth_ = std::move(depth);
    framebuffer_ = std::move(framebuffer);
    width_ = width;
    height_ = height;
    colorFormat_ = colorFormat;
    return {};
}

std::vector<std::uint8_t> RenderTarget::readColor() const {
    std::vector<std::uint8_t> pixels(std::size_t(width_) * height_ * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(color_.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
    return pixels;
}

float RenderTarget::readDepth(int x, int row) const {
    float depth = 1.0f;
    if (!framebuffer_ || x < 0 || row < 0 || x >= width_ || row >= height_) return depth;
    GLint previous = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(x, row, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previous));
    return depth;
}

}  // namespace shadowlab
