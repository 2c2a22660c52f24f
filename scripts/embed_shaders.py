#!/usr/bin/env python3
"""Writes a C++ file that maps each shader file name to its GLSL source (see renderer/gl/shader_sources.h)."""
import os
import sys

out, files = sys.argv[1], sorted(sys.argv[2:])
lines = ['#include "gl/shader_sources.h"', '', 'namespace shadowlab {', '',
         'const std::map<std::string, std::string>& embeddedShaderSources() {',
         '    static const std::map<std::string, std::string> sources = {']
for path in files:
    with open(path, encoding='utf-8') as f:
        text = f.read()
    delim = 'GLSL_'
    lines.append('        {"%s", R"%s(%s)%s"},' % (os.path.basename(path), delim, text, delim))
lines += ['    };', '    return sources;', '}', '', '}  // namespace shadowlab', '']
tmp = out + '.tmp'
with open(tmp, 'w', encoding='utf-8') as f:
    f.write('\n'.join(lines))
os.replace(tmp, out)
