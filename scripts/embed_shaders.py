#!/usr/bin/env python3
"""Writes a C++ file that maps each shader file's path under the shaders folder ("main.frag.glsl",
"shadow/view_select.glsl") to its GLSL source (see renderer/gl/shader_sources.h).
Usage: embed_shaders.py OUT.cpp SHADERS_DIR FILE..."""
import os
import sys

out, root, files = sys.argv[1], sys.argv[2], sorted(sys.argv[3:])
lines = ['#include "gl/shader_sources.h"', '', 'namespace shadowlab {', '',
         'const std::map<std::string, std::string>& embeddedShaderSources() {',
         '    static const std::map<std::string, std::string> sources = {']
for path in files:
    with open(path, encoding='utf-8') as f:
        text = f.read()
    delim = 'GLSL_'
    name = os.path.relpath(path, root).replace(os.sep, '/')
    lines.append('        {"%s", R"%s(%s)%s"},' % (name, delim, text, delim))
lines += ['    };', '    return sources;', '}', '', '}  // namespace shadowlab', '']
tmp = out + '.tmp'
with open(tmp, 'w', encoding='utf-8') as f:
    f.write('\n'.join(lines))
os.replace(tmp, out)
