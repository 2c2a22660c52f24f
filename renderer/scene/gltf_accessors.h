#pragma once
// Reading glTF accessors and bufferViews defensively: every index, offset, stride and count is checked against the
// buffer it points into, so a broken file yields an error message instead of an out-of-bounds read.
#include "scene/gltf_common.h"

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab::gltf {

// `count` elements of `elemSize` bytes, `stride` apart (0: the view's byteStride, or packed), starting `offset` bytes
// into bufferView `viewIndex`; checked against the view and the view against its buffer. nullptr + err on failure.
const unsigned char* viewBytes(const tg::Model& m, int viewIndex, std::size_t offset, std::size_t count,
                               std::size_t& stride, std::size_t elemSize, std::string& err);

// Accessor `index` of type `wantType` (TINYGLTF_TYPE_*) as count * components floats, with glTF's normalized-integer
// rules, byteStride, missing bufferView (zeros) and sparse substitution. false + err on failure.
bool readFloats(const tg::Model& m, int index, int wantType, std::vector<float>& out, std::string& err);

// Index accessor `index` (SCALAR, unsigned byte/short/int). false + err on failure.
bool readIndices(const tg::Model& m, int index, std::vector<std::uint32_t>& out, std::string& err);

}  // namespace shadowlab::gltf
