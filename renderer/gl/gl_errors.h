#pragma once
// GL error reporting: KHR_debug output collected into a log (tests treat any error as a failure), and
// glGetError draining for the places where a user's value may be refused by the driver (allocation).
#include "gl/gl.h"

#include <string>
#include <vector>

namespace shadowlab::gl {

// Installs a synchronous debug callback (needs a debug context for full output; harmless otherwise).
void enableDebugOutput();

// Errors (GL_DEBUG_TYPE_ERROR) reported since the last call; clears the list.
std::vector<std::string> takeDebugErrors();

// Drains glGetError; returns "" when there was none, else the names of the errors, e.g. "GL_OUT_OF_MEMORY".
std::string drainErrors();

const char* errorName(GLenum error);

}  // namespace shadowlab::gl
