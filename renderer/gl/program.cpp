#include "gl/program.h"

#include "gl/shader_sources.h"

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

std::string preprocessedSource(const std::string& file, const std::vector<std::string>& defines) {
    const auto& sources = embeddedShaderSources();
    auto it = sources.find(file);
    if (it == sources.end()) throw std::runtime_error("shader source not embedded: " + file);
    const std::string& text = it->second;
    // Keep "#version" first: defines go right after its line.
    std::size_t versionEnd = 0;
    if (text.rfind("#version", 0) == 0) versionEnd = text.find('\n') + 1;
    std::string out = text.substr(0, versionEnd);
    for (const std::string& d : defines) out += "#define " + d + "\n";
    out += "#line 2\n";
    out += text.substr(versionEnd);
    return out;
}

Program buildProgram(const std::vector<ShaderStage>& stages, const std::vector<std::string>& defines) {
    Program program(glCreateProgram());
    std::vector<Shader> shaders;
    for (const ShaderStage& stage : stages) {
        std::string source = preprocessedSource(stage.file, defines);
        Shader shader(glCreateShader(stage.type));
        const char* text = source.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE) throw std::runtime_error("compiling " + stage.file + ":\n" + infoLog(shader.id(), glGetShaderiv, glGetShaderInfoLog));
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
