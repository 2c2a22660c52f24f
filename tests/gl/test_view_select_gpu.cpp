// The view selection's three copies agree: the CPU's (views/view_select.cpp), the main pass's GLSL
// (shaders/shadow/view_select.glsl, compiled through the same #include the main pass uses) and the hardware's
// cube-map lookup (which face a samplerCubeArray reads for a direction) on many random points.
#include "gl_fixture.h"

#include "gl/gl_objects.h"
#include "gl/program.h"
#include "views/view_select.h"

#include <gtest/gtest.h>

#include <random>

using namespace shadowlab;
using namespace shadowlab::test;

namespace {

// For each direction: the GLSL selection, and the face whose layer the hardware's cube lookup read (each face's
// layer is filled with its own index).
constexpr const char* kSelectionProbe = R"(#version 450 core
layout(local_size_x = 64) in;
#include "shadow/view_select.glsl"
layout(std430, binding = 0) readonly buffer Directions { vec4 directions[]; };
layout(std430, binding = 1) writeonly buffer Faces { ivec2 faces[]; };
uniform samplerCubeArray uFaceIds;
uniform int uCount;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(uCount)) return;
    vec3 d = directions[i].xyz;
    faces[i] = ivec2(cubeFaceOf(d), int(round(textureLod(uFaceIds, vec4(d, 0.0), 0.0).r)));
}
)";

}  // namespace

class ViewSelectionGpu : public GlTest {};

TEST_F(ViewSelectionGpu, CpuGlslAndTheHardwaresCubeLookupPickTheSameFace) {
    const int count = 50000;
    std::mt19937 rng(2011);
    std::uniform_real_distribution<float> coord(-1.0f, 1.0f);
    std::vector<glm::vec4> directions;
    while (int(directions.size()) < count) {
        const glm::vec4 d(coord(rng), coord(rng), coord(rng), 0.0f);
        // A tie between two axes is the implementation's choice (GL 4.5, 8.13): keep 1e-4 away from one.
        const glm::vec3 a = glm::abs(glm::vec3(d));
        const float hi = std::max({a.x, a.y, a.z});
        const float mid = a.x + a.y + a.z - hi - std::min({a.x, a.y, a.z});
        if (hi - mid > 1e-4f * hi) directions.push_back(d);
    }

    gl::Texture ids = gl::createTexture(GL_TEXTURE_CUBE_MAP_ARRAY);
    glTextureStorage3D(ids.id(), 1, GL_R32F, 4, 4, 6);
    for (int face = 0; face < 6; ++face) {
        const float value = float(face);
        glClearTexSubImage(ids.id(), 0, 0, 0, face, 4, 4, 1, GL_RED, GL_FLOAT, &value);
    }
    glTextureParameteri(ids.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(ids.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    gl::Buffer in = gl::createBuffer(), out = gl::createBuffer();
    glNamedBufferData(in.id(), GLsizeiptr(directions.size() * sizeof(glm::vec4)), directions.data(), GL_STATIC_DRAW);
    glNamedBufferData(out.id(), GLsizeiptr(directions.size() * sizeof(glm::ivec2)), nullptr, GL_STATIC_READ);

    const gl::Program program = gl::buildProgram({{GL_COMPUTE_SHADER, "view_select_probe.comp", kSelectionProbe}}, {});
    glUseProgram(program.id());
    glUniform1i(glGetUniformLocation(program.id(), "uCount"), count);
    glUniform1i(glGetUniformLocation(program.id(), "uFaceIds"), 0);
    glBindTextureUnit(0, ids.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::ivec2> faces(directions.size());
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(faces.size() * sizeof(glm::ivec2)), faces.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
    glBindTextureUnit(0, 0);
    glUseProgram(0);

    int glslDiffers = 0, hardwareDiffers = 0;
    std::array<int, 6> perFace{};
    for (std::size_t i = 0; i < directions.size(); ++i) {
        const int cpu = cubeFaceOf(glm::dvec3(glm::vec3(directions[i])));
        glslDiffers += faces[i].x != cpu;
        hardwareDiffers += faces[i].y != cpu;
        if (cpu >= 0 && cpu < 6) ++perFace[std::size_t(cpu)];
    }
    EXPECT_EQ(glslDiffers, 0) << "of " << count << " directions, the GLSL selection differs from the CPU's";
    EXPECT_EQ(hardwareDiffers, 0) << "of " << count << " directions, the hardware's cube lookup reads another face";
    for (int f = 0; f < 6; ++f) EXPECT_GT(perFace[std::size_t(f)], count / 10) << "face " << f;
}

// A shader with an #include that does not exist fails to build with the file's name, not silently.
TEST_F(ViewSelectionGpu, AnUnknownIncludeIsNamed) {
    const char* text = "#version 450 core\nlayout(local_size_x = 1) in;\n#include \"shadow/nope.glsl\"\nvoid main() {}\n";
    try {
        gl::buildProgram({{GL_COMPUTE_SHADER, "broken.comp", text}}, {});
        FAIL() << "a missing include built";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("shadow/nope.glsl"), std::string::npos) << e.what();
    }
}

namespace {

// For each depth: the GLSL cascade choice for one light's far depths and blend starts.
constexpr const char* kCascadeProbe = R"(#version 450 core
layout(local_size_x = 64) in;
#include "shadow/view_select.glsl"
layout(std430, binding = 0) readonly buffer Depths { float depths[]; };
layout(std430, binding = 1) writeonly buffer Choices { vec4 choices[]; };
uniform vec4 uFar, uBlend;
uniform int uCascades, uCount;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(uCount)) return;
    CascadeChoice c = selectCascade(depths[i], uFar, uBlend, uCascades);
    choices[i] = vec4(float(c.view), float(c.next), c.weight, 0.0);
}
)";

}  // namespace

// The cascade a depth selects, its blend partner and weight: the GLSL and the CPU agree for 1..4 cascades, with and
// without a blend band, on depths across every split and beyond the last.
TEST_F(ViewSelectionGpu, CpuAndGlslPickTheSameCascadeAndBlend) {
    const int count = 20000;
    const gl::Program program = gl::buildProgram({{GL_COMPUTE_SHADER, "cascade_probe.comp", kCascadeProbe}}, {});
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> depth(0.0f, 130.0f);
    std::vector<float> depths(count);
    for (float& d : depths) d = depth(rng);
    gl::Buffer in = gl::createBuffer(), out = gl::createBuffer();
    glNamedBufferData(in.id(), GLsizeiptr(depths.size() * sizeof(float)), depths.data(), GL_STATIC_DRAW);
    glNamedBufferData(out.id(), GLsizeiptr(depths.size() * sizeof(glm::vec4)), nullptr, GL_STATIC_READ);
    for (int cascades = 1; cascades <= 4; ++cascades)
        for (float band : {0.0f, 0.2f}) {
            std::vector<double> far, blend;
            glm::vec4 farV(0.0f), blendV(0.0f);
            float previous = 0.5f;
            for (int c = 0; c < cascades; ++c) {
                const float f = 120.0f * std::pow(float(c + 1) / float(cascades), 1.7f);
                const float b = c + 1 < cascades ? f - band * (f - previous) : f;
                far.push_back(f);
                blend.push_back(b);
                farV[c] = f;
                blendV[c] = b;
                previous = f;
            }
            glUseProgram(program.id());
            glUniform4fv(glGetUniformLocation(program.id(), "uFar"), 1, &farV.x);
            glUniform4fv(glGetUniformLocation(program.id(), "uBlend"), 1, &blendV.x);
            glUniform1i(glGetUniformLocation(program.id(), "uCascades"), cascades);
            glUniform1i(glGetUniformLocation(program.id(), "uCount"), count);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
            glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
            glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
            std::vector<glm::vec4> choices(depths.size());
            glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(choices.size() * sizeof(glm::vec4)), choices.data());
            int differs = 0, blended = 0, beyond = 0;
            for (std::size_t i = 0; i < depths.size(); ++i) {
                // The CPU in float inputs, as the shader reads them.
                const ViewChoice cpu = selectCascade(double(depths[i]), far, blend);
                const bool same = int(choices[i].x) == cpu.view && int(choices[i].y) == cpu.next &&
                                  std::abs(double(choices[i].z) - cpu.weight) < 1e-4;
                differs += !same;
                blended += cpu.next >= 0;
                beyond += cpu.view < 0;
            }
            EXPECT_EQ(differs, 0) << cascades << " cascades, band " << band;
            EXPECT_GT(beyond, 0);
            if (band > 0.0f && cascades > 1) EXPECT_GT(blended, 0);
        }
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
    glUseProgram(0);
}
