#pragma once
// The nearest and farthest depth written into a depth texture, reduced on the GPU (shaders/depth_range.comp.glsl):
// used by the map viewer's auto contrast (a shadow map, or one channel of a moments map: every finite value counts)
// and by the depth-bounds fit (the camera's depth). A dispatch and its read-back are separate calls, so a caller can
// read a frame later without waiting for the GPU.
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
    // channel >= 0: the range of that channel (0..3) of a float or normalized 2D texture instead, negative values
    // and the clear value included.
    void dispatch(GLuint texture, int width, int height, bool reversedZ, int channel = -1);
    // The last dispatch's result (waits for it if the GPU has not finished); nullopt: every texel was at the clear
    // depth (nothing drawn), or nothing was dispatched.
    std::optional<WrittenDepths> read();
    bool pending() const { return pending_; }

private:
    gl::Program program_;
    GLint reversedZ_ = -1;
    GLint channel_ = -1;
    bool channelPending_ = false;  // the pending dispatch reduced a channel (ordered bits of any sign)
    gl::Sampler rawSampler_;  // nearest, no comparison: reads stored depth
    gl::Buffer buffer_;       // two uints: min and max of written depths (float bits)
    bool pending_ = false;
};

}  // namespace shadowlab
