#pragma once
// The one include for OpenGL in the renderer: glad's GL 4.5 core loader (generated at build time).
#include <glad/gl.h>
