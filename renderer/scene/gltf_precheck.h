#pragma once
// What the glTF JSON is checked for before tinygltf sees it: tinygltf walks extras recursively (a deeply nested
// file overflows the stack), reads a negative byteOffset as 0 without a word, and quotes a data: URI whole when its
// byteLength disagrees (megabytes of base64 in one message).
#include <string>
#include <string_view>
#include <vector>

namespace shadowlab::gltf {

// The JSON chunk of a GLB, or an empty view when the header or chunk table is malformed (tinygltf then says why).
std::string_view glbJsonChunk(const std::vector<unsigned char>& bytes);

// "" or the first problem: nesting deeper than kMaxJsonNesting, a negative or fractional byteOffset / byteLength /
// count / byteStride, a data: URI whose decoded size differs from its buffer's byteLength. Text that is not valid
// JSON passes (tinygltf reports the syntax error).
std::string precheckGltfJson(std::string_view json);

}  // namespace shadowlab::gltf
