#pragma once
// Image files: PNG screenshots (8-bit) and EXR depth dumps (32-bit float), plus readers for tests.
// Writers return "" on success or an error message naming the file; they never create folders.
// GL reads pixels bottom row first: pass flipVertically = true to store glReadPixels output top row first.
#include "image/png_text.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab {

// channels: 1 (gray), 2 (gray+alpha), 3 (RGB) or 4 (RGBA); pixels: width*height*channels bytes, rows packed.
// `text`: iTXt chunks to carry (png_text.h), e.g. the preset a screenshot was rendered with.
std::string writePng(const std::string& path, int width, int height, int channels, const std::uint8_t* pixels,
                     bool flipVertically, const PngText& text = {});

// One FLOAT channel named "Z" (OpenEXR's standard name for depth), ZIP compressed (lossless), so the values read
// back bit-exact. depth: width*height floats, rows packed.
std::string writeExrDepth(const std::string& path, int width, int height, const float* depth, bool flipVertically);

struct PngImage {
    int width = 0;
    int height = 0;
    int channels = 0;                  // as stored in the file
    std::vector<std::uint8_t> pixels;  // top row first
};

struct DepthImage {
    int width = 0;
    int height = 0;
    std::vector<float> depth;  // top row first (the file's first scanline)
};

// nullopt on failure; *error (when given) says why.
std::optional<PngImage> readPng(const std::string& path, std::string* error = nullptr);

// Reads channel "Z", else "R", else "Y", else the file's only channel.
std::optional<DepthImage> readExrDepth(const std::string& path, std::string* error = nullptr);

}  // namespace shadowlab
