#include "scene/gltf_images.h"

#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace shadowlab::gltf {
namespace {

// tinygltf image (1-4 channels, 8/16 bit or float) -> RGBA8.
bool toRgba8(const tg::Image& src, Image& out, std::string& why) {
    if (src.image.empty() || src.width <= 0 || src.height <= 0) {
        why = "is missing, empty or could not be decoded";
        return false;
    }
    const int comps = src.component;
    const bool isFloat = src.bits == 32 && src.pixel_type == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const int bytes = src.bits == 8 ? 1 : src.bits == 16 ? 2 : isFloat ? 4 : 0;
    if (comps < 1 || comps > 4 || bytes == 0) {
        why = "has an unsupported pixel format (" + str(comps) + " channels, " + str(src.bits) + " bits)";
        return false;
    }
    const std::size_t pixels = std::size_t(src.width) * std::size_t(src.height);
    if (src.image.size() != pixels * std::size_t(comps * bytes)) {
        why = "has " + str(src.image.size()) + " bytes of pixels, expected " + str(pixels * std::size_t(comps * bytes));
        return false;
    }
    auto channel = [&](std::size_t pixel, int c) -> std::uint8_t {
        const unsigned char* p = &src.image[(pixel * std::size_t(comps) + std::size_t(c)) * std::size_t(bytes)];
        if (bytes == 1) return p[0];
        if (bytes == 2) return std::uint8_t(load<std::uint16_t>(p) >> 8);
        const float f = load<float>(p);
        return std::uint8_t(std::isfinite(f) ? std::clamp(f, 0.0f, 1.0f) * 255.0f + 0.5f : 0.0f);
    };
    out.width = src.width;
    out.height = src.height;
    out.rgba.resize(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
        std::uint8_t* d = &out.rgba[i * 4];
        const bool gray = comps <= 2;
        d[0] = channel(i, 0);
        d[1] = gray ? d[0] : channel(i, 1);
        d[2] = gray ? d[0] : channel(i, 2);
        d[3] = comps == 2 ? channel(i, 1) : comps == 4 ? channel(i, 3) : 255;
    }
    return true;
}

// A texture's decoded RGBA8 size is bounded: 8192² (256 MiB) is more than any shadow-casting cutout needs.
constexpr std::size_t kMaxImagePixels = std::size_t(8192) * 8192;

// "" or why the PNG header's size is refused, read before the decoder allocates for it (stb's own refusal says only
// "Unknown image format").
std::string checkPngSize(const std::vector<unsigned char>& bytes) {
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < 24 || std::memcmp(bytes.data(), signature, 8) != 0 || std::memcmp(&bytes[12], "IHDR", 4) != 0)
        return {};
    auto be32 = [&](std::size_t at) {
        return std::uint32_t(bytes[at]) << 24 | std::uint32_t(bytes[at + 1]) << 16 | std::uint32_t(bytes[at + 2]) << 8 |
               std::uint32_t(bytes[at + 3]);
    };
    const std::uint32_t w = be32(16), h = be32(20);
    if (std::uint64_t(w) * h <= kMaxImagePixels) return {};
    return "is a PNG of " + std::to_string(w) + "x" + std::to_string(h) + " pixels, more than the " +
           std::to_string(kMaxImagePixels) + "-pixel (8192x8192) limit for a texture";
}

}  // namespace

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
    if (ctx->bytes.size() <= std::size_t(index)) ctx->bytes.resize(std::size_t(index) + 1);
    ctx->bytes[std::size_t(index)].assign(bytes, bytes + size);
    return true;
}

bool decodeImage(const EncodedImages& images, int index, Image& out, std::string& why) {
    const auto& encoded = std::size_t(index) < images.bytes.size() ? images.bytes[std::size_t(index)]
                                                                    : std::vector<unsigned char>{};
    tg::Image decoded;
    std::string decodeErr, decodeWarn;
    if (encoded.empty())
        why = "is missing or empty";
    else if (encoded.size() > std::size_t(std::numeric_limits<int>::max()))
        why = "is too large";
    else if (std::string tooLarge = checkPngSize(encoded); !tooLarge.empty())
        why = std::move(tooLarge);
    else if (!tg::LoadImageData(&decoded, index, &decodeErr, &decodeWarn, 0, 0, encoded.data(), int(encoded.size()),
                                nullptr))
        why = "cannot be decoded (" + joinLines(decodeErr) + ")";
    return why.empty() && toRgba8(decoded, out, why);
}

}  // namespace shadowlab::gltf
