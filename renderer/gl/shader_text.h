#pragma once
// The text half of building a GLSL program, no GL: an embedded shader source with #defines after its #version and
// each `#include "name"` replaced by the embedded file (recursively, each file once; #line keeps the compiler's line
// numbers). The renderer compiles this text (gl/program.h); the export prints it (export/), so an exported shader is
// the renderer's own file, not a copy.
#include <map>
#include <string>
#include <vector>

namespace shadowlab::gl {

// `#include "alias:NAME"` includes the file the aliases map it to (a variant's choice of file, e.g. the filter
// technique's lookup).
using IncludeAliases = std::map<std::string, std::string>;

// The full text handed to the compiler for one stage: the embedded `file`, or `text` when given. Defines are "NAME" or
// "NAME VALUE". `files` receives the name of each #line source number (0 = `file`). Throws std::runtime_error for a
// file that is not embedded or a malformed #include.
std::string preprocessedSource(const std::string& file, const std::vector<std::string>& defines,
                               const std::string& text, const IncludeAliases& aliases, std::vector<std::string>& files);
std::string preprocessedSource(const std::string& file, const std::vector<std::string>& defines,
                               const std::string& text = {}, const IncludeAliases& aliases = {});

// "(sources: 0 = main.frag.glsl, 1 = shadow/view_select.glsl, ...)": which file each #line number is.
std::string sourceLegend(const std::vector<std::string>& files);

}  // namespace shadowlab::gl
