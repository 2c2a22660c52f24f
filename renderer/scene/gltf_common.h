#pragma once
// Small pieces every part of the glTF loader shares: the tinygltf alias, number-to-text for messages, unaligned reads
// and the warning callback. Only the gltf_*.cpp files include this (tinygltf stays out of the public headers).
#include <tiny_gltf.h>

#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace shadowlab::gltf {

namespace tg = tinygltf;

// Where a part reports what it repaired or ignored; the Loader caps and collects these into Scene::warnings.
using Warn = std::function<void(const std::string&)>;

inline std::string str(std::size_t v) { return std::to_string(v); }
inline std::string str(int v) { return std::to_string(v); }

template <typename T>
T load(const unsigned char* p) {  // unaligned little-endian read (glTF data need not be aligned in broken files)
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// tinygltf's multi-line err/warn text as non-empty lines without trailing '\r' or spaces.
std::vector<std::string> splitLines(const std::string& text);
// The same lines joined with "; ", for one-line messages.
std::string joinLines(const std::string& text);

}  // namespace shadowlab::gltf
