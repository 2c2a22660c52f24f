#include "accuracy/gpu_accuracy_counter.h"

#include "accuracy/accuracy_metrics.h"
#include "gl/program.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

namespace shadowlab {

namespace {

constexpr GLuint kGroupSize = 256;
// The count pass keeps its counts in registers over this many pixels per invocation, then adds them once: atomics
// per pixel cost most on a software rasterizer, and a GPU still gets one invocation per 8 pixels.
constexpr GLuint kPixelsPerInvocation = 8;
constexpr std::uint32_t kOnBoundary = 0x100;  // flag beside the class code

// Each count the shader keeps, by its slot name there and the field it fills here: the one list of both.
using CountField = std::size_t AccuracyCounts::*;
constexpr std::array<std::pair<const char*, CountField>, 16> kCountSlots{{
    {"C_BACKGROUND", &AccuracyCounts::background},
    {"C_NON_FINITE", &AccuracyCounts::nonFinite},
    {"C_FACING_AWAY", &AccuracyCounts::facingAway},
    {"C_OUTSIDE_CONE", &AccuracyCounts::outsideCone},
    {"C_MEASURED", &AccuracyCounts::measured},
    {"C_LIT", &AccuracyCounts::lit},
    {"C_SHADOWED", &AccuracyCounts::shadowed},
    {"C_ACNE", &AccuracyCounts::acne},
    {"C_LEAK", &AccuracyCounts::leak},
    {"C_WRONG", &AccuracyCounts::wrong},
    {"C_WRONG_BEYOND_K", &AccuracyCounts::wrongBeyondK},
    {"C_MISMATCHED", &AccuracyCounts::mismatched},
    {"C_MISMATCHED_WITHIN_K", &AccuracyCounts::mismatchedWithinK},
    {"C_SHADOWED_NEAR_EDGE", &AccuracyCounts::shadowedNearEdge},
    {"C_BOUNDARY", &AccuracyCounts::boundaryPixels},
    {"C_COVERAGE_MISMATCH", &AccuracyCounts::coverageMismatch},
}};
// After the counts: the unresolved pixels' number, then per edge-error key its remaining rank and picked bits.
constexpr GLuint kWordUnresolved = GLuint(kCountSlots.size());
constexpr GLuint kWordListed = kWordUnresolved + 1;
constexpr GLuint kWordRank = kWordListed + 1;
constexpr GLuint kWordPrefix = kWordRank + 3;
constexpr GLuint kWords = kWordPrefix + 3;

enum Stage { Count = 1, Finish, Histogram, Pick };

gl::Program buildStage(Stage stage) {
    std::vector<std::string> defines = {
        "STAGE_COUNT 1", "STAGE_FINISH 2", "STAGE_HISTOGRAM 3", "STAGE_PICK 4",
        "STAGE " + std::to_string(int(stage)), "GROUP_SIZE " + std::to_string(kGroupSize),
        "COUNT_SLOTS " + std::to_string(kCountSlots.size()), "WORD_UNRESOLVED " + std::to_string(kWordUnresolved),
        "WORD_LISTED " + std::to_string(kWordListed), "WORD_RANK " + std::to_string(kWordRank),
        "PIXELS_PER_INVOCATION " + std::to_string(kPixelsPerInvocation), "WORD_PREFIX " + std::to_string(kWordPrefix),
        "FLAG_ON_BOUNDARY " + std::to_string(kOnBoundary) + "u"};
    for (std::size_t slot = 0; slot < kCountSlots.size(); ++slot)
        defines.push_back(std::string(kCountSlots[slot].first) + " " + std::to_string(slot) + "u");
    for (auto [name, cls] : {std::pair{"CLASS_BACKGROUND", PixelClass::Background},
                             std::pair{"CLASS_NON_FINITE", PixelClass::NonFinite},
                             std::pair{"CLASS_FACING_AWAY", PixelClass::FacingAway},
                             std::pair{"CLASS_OUTSIDE_CONE", PixelClass::OutsideCone},
                             std::pair{"CLASS_LIT", PixelClass::Lit}})
        defines.push_back(std::string(name) + " " + std::to_string(int(cls)) + "u");
    return gl::buildProgram({{GL_COMPUTE_SHADER, "accuracy_count.comp.glsl"}}, defines);
}

gl::Buffer makeBuffer(std::size_t bytes, const void* data = nullptr) {
    gl::Buffer buffer = gl::createBuffer();
    glNamedBufferStorage(buffer.id(), GLsizeiptr(std::max<std::size_t>(bytes, 16)), data, GL_DYNAMIC_STORAGE_BIT);
    return buffer;
}

// Infinity stays out of the GPU's buffers (fast-math compilers may assume finite floats): the largest float orders
// the same against k and the cap.
float finite(float v) { return std::isfinite(v) ? v : FLT_MAX; }

std::array<std::uint32_t, 4> referenceTexel(const DistanceState& s, std::uint32_t flags) {
    std::array<std::uint32_t, 4> texel{};
    const float values[3] = {finite(s.visible), finite(s.flipAt), finite(s.probedTo)};
    std::memcpy(texel.data(), values, sizeof values);
    texel[3] = flags;
    return texel;
}

GLuint countGroups(std::size_t pixels) {
    const std::size_t perGroup = std::size_t(kGroupSize) * kPixelsPerInvocation;
    return GLuint((pixels + perGroup - 1) / perGroup);
}

// Inverse of the shader's orderBits.
float fromOrderBits(std::uint32_t bits) {
    const std::uint32_t raw = (bits & 0x80000000u) != 0 ? bits & 0x7FFFFFFFu : ~bits;
    float value;
    std::memcpy(&value, &raw, sizeof value);
    return value;
}

}  // namespace

GpuAccuracyCounter::GpuAccuracyCounter()
    : countProgram_(buildStage(Count)),
      finishProgram_(buildStage(Finish)),
      histogramProgram_(buildStage(Histogram)),
      pickProgram_(buildStage(Pick)),
      words_(makeBuffer(kWords * sizeof(std::uint32_t))),
      sums_(makeBuffer(2 * sizeof(double))),
      histogram_(makeBuffer(3 * 256 * sizeof(std::uint32_t))),
      dispatch_(makeBuffer(3 * sizeof(GLuint))) {
    glClearNamedBufferData(histogram_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
}

void GpuAccuracyCounter::upload(int width, int height, const std::vector<PixelClass>& classes,
                                ShadowBoundary& boundary, double k, const std::vector<float>& worldPerTexel,
                                const std::vector<float>& screenPixelsPerTexel) {
    const std::size_t count = std::size_t(width) * std::size_t(height);
    boundary.prepareVisible();
    flags_.resize(count);
    std::vector<std::array<std::uint32_t, 4>> reference(count);
    std::vector<float> units(count * 2);
    for (std::size_t i = 0; i < count; ++i) {
        flags_[i] = std::uint32_t(classes[i]) | (boundary.onBoundary(i) ? kOnBoundary : 0u);
        reference[i] = referenceTexel(boundary.state(i, k), flags_[i]);
        units[2 * i] = worldPerTexel[i];
        units[2 * i + 1] = screenPixelsPerTexel[i];
    }
    if (width != width_ || height != height_) {
        partials_ = makeBuffer(countGroups(count) * 2 * sizeof(double));
        listed_ = makeBuffer(count * sizeof(std::uint32_t));
        keys_ = makeBuffer(count * sizeof(float));
        unresolved_ = makeBuffer(count * sizeof(std::uint32_t));
        reference_ = makeBuffer(count * 4 * sizeof(std::uint32_t));
        units_ = makeBuffer(count * 2 * sizeof(float));
        width_ = width;
        height_ = height;
    }
    glNamedBufferSubData(reference_.id(), 0, GLsizeiptr(count * 4 * sizeof(std::uint32_t)), reference.data());
    glNamedBufferSubData(units_.id(), 0, GLsizeiptr(count * 2 * sizeof(float)), units.data());
}

void GpuAccuracyCounter::update(const std::vector<std::uint32_t>& pixels, ShadowBoundary& boundary, double k) {
    if (pixels.empty()) return;
    // One upload of the range they span (they cluster where the edit changed the picture).
    const auto [lo, hi] = std::minmax_element(pixels.begin(), pixels.end());
    std::vector<std::array<std::uint32_t, 4>> range(std::size_t(*hi - *lo) + 1);
    for (std::size_t i = *lo; i <= *hi; ++i) range[i - *lo] = referenceTexel(boundary.state(i, k), flags_[i]);
    glNamedBufferSubData(reference_.id(), GLintptr(std::size_t(*lo) * sizeof(range[0])),
                         GLsizeiptr(range.size() * sizeof(range[0])), range.data());
}

void GpuAccuracyCounter::dispatch(const gl::Program& program, GLuint groups) {
    glUseProgram(program.id());
    if (groups > 0)
        glDispatchCompute(groups, 1, 1);
    else
        glDispatchComputeIndirect(0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

GpuAccuracyCounter::Result GpuAccuracyCounter::count(GLuint shadowTexture, double k, double cap, bool probing) {
    Result result;
    const std::size_t pixels = std::size_t(width_) * std::size_t(height_);
    const GLuint groups = countGroups(pixels);
    glClearNamedBufferData(words_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    const GLuint buffers[10] = {words_.id(),     sums_.id(),  partials_.id(),  keys_.id(),    unresolved_.id(),
                                reference_.id(), units_.id(), histogram_.id(), listed_.id(), dispatch_.id()};
    glBindBuffersBase(GL_SHADER_STORAGE_BUFFER, 0, 10, buffers);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_.id());
    glBindTextureUnit(0, shadowTexture);
    glBindSampler(0, 0);
    auto set = [](const gl::Program& program, auto&& fn) {
        glUseProgram(program.id());
        fn(program.id());
    };
    set(countProgram_, [&](GLuint p) {
        glUniform2i(glGetUniformLocation(p, "uSize"), width_, height_);
        glUniform1f(glGetUniformLocation(p, "uK"), float(k));
        glUniform1f(glGetUniformLocation(p, "uCap"), float(cap));
        glUniform1f(glGetUniformLocation(p, "uLitBelow"), kLitBelow);
        glUniform1f(glGetUniformLocation(p, "uShadowedAbove"), kVisibleStep);
        glUniform1d(glGetUniformLocation(p, "uWrongError"), kWrongError);
        glUniform1i(glGetUniformLocation(p, "uProbing"), probing ? 1 : 0);
    });
    dispatch(countProgram_, groups);

    std::array<std::uint32_t, kWords> words{};
    glGetNamedBufferSubData(words_.id(), 0, sizeof words, words.data());
    if (const std::uint32_t n = words[kWordUnresolved]; n > 0) {
        result.unresolved.resize(n);
        glGetNamedBufferSubData(unresolved_.id(), 0, GLsizeiptr(n * sizeof(std::uint32_t)), result.unresolved.data());
    } else {
        set(finishProgram_, [&](GLuint p) {
            glUniform1ui(glGetUniformLocation(p, "uPartials"), groups);
            glUniform1ui(glGetUniformLocation(p, "uPercent"), GLuint(kEdgeErrorPercentile));
        });
        dispatch(finishProgram_, 1);
        for (int shift = 24; shift >= 0; shift -= 8) {
            set(histogramProgram_, [&](GLuint p) { glUniform1i(glGetUniformLocation(p, "uShift"), shift); });
            dispatch(histogramProgram_, 0);
            set(pickProgram_, [&](GLuint p) { glUniform1i(glGetUniformLocation(p, "uShift"), shift); });
            dispatch(pickProgram_, 1);
        }
        glGetNamedBufferSubData(words_.id(), 0, sizeof words, words.data());
        double sums[2] = {0.0, 0.0};
        glGetNamedBufferSubData(sums_.id(), 0, sizeof sums, sums);
        AccuracyCounts& c = result.numbers.counts;
        c.pixels = pixels;
        for (std::size_t slot = 0; slot < kCountSlots.size(); ++slot) c.*kCountSlots[slot].second = words[slot];
        setRatios(result.numbers, sums[0], sums[1]);
        if (c.mismatched > 0) {
            result.numbers.edgeErrorP95Texels = fromOrderBits(words[kWordPrefix]);
            result.numbers.edgeErrorP95World = fromOrderBits(words[kWordPrefix + 1]);
            result.numbers.edgeErrorP95ScreenPixels = fromOrderBits(words[kWordPrefix + 2]);
        }
    }
    glBindBuffersBase(GL_SHADER_STORAGE_BUFFER, 0, 10, nullptr);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glBindTextureUnit(0, 0);
    glUseProgram(0);
    return result;
}

}  // namespace shadowlab
