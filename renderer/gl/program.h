#pragma once
// Links GLSL programs from the embedded shader sources, with #defines prepended after #version so one source
// file yields the shader variants the renderer needs. A line `#include "common/alpha_test.glsl"` is replaced by that
// embedded file (each file once per stage; #line keeps the compiler's line numbers, and a failure names the files),
// so a snippet several shaders need is written once.
#include "gl/gl_objects.h"
#include "gl/shader_text.h"  // IncludeAliases, preprocessedSource

#include <string>
#include <vector>

namespace shadowlab::gl {

struct ShaderStage {
    GLenum type;                       // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
    std::string file;                  // name under shaders/, e.g. "main.frag.glsl"
    std::string text;                  // when not empty: the source itself (tests), `file` only names it
};

// Defines are "NAME" or "NAME VALUE". Throws std::runtime_error with the compiler/linker log on failure
// (a shader that does not compile is a bug in the tool, not a user error).
Program buildProgram(const std::vector<ShaderStage>& stages, const std::vector<std::string>& defines,
                     const IncludeAliases& aliases = {});

// Programs built on this thread (GL contexts are per thread) since it started, and the wall time they took
// (preprocess, compile, link: the first frame's hidden cost, which the accuracy cost reports).
struct ProgramBuildTally {
    int programs = 0;
    double milliseconds = 0.0;
};
ProgramBuildTally programBuildTally();

}  // namespace shadowlab::gl
