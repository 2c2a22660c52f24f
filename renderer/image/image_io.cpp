#include "image/image_io.h"

#include "image/picture_size.h"
#include "settings/atomic_file.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

// stb, as private (static) copies: libtinygltf.so exports its own stbi_* symbols, and sharing one definition
// across two stb versions by ELF interposition would be an ODR accident waiting to happen. This is the one
// translation unit of ours that holds the implementations; stb is third-party, so its warnings are silenced here.
#pragma GCC diagnostic push
#ifdef __clang__
#pragma clang diagnostic ignored "-Wunknown-warning-option"  // the GCC-only names below
#endif
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wsign-conversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wuseless-cast"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace shadowlab {

namespace fs = std::filesystem;

namespace {

// EXR into memory, so the file is written once, whole, by the atomic writer (OutputFile seeks back to fill in its
// line offset table, hence the seekable buffer).
class MemoryOStream : public Imf::OStream {
public:
    explicit MemoryOStream(const char* name) : Imf::OStream(name) {}
    void write(const char c[], int n) override {
        const std::size_t end = pos_ + static_cast<std::size_t>(n);
        if (end > bytes.size()) bytes.resize(end);
        std::memcpy(bytes.data() + pos_, c, static_cast<std::size_t>(n));
        pos_ = end;
    }
    uint64_t tellp() override { return pos_; }
    void seekp(uint64_t pos) override { pos_ = static_cast<std::size_t>(pos); }
    std::vector<char> bytes;

private:
    std::size_t pos_ = 0;
};

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::string writePng(const std::string& path, int width, int height, int channels, const std::uint8_t* pixels,
                     bool flipVertically, const PngText& text) {
    const std::string failed = "cannot write PNG '" + path + "': ";
    if (width <= 0 || height <= 0) return failed + "empty image (" + std::to_string(width) + "x" + std::to_string(height) + ")";
    if (channels < 1 || channels > 4) return failed + "unsupported channel count " + std::to_string(channels);
    if (!pixels) return failed + "no pixel data";
    if (std::string tooLarge = pictureSizeError({width, height, channels, channels, true, {}}); !tooLarge.empty())
        return failed + tooLarge;
    // Flip by handing stb the last row and a negative stride: no copy of the image.
    const int rowBytes = width * channels;
    const std::uint8_t* first = flipVertically ? pixels + static_cast<std::size_t>(height - 1) * rowBytes : pixels;
    std::vector<unsigned char> encoded;
    if (!stbi_write_png_to_func(appendBytes, &encoded, width, height, channels, first,
                                flipVertically ? -rowBytes : rowBytes))
        return failed + "PNG encoding failed (out of memory?)";
    if (!text.empty())
        if (std::string e = insertPngText(encoded, text); !e.empty()) return failed + e;
    if (std::string e = writeFileAtomically(path, encoded.data(), encoded.size()); !e.empty()) return failed + e;
    return {};
}

std::string writeExrDepth(const std::string& path, int width, int height, const float* depth, bool flipVertically) {
    const std::string failed = "cannot write EXR '" + path + "': ";
    if (width <= 0 || height <= 0) return failed + "empty image (" + std::to_string(width) + "x" + std::to_string(height) + ")";
    if (!depth) return failed + "no depth data";
    MemoryOStream out(path.c_str());
    try {
        Imf::Header header(width, height);
        header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
        header.compression() = Imf::ZIP_COMPRESSION;  // lossless: depth reads back bit-exact
        {
            Imf::OutputFile file(out, header);
            // Rows go out in bands copied into a small buffer, flipped if asked; the full image is never duplicated.
            constexpr int band = 64;
            std::vector<float> rows(static_cast<std::size_t>(band) * width);
            for (int y0 = 0; y0 < height; y0 += band) {
                const int n = std::min(band, height - y0);
                for (int r = 0; r < n; ++r) {
                    const int src = flipVertically ? height - 1 - (y0 + r) : y0 + r;
                    std::copy_n(depth + static_cast<std::size_t>(src) * width, width,
                                rows.begin() + static_cast<std::ptrdiff_t>(r) * width);
                }
                Imf::FrameBuffer frame;
                frame.insert("Z", Imf::Slice::Make(Imf::FLOAT, rows.data(), Imath::V2i(0, y0), width, n,
                                                   sizeof(float), sizeof(float) * static_cast<std::size_t>(width)));
                file.setFrameBuffer(frame);
                file.writePixels(n);
            }
        }  // the line offset table is written here
    } catch (const std::exception& e) {
        return failed + e.what();
    }
    if (std::string e = writeFileAtomically(path, out.bytes.data(), out.bytes.size()); !e.empty()) return failed + e;
    return {};
}

std::optional<std::vector<std::uint8_t>> inflateZlib(const std::uint8_t* data, std::size_t size, std::size_t maxBytes) {
    // Deflate expands at most 1032:1, so the output buffer is bounded by the input as well as by the limit.
    constexpr std::size_t kMaxRatio = 1032;
    if (size > std::size_t(INT_MAX)) return std::nullopt;
    const std::size_t capacity = std::min({maxBytes, size * kMaxRatio + 64, std::size_t(INT_MAX)});
    std::vector<std::uint8_t> out(capacity);
    const int got = stbi_zlib_decode_buffer(reinterpret_cast<char*>(out.data()), int(capacity),
                                            reinterpret_cast<const char*>(data), int(size));
    if (got < 0) return std::nullopt;
    out.resize(std::size_t(got));
    return out;
}

std::optional<PngImage> readPng(const std::string& path, std::string* error) {
    int w = 0, h = 0, n = 0;
    stbi_uc* data = stbi_load(path.c_str(), &w, &h, &n, 0);
    if (!data) {
        if (error) *error = "cannot read PNG '" + path + "': " + stbi_failure_reason();
        return std::nullopt;
    }
    PngImage image;
    image.width = w;
    image.height = h;
    image.channels = n;
    image.pixels.assign(data, data + static_cast<std::size_t>(w) * h * n);
    stbi_image_free(data);
    return image;
}

std::optional<DepthImage> readExrDepth(const std::string& path, std::string* error) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::ChannelList& channels = file.header().channels();
        const char* channel = nullptr;
        for (const char* name : {"Z", "R", "Y"})
            if (channels.findChannel(name)) {
                channel = name;
                break;
            }
        if (!channel && channels.begin() != channels.end() && ++channels.begin() == channels.end())
            channel = channels.begin().name();
        if (!channel) throw std::runtime_error("no Z, R or Y channel and more than one channel");

        const Imath::Box2i window = file.header().dataWindow();
        DepthImage image;
        image.width = window.max.x - window.min.x + 1;
        image.height = window.max.y - window.min.y + 1;
        image.depth.resize(static_cast<std::size_t>(image.width) * image.height);
        Imf::FrameBuffer frame;
        frame.insert(channel, Imf::Slice::Make(Imf::FLOAT, image.depth.data(), window));
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const std::exception& e) {
        if (error) *error = "cannot read EXR '" + path + "': " + e.what();
        return std::nullopt;
    }
}

}  // namespace shadowlab
