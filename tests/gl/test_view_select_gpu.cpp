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
