#include "gl/depth_range_reduction.h"

#include "gl/program.h"

#include <cstring>
#include <string>

namespace shadowlab {

namespace {

constexpr GLuint kDepthUnit = 0;
constexpr GLuint kNothingBits = 0xFFFFFFFFu;
constexpr int kTexelsPerInvocation = 8;  // depth_range.comp.glsl reads BLOCK x BLOCK texels per invocation
constexpr int kGroupSize = 16;           // its local size

float fromBits(GLuint bits) {
    float value = 0.0f;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

}  // namespace

DepthRangeReduction::DepthRangeReduction()
    : program_(gl::buildProgram({{GL_COMPUTE_SHADER, "depth_range.comp.glsl"}},
                                {"BLOCK " + std::to_string(kTexelsPerInvocation)})),
      reversedZ_(glGetUniformLocation(program_.id(), "uReversedZ")),
      channel_(glGetUniformLocation(program_.id(), "uChannel")),
      rawSampler_(gl::createSampler()),
      buffer_(gl::createBuffer()) {
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(rawSampler_.id(), GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glNamedBufferStorage(buffer_.id(), 2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void DepthRangeReduction::dispatch(GLuint texture, int width, int height, bool reversedZ, int channel) {
    const GLuint start[2] = {kNothingBits, 0u};
    glNamedBufferSubData(buffer_.id(), 0, sizeof start, start);
    glUseProgram(program_.id());
    glUniform1i(reversedZ_, reversedZ ? 1 : 0);
    glUniform1i(channel_, channel);
    channelPending_ = channel >= 0;
    glBindTextureUnit(kDepthUnit, texture);
    glBindSampler(kDepthUnit, rawSampler_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer_.id());
    const int perGroup = kGroupSize * kTexelsPerInvocation;
    glDispatchCompute(GLuint((width + perGroup - 1) / perGroup), GLuint((height + perGroup - 1) / perGroup), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glBindSampler(kDepthUnit, 0);
    glUseProgram(0);
    pending_ = true;
}

std::optional<WrittenDepths> DepthRangeReduction::read() {
    if (!pending_) return std::nullopt;
    pending_ = false;
    GLuint result[2] = {kNothingBits, 0u};
    glGetNamedBufferSubData(buffer_.id(), 0, sizeof result, result);
    if (result[0] == kNothingBits) return std::nullopt;
    if (channelPending_)  // ordered bits back to float bits (depth_range.comp.glsl: orderedBits)
        for (GLuint& bits : result) bits = (bits & 0x80000000u) ? bits & 0x7FFFFFFFu : ~bits;
    return WrittenDepths{fromBits(result[0]), fromBits(result[1])};
}

}  // namespace shadowlab
