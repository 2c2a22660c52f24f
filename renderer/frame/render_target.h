#pragma once
// Where the main pass draws: an RGBA8 colour texture and a depth buffer of the view's size. The editor shows the
// colour texture; the CLI reads it back to write a PNG.
#include "gl/gl_objects.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

class RenderTarget {
public:
    // Returns "" or why it could not be made (size outside the GPU's limits). colorFormat: GL_RGBA8 for pictures;
    // GL_RGBA32F where exact values are read back (the accuracy meter's shadow factor).
    std::string resize(int width, int height, GLenum colorFormat = GL_RGBA8);

    int width() const { return width_; }
    int height() const { return height_; }
    GLuint framebuffer() const { return framebuffer_.id(); }
    GLuint colorTexture() const { return color_.id(); }
    GLuint depthTexture() const { return depth_.id(); }  // GL_DEPTH_COMPONENT32F, window depth 0..1

    // RGBA8 pixels, row 0 = bottom (GL order).
    std::vector<std::uint8_t> readColor() const;
    // The window-space depth (0..1) of pixel (x, row) in GL order (row 0 = bottom); 1 where nothing was drawn.
    float readDepth(int x, int row) const;

private:
    gl::Texture color_;
    gl::Texture depth_;
    gl::Framebuffer framebuffer_;
    int width_ = 0;
    int height_ = 0;
    GLenum colorFormat_ = GL_RGBA8;
};

}  // namespace shadowlab
