#include "image/image_io.h"

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

// Writers never create folders: a typo in an output path should say so rather than grow a directory tree.
std::string checkFolder(const std::string& path) {
    if (path.empty()) return "no file name given";
    fs::path folder = fs::path(path).parent_path();
    if (folder.empty()) return {};
    std::error_code ec;
    fs::file_status st = fs::status(folder, ec);
    // Built with append: `"literal" + std::string&&` trips a GCC 12 -Wrestrict false positive (PR 105329).
    std::string quoted = "'";
    quoted += folder.string();
    quoted += "'";
    if (st.type() == fs::file_type::not_found) return "folder " + quoted + " does not exist";
    if (!fs::is_directory(st)) return quoted + " is not a folder";
    return {};
}

// Whole-file write with every error checked; a half-written file is removed.
std::string writeBytes(const std::string& path, const std::vector<unsigned char>& bytes) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return std::string("cannot open for writing: ") + std::strerror(errno);
    bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    int writeErrno = errno;
    if (std::fclose(file) != 0 && ok) {
        ok = false;
        writeErrno = errno;
    }
    if (!ok) {
        std::remove(path.c_str());
        return std::string("write failed: ") + std::strerror(writeErrno);
    }
    return {};
}

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::string writePng(const std::string& path, int width, int height, int channels, const std::uint8_t* pixels,
                     bool flipVertically) {
    const std::string failed = "cannot write PNG '" + path + "': ";
    if (width <= 0 || height <= 0) return failed + "empty image (" + std::to_string(width) + "x" + std::to_string(height) + ")";
    if (channels < 1 || channels > 4) return failed + "unsupported channel count " + std::to_string(channels);
    if (!pixels) return failed + "no pixel data";
    // stb computes sizes in int, filtered rows included.
    if ((static_cast<long long>(width) * channels + 1) * height > INT_MAX / 2)
        return failed + "image too large for the PNG writer";
    if (std::string e = checkFolder(path); !e.empty()) return failed + e;

    // Flip by handing stb the last row and a negative stride: no copy of the image.
    const int rowBytes = width * channels;
    const std::uint8_t* first = flipVertically ? pixels + static_cast<std::size_t>(height - 1) * rowBytes : pixels;
    std::vector<unsigned char> encoded;
    if (!stbi_write_png_to_func(appendBytes, &encoded, width, height, channels, first,
                                flipVertically ? -rowBytes : rowBytes))
        return failed + "PNG encoding failed (out of memory?)";
    if (std::string e = writeBytes(path, encoded); !e.empty()) return failed + e;
    return {};
}

std::string writeExrDepth(const std::string& path, int width, int height, const float* depth, bool flipVertically) {
    const std::string failed = "cannot write EXR '" + path + "': ";
    if (width <= 0 || height <= 0) return failed + "empty image (" + std::to_string(width) + "x" + std::to_string(height) + ")";
    if (!depth) return failed + "no depth data";
    if (std::string e = checkFolder(path); !e.empty()) return failed + e;

    // Our own stream: OutputFile's destructor writes the line offset table and swallows its errors, so the stream
    // state after it is gone is the only way to learn that the file is incomplete.
    std::ofstream stream(path, std::ios::binary | std::ios::trunc);
    if (!stream) return failed + "cannot open for writing: " + std::strerror(errno);
    try {
        Imf::Header header(width, height);
        header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
        header.compression() = Imf::ZIP_COMPRESSION;  // lossless: depth reads back bit-exact
        Imf::StdOFStream out(stream, path.c_str());
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
        }  // the file is complete only here
        stream.flush();
        stream.close();
        if (stream.fail()) throw std::runtime_error(std::string("write failed: ") + std::strerror(errno));
    } catch (const std::exception& e) {
        if (stream.is_open()) stream.close();
        std::remove(path.c_str());
        return failed + e.what();
    }
    return {};
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
