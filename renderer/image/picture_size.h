#pragma once
// What a picture output needs, known before the work that makes it: the bytes its pixels take in memory and the
// bytes the PNG encoder works in. One check for every picture ShadowLab writes (render's view and shadow-map files,
// measure's overlays, sweep's chart, the editor's screenshots), so an output that cannot be written is refused up
// front with the figures instead of after seconds of rendering and gigabytes of memory.
#include <climits>
#include <cstddef>
#include <cstdint>
#include <string>

namespace shadowlab {

// stb_image_write's PNG encoder holds its filtered rows, (width * channels + 1) * height bytes, in an int, and the
// buffer it compresses into doubles as it grows: past INT_MAX / 2 it cannot encode (16384x16384 RGBA is 16 KiB over).
inline constexpr std::uint64_t kMaxPngEncoderBytes = INT_MAX / 2;
std::uint64_t pngEncoderBytes(int width, int height, int channels);

// The most a picture's pixels may take in memory: a 16384² RGBA view. A point light's 8192² faces unfolded into one
// float cross (32768x24576) would take 3 GiB, and three times that while it is converted and encoded.
inline constexpr std::uint64_t kMaxPictureBytes = std::uint64_t(16384) * 16384 * 4;

struct PictureSize {
    int width = 0;
    int height = 0;
    int channels = 4;       // as written: 4 = RGBA8 view, 1 = grey shadow map
    int bytesPerPixel = 4;  // as held in memory while it is made: 4 for RGBA8 and for float depth
    bool png = true;        // false: an EXR (no PNG encoder limit)
    std::string what;       // what the picture shows, for the message ("light 0's 8192² faces as one cross"); optional
};

// "" or why the picture cannot be written, with the figures: its pixels' bytes over kMaxPictureBytes, or the PNG
// encoder's rows over kMaxPngEncoderBytes (with the most rows that fit at this width).
std::string pictureSizeError(const PictureSize& size);

}  // namespace shadowlab
