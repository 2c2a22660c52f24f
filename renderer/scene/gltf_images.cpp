#include "scene/gltf_images.h"

#include "scene/gltf_accessors.h"

#include <stb_image.h>  // libstb's, the decoder tinygltf uses too (declarations only: no second implementation)

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>

namespace shadowlab::gltf {
namespace {

const std::vector<unsigned char>& encodedBytes(const EncodedImages& images, int index) {
    static const std::vector<unsigned char> none;
    const int source = images.canonical(index);
    return source >= 0 && std::size_t(source) < images.bytes.size() ? images.bytes[std::size_t(source)] : none;
}

// A PNG's size from its IHDR: stb's header reader refuses one past 1 GiB of pixels without saying its size.
std::optional<ImageSize> pngHeaderSize(const std::vector<unsigned char>& bytes) {
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 24 || std::memcmp(bytes.data(), signature, 8) != 0 || std::memcmp(&bytes[12], "IHDR", 4) != 0)
        return std::nullopt;
    auto be32 = [&](std::size_t at) {
        return std::uint32_t(bytes[at]) << 24 | std::uint32_t(bytes[at + 1]) << 16 | std::uint32_t(bytes[at + 2]) << 8 |
               std::uint32_t(bytes[at + 3]);
    };
    const std::uint32_t w = be32(16), h = be32(20);
    if (w == 0 || h == 0 || w > 0x7fffffffu || h > 0x7fffffffu) return std::nullopt;
    return ImageSize{int(w), int(h)};
}

std::string mib(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", double(bytes) / double(1u << 20));
    return text;
}

}  // namespace

int EncodedImages::canonical(int index) const {
    if (index < 0) return -1;
    return std::size_t(index) < sameAs.size() && sameAs[std::size_t(index)] >= 0 ? sameAs[std::size_t(index)] : index;
}

bool keepEncodedImage(tg::Image* image, const int index, std::string*, std::string* warn, int, int,
                      const unsigned char* bytes, int size, void* user) {
    auto* ctx = static_cast<EncodedImages*>(user);
    if (index < 0 || !bytes || size <= 0) return true;
    if (image->bufferView >= 0) {
        std::size_t stride = 1;
        std::string why;
        const auto& views = ctx->model->bufferViews;
        const std::size_t length =
            image->bufferView < int(views.size()) ? views[std::size_t(image->bufferView)].byteLength : 0;
        if (!viewBytes(*ctx->model, image->bufferView, 0, length, stride, 1, why)) {
            if (warn) *warn += "image[" + str(index) + "]: " + why + "\n";
            return true;
        }
    }
    const std::size_t n = std::size_t(size);
    if (ctx->bytes.size() <= std::size_t(index)) {
        ctx->bytes.resize(std::size_t(index) + 1);
        ctx->sameAs.resize(std::size_t(index) + 1, -1);
    }
    // Forty image entries naming one file are one image: its bytes are kept once and decoded once.
    for (std::size_t earlier = 0; earlier < ctx->bytes.size(); ++earlier) {
        const std::vector<unsigned char>& other = ctx->bytes[earlier];
        if (earlier != std::size_t(index) && other.size() == n && std::memcmp(other.data(), bytes, n) == 0) {
            ctx->sameAs[std::size_t(index)] = int(earlier);
            // The file read was counted against the scene's budget; its bytes are not kept (tinygltf frees them).
            const bool readFromFile = image->bufferView < 0 && !image->uri.empty();
            if (readFromFile && ctx->budget) ctx->budget->used -= std::min(ctx->budget->used, n);
            return true;
        }
    }
    ctx->bytes[std::size_t(index)].assign(bytes, bytes + size);
    return true;
}

std::string imageLabel(const tg::Model& model, int index) {
    std::string label = "image " + str(index);
    if (index < 0 || std::size_t(index) >= model.images.size()) return label;
    const tg::Image& image = model.images[std::size_t(index)];
    // A data: URI is megabytes of base64: never quoted.
    if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0) return label + " '" + image.uri + "'";
    if (!image.name.empty()) return label + " '" + image.name + "'";
    return label;
}

std::optional<ImageSize> imageSize(const EncodedImages& images, int index, std::string& why) {
    const std::vector<unsigned char>& encoded = encodedBytes(images, index);
    if (encoded.empty()) {
        why = "is missing or empty";
        return std::nullopt;
    }
    if (encoded.size() > std::size_t(std::numeric_limits<int>::max())) {
        why = "is too large (" + str(encoded.size()) + " bytes encoded)";
        return std::nullopt;
    }
    ImageSize size;
    int channels = 0;
    if (!stbi_info_from_memory(encoded.data(), int(encoded.size()), &size.width, &size.height, &channels)) {
        const std::optional<ImageSize> png = pngHeaderSize(encoded);
        if (!png) {
            why = std::string("cannot be decoded (") + stbi_failure_reason() + ")";
            return std::nullopt;
        }
        size = *png;
    }
    if (size.width <= 0 || size.height <= 0) {
        why = "has no pixels (" + str(size.width) + "x" + str(size.height) + ")";
        return std::nullopt;
    }
    if (std::uint64_t(size.width) * std::uint64_t(size.height) > kMaxImagePixels) {
        why = "is " + str(size.width) + "x" + str(size.height) + " pixels: decoded (RGBA8) it would take " +
              mib(size.decodedBytes()) + ", more than the 8192x8192 (" + mib(kMaxImagePixels * kDecodedBytesPerPixel) +
              ") limit for a texture";
        return std::nullopt;
    }
    return size;
}

bool decodeImage(const EncodedImages& images, int index, Image& out, std::string& why) {
    const std::optional<ImageSize> size = imageSize(images, index, why);
    if (!size) return false;
    const std::vector<unsigned char>& encoded = encodedBytes(images, index);
    const int length = int(encoded.size());
    int w = 0, h = 0, channels = 0;
    // Straight to RGBA8 (gray replicated, alpha 255 when absent, 16 bits to their high byte); float (HDR) sources
    // are clamped to [0, 1] linearly, not tone-mapped.
    const bool hdr = stbi_is_hdr_from_memory(encoded.data(), length) != 0;
    std::unique_ptr<void, void (*)(void*)> pixels(
        hdr ? static_cast<void*>(stbi_loadf_from_memory(encoded.data(), length, &w, &h, &channels, 4))
            : static_cast<void*>(stbi_load_from_memory(encoded.data(), length, &w, &h, &channels, 4)),
        stbi_image_free);
    if (!pixels) {
        why = std::string("cannot be decoded (") + stbi_failure_reason() + ")";
        return false;
    }
    if (w != size->width || h != size->height) {
        why = "decodes to " + str(w) + "x" + str(h) + " pixels where its header says " + str(size->width) + "x" +
              str(size->height);
        return false;
    }
    out.width = w;
    out.height = h;
    const std::size_t values = size->decodedBytes();
    out.rgba.resize(values);
    if (hdr) {
        const float* f = static_cast<const float*>(pixels.get());
        for (std::size_t i = 0; i < values; ++i)
            out.rgba[i] = std::uint8_t(std::isfinite(f[i]) ? std::clamp(f[i], 0.0f, 1.0f) * 255.0f + 0.5f : 0.0f);
    } else {
        std::memcpy(out.rgba.data(), pixels.get(), values);
    }
    return true;
}

}  // namespace shadowlab::gltf
