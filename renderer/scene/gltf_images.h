#pragma once
// glTF images: kept encoded while tinygltf parses (one copy of identical bytes, however many image entries name
// them), sized from their headers, and decoded to RGBA8 only when a drawn material's base colour texture uses them.
#include "scene/gltf_common.h"
#include "scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::gltf {

// tinygltf hands every image to keepEncodedImage instead of decoding it: the encoded bytes are kept and only the
// images a base colour texture uses are decoded later (decodeImage, with stb_image). Normal and ORM maps are never
// decoded, and an unreadable image costs a warning instead of the whole file (tinygltf's own callback fails the
// load). Embedded images are range-checked first, which tinygltf does not do.
struct EncodedImages {
    const tg::Model* model = nullptr;
    DecodeBudget* budget = nullptr;                 // a duplicate read from a file gives its bytes back
    std::vector<std::vector<unsigned char>> bytes;  // by glTF image index; empty = missing, unusable or a duplicate
    std::vector<int> sameAs;                        // by glTF image index: the first image with the same bytes

    // The image whose bytes `index` uses (itself unless an earlier image had the same bytes).
    int canonical(int index) const;
};

// tinygltf's LoadImageDataFunction; `user` is an EncodedImages. Always succeeds (problems go to *warn).
bool keepEncodedImage(tg::Image* image, const int index, std::string*, std::string* warn, int, int,
                      const unsigned char* bytes, int size, void* user);

// A texture's decoded RGBA8 size is bounded: 8192² (256 MiB) is more than any shadow-casting cutout needs.
inline constexpr std::size_t kMaxImagePixels = std::size_t(8192) * 8192;
// What a decoded image keeps in memory: RGBA8, whatever the file's channels and depth.
inline constexpr std::size_t kDecodedBytesPerPixel = 4;

struct ImageSize {
    int width = 0;
    int height = 0;
    std::size_t decodedBytes() const { return std::size_t(width) * std::size_t(height) * kDecodedBytesPerPixel; }
};

// glTF image `index`'s size from its header (every format stb_image reads), before anything is decoded; nullopt +
// why ("is missing or empty", "cannot be decoded (...)", past kMaxImagePixels with the figures) when it cannot be
// used.
std::optional<ImageSize> imageSize(const EncodedImages& images, int index, std::string& why);

// glTF image `index` as RGBA8 (gray, gray+alpha, RGB, 16-bit and float sources are converted). It refuses what
// imageSize refuses; the caller counts imageSize's decodedBytes against the scene's budget first, since this
// allocates them. false + why when it cannot be used.
bool decodeImage(const EncodedImages& images, int index, Image& out, std::string& why);

// "image 3 'leaves.png'" (the uri, else the name) for messages.
std::string imageLabel(const tg::Model& model, int index);

}  // namespace shadowlab::gltf
