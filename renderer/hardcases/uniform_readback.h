#pragma once
// HARD_CASES 14's "no NaN reaches the GPU": reads back every float uniform of the program the last draw used and
// the per-light uniform block, and names the non-finite ones. Needs the GL context the frame was drawn on.
#include <string>
#include <vector>

namespace shadowlab::hardcases {

// The names of non-finite float uniforms ("Lights block float 17" for the block); {"no program bound"} when none.
std::vector<std::string> nonFiniteUniforms();

}  // namespace shadowlab::hardcases
