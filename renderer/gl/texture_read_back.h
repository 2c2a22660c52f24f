#pragma once
// Reads a texture's level 0 back through a pixel-pack buffer the driver copies into by DMA, then maps it for the
// caller to read in place. A glGetTextureImage straight into pageable memory ran at about 0.7 GB/s on the lent H200
// (47 ms for the accuracy meter's 1920x1080 RGBA32F frame); the buffer is kept between reads of the same size.
#include "gl/gl_objects.h"

#include <cstddef>
#include <functional>

namespace shadowlab::gl {

class TextureReadBack {
public:
    // Copies level 0 of `texture` as `format`/`type` (glGetTextureImage's), `bytes` in all, with pack alignment 4,
    // and calls `use` with the mapped bytes (valid only during the call). Returns false (without calling `use`)
    // when the buffer cannot be mapped.
    bool read(GLuint texture, GLenum format, GLenum type, std::size_t bytes,
              const std::function<void(const void* pixels)>& use);

private:
    Buffer buffer_;
    std::size_t capacity_ = 0;
};

}  // namespace shadowlab::gl
