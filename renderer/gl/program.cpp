#include "gl/program.h"

#include <chrono>
#include <stdexcept>

namespace shadowlab::gl {

namespace {

// The info log of a shader or program (each has its own pair of query functions).
template <typename GetParameter, typename GetLog>
std::string infoLog(GLuint object, GetParameter getParameter, GetLog getLog) {
    GLint length = 0;
    getParameter(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(length > 0 ? length : 1), '\0');
    getLog(object, length, nullptr, log.data());
    return log;
}

}  // namespace

namespace {
thread_local ProgramBuildTally tally;
}

ProgramBuildTally programBuildTally() { return tally; }

Program buildProgram(const std::vector<ShaderStage>& stages, const std::vector<std::string>& defines,
                     const IncludeAliases& aliases) {
    const auto start = std::chrono::steady_clock::now();
    struct Count {  // tallied however the build ends (a failure throws)
        std::chrono::steady_clock::time_point start;
        ~Count() {
            ++tally.programs;
            tally.milliseconds +=
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        }
    } count{start};
    Program program(glCreateProgram());
    std::vector<Shader> shaders;
    for (const ShaderStage& stage : stages) {
        std::vector<std::string> files;
        const std::string source = preprocessedSource(stage.file, defines, stage.text, aliases, files);
        Shader shader(glCreateShader(stage.type));
        const char* text = source.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE) throw std::runtime_error("compiling " + stage.file + " " + sourceLegend(files) + ":\n" +
                                     infoLog(shader.id(), glGetShaderiv, glGetShaderInfoLog));
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) throw std::runtime_error("linking program:\n" + infoLog(program.id(), glGetProgramiv, glGetProgramInfoLog));
    for (const Shader& s : shaders) glDetachShader(program.id(), s.id());
    return program;
}

}  // namespace shadowlab::gl
