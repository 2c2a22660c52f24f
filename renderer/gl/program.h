#pragma once
// Links GLSL programs from the embedded shader sources, with #defines prepended after #version so one source
// file yields the shader variants the renderer needs.
#include "gl/gl_objects.h"

#include <string>
#include <vector>

namespace shadowlab::gl {

struct ShaderStage {
    GLenum type;                       // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
    std::string file;                  // name under shaders/, e.g. "main.frag.glsl"
};

// Defines are "NAME" or "NAME VALUE". Throws std::runtime_error with the compiler/linker log on failure
// (a shader that does not compile is a bug in the tool, not a user error).
Program buildProgram(const std::vector<ShaderStage>& stages, const std::vector<std::string>& defines);

// The full text handed to the compiler for one stage (for logs and tests).
std::string preprocessedSource(const std::string& file, const std::vector<std::string>& defines);

}  // namespace shadowlab::gl
