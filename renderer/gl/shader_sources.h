#pragma once
// GLSL sources from shaders/, embedded at build time by scripts/embed_shaders.py.
#include <map>
#include <string>

namespace shadowlab {
const std::map<std::string, std::string>& embeddedShaderSources();
}
