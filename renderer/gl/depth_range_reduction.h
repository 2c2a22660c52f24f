#pragma once
// The nearest and farthest depth written into a depth texture, reduced on the GPU (shaders/depth_range.comp.glsl):
// used by the map viewer's auto contrast (a shadow map) and by the depth-bounds fit (the camera's depth). A dispatch
// and its read-back are separate calls, so a caller can read a frame later without waiting for the GPU.
#include "gl/gl_objects.h"

#include <optional>

namespace shadowlab {

struct WrittenDepths {
    float min = 0.0f, max = 0.0f;  // stored depths (1 - stored with reversedZ), texels at the clear depth left out
};

class DepthRangeReduction {
public:
    DepthRangeReduction();  // needs a current GL 4.5 context; throws std::runtime_error if the shader does not build

    // Starts the reduction of `texture` (a 2D depth texture of width x height); reversedZ: near 1, far 0.
    void dispatch(GLuint texture, int width, int height, bool reversedZ);
    // The last dispatch's result (waits for it if the GPU has not finished); nullopt: every texel was at the clear
    // depth (nothing drawn), or nothing was dispatched.
    std::optional<WrittenDepths> read();
    bool pending() const { return pending_; }

private:
    gl::Program program_;
    GLint reversedZ_ = -1;
    gl::Sampler rawSampler_;  // nearest, no comparison: reads stored depth
    gl::Buffer buffer_;       // two uints: min and max of written depths (float bits)
    bool pending_ = false;
};

}  // namespace shadowlab
