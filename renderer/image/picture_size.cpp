#include "image/picture_size.h"

namespace shadowlab {

std::uint64_t pngEncoderBytes(int width, int height, int channels) {
    return (std::uint64_t(width > 0 ? width : 0) * std::uint64_t(channels > 0 ? channels : 0) + 1) *
           std::uint64_t(height > 0 ? height : 0);
}

std::string pictureSizeError(const PictureSize& size) {
    const std::string dims = std::to_string(size.width) + "x" + std::to_string(size.height);
    const std::string what = size.what.empty() ? "" : " (" + size.what + ")";
    const std::uint64_t bytes = std::uint64_t(size.width) * std::uint64_t(size.height) * std::uint64_t(size.bytesPerPixel);
    if (bytes > kMaxPictureBytes)
        return "a " + dims + " picture" + what + " needs " + std::to_string(bytes) + " bytes (" +
               std::to_string(size.bytesPerPixel) + " a pixel), more than the limit of " +
               std::to_string(kMaxPictureBytes) + " bytes for a picture (16384x16384 RGBA)";
    if (size.png) {
        const std::uint64_t rows = pngEncoderBytes(size.width, size.height, size.channels);
        if (rows > kMaxPngEncoderBytes)
            return "a " + dims + " PNG of " + std::to_string(size.channels) + " channel" +
                   (size.channels == 1 ? "" : "s") + what + " needs " + std::to_string(rows) +
                   " bytes of encoder rows ((width x channels + 1) x height), more than the PNG writer's limit of " +
                   std::to_string(kMaxPngEncoderBytes) + " (it counts in int); at this width at most " +
                   std::to_string(kMaxPngEncoderBytes / pngEncoderBytes(size.width, 1, size.channels)) + " rows fit";
    }
    return {};
}

}  // namespace shadowlab
