#pragma once
// glTF images: kept encoded while tinygltf parses, decoded to RGBA8 only when a base colour texture uses them.
#include "scene/gltf_common.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace shadowlab::gltf {

// tinygltf hands every image to keepEncodedImage instead of decoding it: the encoded bytes are kept and only the
// images a base colour texture uses are decoded later (decodeImage, with tinygltf's stb_image decoder). Normal and
// ORM maps are never decoded, and an unreadable image costs a warning instead of the whole file (tinygltf's own
// callback fails the load). Embedded images are range-checked first, which tinygltf does not do.
struct EncodedImages {
    const tg::Model* model = nullptr;
    std::vector<std::vector<unsigned char>> bytes;  // by glTF image index; empty = missing or unusable
};

// tinygltf's LoadImageDataFunction; `user` is an EncodedImages. Always succeeds (problems go to *warn).
bool keepEncodedImage(tg::Image* image, const int index, std::string*, std::string* warn, int, int,
                      const unsigned char* bytes, int size, void* user);

// glTF image `index` from `images` as RGBA8 (gray, gray+alpha, RGB, 16-bit and float sources are converted).
// false + why ("is missing or empty", "cannot be decoded (...)", ...) when it cannot be used.
bool decodeImage(const EncodedImages& images, int index, Image& out, std::string& why);

}  // namespace shadowlab::gltf
