#include "hardcases/uniform_readback.h"

#include "gl/gl.h"

#include <cmath>

namespace shadowlab::hardcases {

std::vector<std::string> nonFiniteUniforms() {
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    std::vector<std::string> bad;
    if (program == 0) return {"no program bound"};
    GLint count = 0;
    glGetProgramiv(GLuint(program), GL_ACTIVE_UNIFORMS, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[128];
        GLint size = 0;
        GLenum type = 0;
        glGetActiveUniform(GLuint(program), GLuint(i), sizeof name, nullptr, &size, &type, name);
        int components = 0;
        switch (type) {
            case GL_FLOAT: components = 1; break;
            case GL_FLOAT_VEC2: components = 2; break;
            case GL_FLOAT_VEC3: components = 3; break;
            case GL_FLOAT_VEC4: components = 4; break;
            case GL_FLOAT_MAT3: components = 9; break;
            case GL_FLOAT_MAT4: components = 16; break;
            default: continue;
        }
        const GLint location = glGetUniformLocation(GLuint(program), name);
        if (location < 0) continue;  // a member of the Lights block: checked below, in the buffer
        float values[16] = {};
        glGetUniformfv(GLuint(program), location, values);
        for (int c = 0; c < components; ++c)
            if (!std::isfinite(values[c])) bad.push_back(name);
    }
    // The per-light data (matrices, positions, cone, texel sizes) lives in the uniform buffer at binding 0.
    GLint buffer = 0, bytes = 0;
    glGetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, 0, &buffer);
    if (buffer != 0) {
        glGetNamedBufferParameteriv(GLuint(buffer), GL_BUFFER_SIZE, &bytes);
        std::vector<float> block(std::size_t(bytes) / sizeof(float));
        glGetNamedBufferSubData(GLuint(buffer), 0, GLsizeiptr(block.size() * sizeof(float)), block.data());
        for (std::size_t i = 0; i < block.size(); ++i)
            if (!std::isfinite(block[i])) bad.push_back("Lights block float " + std::to_string(i));
    }
    return bad;
}

}  // namespace shadowlab::hardcases
