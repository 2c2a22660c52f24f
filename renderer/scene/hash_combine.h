#pragma once
// Combining hashes for the scene's fingerprints (frame/renderer.h, frame/gpu_scene.h): not cryptographic, only a
// key that changes when what it covers does.
#include <cstddef>
#include <functional>
#include <string_view>
#include <utility>
#include <vector>

namespace shadowlab {

inline void hashCombine(std::size_t& seed, std::size_t value) {
    seed ^= value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
}

// A trivially copyable value's bytes.
template <typename T>
void hashBytes(std::size_t& seed, const T& value) {
    std::size_t chunk = 0;
    const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
    for (std::size_t i = 0; i < sizeof(T); ++i) {
        chunk = chunk * 131 + bytes[i];
        if (i % 8 == 7) hashCombine(seed, std::exchange(chunk, 0));
    }
    hashCombine(seed, chunk);
}

// A vector's contents (of trivially copyable elements) and its size.
template <typename T>
void hashContents(std::size_t& seed, const std::vector<T>& values) {
    hashCombine(seed, values.size());
    hashCombine(seed, std::hash<std::string_view>{}(
                          std::string_view(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T))));
}

}  // namespace shadowlab
