#pragma once
// `shadowlab measure --motion camera|light --frames N --step S`: flicker (renderer/accuracy/flicker.h) of one light
// while the camera translates or the light turns by S per frame; prints it beside the share of pixels whose true
// visibility changed, optionally as JSON, as an overlay PNG marking the flickering pixels, and as the worst pair's two
// frames (--frames-out DIR).
#include "cli/measure_command.h"

#include <glm/ext/vector_double3.hpp>

#include <optional>
#include <string>

namespace shadowlab::cli {

// A finite number that is the whole of `text`, else nullopt with `error` naming the option ("--step 'x': not a
// finite number"), so "nan" or "1e999" get a clear message.
std::optional<double> parseFiniteOption(const std::string& text, const std::string& option, std::string& error);
// Three finite numbers "x,y,z" (--direction, bench's --walk), else nullopt with `error` naming the option.
std::optional<glm::dvec3> parseVectorOption(const std::string& text, const std::string& option, std::string& error);

// Any of --motion, --frames, --step, --direction, --frames-out given.
bool wantsMotion(const MeasureOptions& options);

// Exit code 0 unless it failed (bad option, no GL, a file that cannot be written).
int runMeasureMotion(const MeasureOptions& options);

}  // namespace shadowlab::cli
