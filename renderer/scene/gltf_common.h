#pragma once
// Small pieces every part of the glTF loader shares: the tinygltf alias, number-to-text for messages, unaligned reads
// and the warning callback. Only the gltf_*.cpp files include this (tinygltf stays out of the public headers).
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <functional>
#include <string>
#include <vector>

namespace shadowlab::gltf {

namespace tg = tinygltf;

// Where a part reports what it repaired or ignored; the Loader caps and collects these into Scene::warnings.
using Warn = std::function<void(const std::string&)>;

inline std::string str(std::size_t v) { return std::to_string(v); }
inline std::string str(int v) { return std::to_string(v); }
std::string str(double v);  // short: "1e+30", "0.5"

template <typename T>
T load(const unsigned char* p) {  // unaligned little-endian read (glTF data need not be aligned in broken files)
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// A double that converts to float without overflow (casting a larger one is undefined behaviour); false for NaN.
inline bool fitsFloat(double v) { return std::abs(v) <= double(std::numeric_limits<float>::max()); }

// The most a scene may decode: buffers and images read from disk plus the vertex and index data built from them.
// Checked before each allocation, so a 1 KiB file claiming 2^26 vertices is refused instead of taking gigabytes.
inline constexpr std::size_t kMaxDecodedBytes = std::size_t(1) << 30;  // 1 GiB

struct DecodeBudget {
    std::size_t used = 0;
    bool exceeded = false;
    // Counts `bytes` against kMaxDecodedBytes; false (and exceeded set) when they would pass it.
    bool take(std::size_t bytes) {
        if (bytes > kMaxDecodedBytes - used) {
            exceeded = true;
            return false;
        }
        used += bytes;
        return true;
    }
};

// tinygltf's multi-line err/warn text as non-empty lines without trailing '\r' or spaces.
std::vector<std::string> splitLines(const std::string& text);
// The same lines joined with "; ", for one-line messages; a line longer than 200 bytes (a data: URI's payload
// quoted whole) is cut, with its length said.
std::string joinLines(const std::string& text);

}  // namespace shadowlab::gltf
