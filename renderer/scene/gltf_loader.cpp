#include "scene/gltf_loader.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <new>
#include <numeric>

namespace shadowlab {
namespace {

namespace tg = tinygltf;

constexpr int kMaxNodeDepth = 512;                  // deeper than any real hierarchy: a broken file
constexpr std::size_t kMaxNodeVisits = 2'000'000;   // a node shared by many parents can explode combinatorially
constexpr std::size_t kMaxWarnings = 100;           // keep the list readable on badly broken files
constexpr std::size_t kMaxZeroElements = 1u << 26;  // an accessor without data is zeros, but not absurdly many

std::string str(std::size_t v) { return std::to_string(v); }
std::string str(int v) { return std::to_string(v); }

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) out.push_back(std::move(line));
        start = end + 1;
    }
    return out;
}

std::string joinLines(const std::string& text) {
    std::string out;
    for (const std::string& l : splitLines(text)) out += (out.empty() ? "" : "; ") + l;
    return out;
}

// ---- accessors ---------------------------------------------------------------------------------------------------

int componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;  // INT and DOUBLE are not valid glTF 2.0 accessor types
    }
}

bool isUnsignedInt(int componentType) {
    return componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

std::string typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        default: return "type " + str(type);
    }
}

template <typename T>
T load(const unsigned char* p) {  // unaligned little-endian read (glTF data need not be aligned in broken files)
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// One component as float, with glTF's normalized-integer rules.
float readFloat(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const float v = load<std::int8_t>(p);
            return normalized ? std::max(v / 127.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            const float v = load<std::uint8_t>(p);
            return normalized ? v / 255.0f : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const float v = load<std::int16_t>(p);
            return normalized ? std::max(v / 32767.0f, -1.0f) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            const float v = load<std::uint16_t>(p);
            return normalized ? v / 65535.0f : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            const double v = load<std::uint32_t>(p);
            return float(normalized ? v / 4294967295.0 : v);
        }
        default: return 0.0f;
    }
}

std::uint32_t readUint(const unsigned char* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<std::uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<std::uint32_t>(p);
        default: return 0;
    }
}

// `count` elements of `elemSize` bytes, `stride` apart (0: the view's byteStride, or packed), starting `offset` bytes
// into bufferView `viewIndex`; checked against the view and the view against its buffer. nullptr + err on failure.
const unsigned char* viewBytes(const tg::Model& m, int viewIndex, std::size_t offset, std::size_t count,
                               std::size_t& stride, std::size_t elemSize, std::string& err) {
    if (viewIndex < 0 || viewIndex >= int(m.bufferViews.size())) {
        err = "bufferView " + str(viewIndex) + " does not exist";
        return nullptr;
    }
    const tg::BufferView& bv = m.bufferViews[viewIndex];
    const std::string view = "bufferView " + str(viewIndex);
    if (bv.buffer < 0 || bv.buffer >= int(m.buffers.size())) {
        err = view + " refers to buffer " + str(bv.buffer) + ", which does not exist";
        return nullptr;
    }
    const std::vector<unsigned char>& data = m.buffers[bv.buffer].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset) {
        err = view + " (bytes " + str(bv.byteOffset) + " + " + str(bv.byteLength) + ") lies outside buffer " +
              str(bv.buffer) + " (" + str(data.size()) + " bytes)";
        return nullptr;
    }
    if (stride == 0) stride = bv.byteStride != 0 ? bv.byteStride : elemSize;
    if (stride < elemSize) {
        err = view + " has byteStride " + str(stride) + ", smaller than one element (" + str(elemSize) + " bytes)";
        return nullptr;
    }
    if (count > 0 && (offset > bv.byteLength || bv.byteLength - offset < elemSize ||
                      count - 1 > (bv.byteLength - offset - elemSize) / stride)) {
        err = str(count) + " elements of " + str(elemSize) + " bytes (stride " + str(stride) + ", offset " +
              str(offset) + ") do not fit in " + view + " (" + str(bv.byteLength) + " bytes)";
        return nullptr;
    }
    return data.data() + bv.byteOffset + offset;
}

// Reads accessor `index` (which must be of `wantType`) into `out`, count * components values, each converted by
// convert(bytes, componentType, normalized). Handles byteStride, missing bufferView (zeros) and sparse substitution.
template <typename T, typename Convert>
bool readAccessor(const tg::Model& m, int index, int wantType, std::vector<T>& out, std::string& err,
                  Convert convert) {
    if (index < 0 || index >= int(m.accessors.size())) {
        err = "accessor " + str(index) + " does not exist";
        return false;
    }
    const tg::Accessor& a = m.accessors[index];
    const std::string name = "accessor " + str(index);
    if (a.type != wantType) {
        err = name + " is " + typeName(a.type) + ", expected " + typeName(wantType);
        return false;
    }
    const std::size_t comps = std::size_t(componentCount(a.type));
    const std::size_t csize = std::size_t(componentSize(a.componentType));
    if (csize == 0) {
        err = name + " has invalid componentType " + str(a.componentType);
        return false;
    }
    const std::size_t elemSize = comps * csize;
    if (a.bufferView < 0) {  // glTF: no bufferView means all zeros (sparse values may follow)
        if (a.count > kMaxZeroElements) {
            err = name + " has no data and an implausible count " + str(a.count);
            return false;
        }
        out.assign(a.count * comps, T{});
    } else {
        std::size_t stride = 0;
        const unsigned char* p = viewBytes(m, a.bufferView, a.byteOffset, a.count, stride, elemSize, err);
        if (!p) {
            err = name + ": " + err;
            return false;
        }
        out.resize(a.count * comps);
        for (std::size_t i = 0; i < a.count; ++i)
            for (std::size_t c = 0; c < comps; ++c)
                out[i * comps + c] = convert(p + i * stride + c * csize, a.componentType, a.normalized);
    }
    if (!a.sparse.isSparse) return true;

    const auto& s = a.sparse;
    const int icsize = componentSize(s.indices.componentType);
    if (s.count < 0 || std::size_t(s.count) > a.count || !isUnsignedInt(s.indices.componentType) ||
        s.indices.byteOffset < 0 || s.values.byteOffset < 0) {
        err = name + " has an invalid sparse section";
        return false;
    }
    const auto sparseCount = std::size_t(s.count);
    std::size_t istride = std::size_t(icsize), vstride = elemSize;  // sparse data is tightly packed
    const unsigned char* ip = viewBytes(m, s.indices.bufferView, std::size_t(s.indices.byteOffset), sparseCount,
                                        istride, std::size_t(icsize), err);
    const unsigned char* vp = ip ? viewBytes(m, s.values.bufferView, std::size_t(s.values.byteOffset), sparseCount,
                                             vstride, elemSize, err)
                                 : nullptr;
    if (!vp) {
        err = name + " (sparse): " + err;
        return false;
    }
    for (std::size_t k = 0; k < sparseCount; ++k) {
        const std::uint32_t target = readUint(ip + k * istride, s.indices.componentType);
        if (target >= a.count) {
            err = name + " (sparse): index " + str(std::size_t(target)) + " out of range";
            return false;
        }
        for (std::size_t c = 0; c < comps; ++c)
            out[target * comps + c] = convert(vp + k * vstride + c * csize, a.componentType, a.normalized);
    }
    return true;
}

bool readFloats(const tg::Model& m, int index, int wantType, std::vector<float>& out, std::string& err) {
    return readAccessor(m, index, wantType, out, err, readFloat);
}

bool readIndices(const tg::Model& m, int index, std::vector<std::uint32_t>& out, std::string& err) {
    if (index >= 0 && index < int(m.accessors.size()) && !isUnsignedInt(m.accessors[index].componentType)) {
        err = "index accessor " + str(index) + " is not an unsigned integer type";
        return false;
    }
    return readAccessor(m, index, TINYGLTF_TYPE_SCALAR, out, err,
                        [](const unsigned char* p, int ct, bool) { return readUint(p, ct); });
}

// ---- geometry repair ---------------------------------------------------------------------------------------------

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Triangle list from TRIANGLES / TRIANGLE_STRIP / TRIANGLE_FAN indices (glTF 2.0 spec, 3.7.2.1).
std::vector<std::uint32_t> toTriangleList(const std::vector<std::uint32_t>& idx, int mode) {
    std::vector<std::uint32_t> tri;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        tri.assign(idx.begin(), idx.begin() + std::ptrdiff_t(idx.size() / 3 * 3));
    } else if (idx.size() >= 3) {
        tri.reserve((idx.size() - 2) * 3);
        for (std::size_t i = 0; i + 2 < idx.size(); ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
                tri.insert(tri.end(), {idx[i], idx[i + 1 + i % 2], idx[i + 2 - i % 2]});
            else
                tri.insert(tri.end(), {idx[i + 1], idx[i + 2], idx[0]});
        }
    }
    return tri;
}

// Drops triangles that use a non-finite position (BoxWithInfinites.glb), then the vertices no triangle uses, so no
// inf/NaN reaches bounds, light fitting or the GPU. Returns the number of triangles dropped.
std::size_t dropNonFiniteTriangles(Mesh& mesh) {
    std::vector<char> bad(mesh.positions.size());
    bool any = false;
    for (std::size_t i = 0; i < bad.size(); ++i) any |= (bad[i] = !finite(mesh.positions[i]));
    if (!any) return 0;
    std::vector<std::uint32_t> kept;
    kept.reserve(mesh.indices.size());
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t* tri = &mesh.indices[t];
        if (!bad[tri[0]] && !bad[tri[1]] && !bad[tri[2]]) kept.insert(kept.end(), tri, tri + 3);
    }
    const std::size_t dropped = (mesh.indices.size() - kept.size()) / 3;
    // Compact: keep referenced vertices only, in their original order.
    std::vector<std::uint32_t> remap(mesh.positions.size(), UINT32_MAX);
    for (std::uint32_t v : kept) remap[v] = 0;
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == UINT32_MAX) continue;
        remap[v] = next;
        mesh.positions[next] = mesh.positions[v];
        if (!mesh.normals.empty()) mesh.normals[next] = mesh.normals[v];
        if (!mesh.uvs.empty()) mesh.uvs[next] = mesh.uvs[v];
        ++next;
    }
    mesh.positions.resize(next);
    if (!mesh.normals.empty()) mesh.normals.resize(next);
    if (!mesh.uvs.empty()) mesh.uvs.resize(next);
    for (std::uint32_t& v : kept) v = remap[v];
    mesh.indices = std::move(kept);
    return dropped;
}

// Area-weighted vertex normals (the face cross product is twice the area); (0,1,0) where no face contributes.
std::vector<glm::vec3> smoothNormals(const Mesh& mesh) {
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const glm::dvec3 pa(mesh.positions[a]);
        const glm::dvec3 n = glm::cross(glm::dvec3(mesh.positions[b]) - pa, glm::dvec3(mesh.positions[c]) - pa);
        sum[a] += n;
        sum[b] += n;
        sum[c] += n;
    }
    std::vector<glm::vec3> normals(sum.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        const double len = glm::length(sum[i]);
        normals[i] = len > 0.0 && std::isfinite(len) ? glm::vec3(sum[i] / len) : glm::vec3(0, 1, 0);
    }
    return normals;
}

std::size_t countZeroArea(const Mesh& mesh) {
    std::size_t n = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
        const glm::dvec3 e1 = glm::dvec3(mesh.positions[mesh.indices[t + 1]]) - a;
        const glm::dvec3 e2 = glm::dvec3(mesh.positions[mesh.indices[t + 2]]) - a;
        if (glm::cross(e1, e2) == glm::dvec3(0.0)) ++n;
    }
    return n;
}

bool allFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// ---- images ------------------------------------------------------------------------------------------------------

// tinygltf hands every image to this callback instead of decoding it: the encoded bytes are kept and only the images
// a base colour texture uses are decoded later (Loader::importImage, with tinygltf's stb_image decoder). Normal and
// ORM maps are never decoded, and an unreadable image costs a warning instead of the whole file (tinygltf's own
// callback fails the load). Embedded images are range-checked first, which tinygltf does not do.
struct EncodedImages {
    const tg::Model* model = nullptr;
    std::vector<std::vector<unsigned char>> bytes;  // by glTF image index; empty = missing or unusable
};

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

// ---- required extensions ----------------------------------------------------------------------------------------

bool isCompressedGeometry(const std::string& ext) {
    return ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression" || ext == "KHR_meshopt_compression";
}

std::string compressedGeometryError(const std::string& ext) {
    return "requires " + ext + " (compressed geometry), which ShadowLab cannot decode";
}

// When tinygltf refuses a file, a required compression extension is usually why (its accessors have no bufferView):
// read extensionsRequired from the JSON ourselves to say so. Best effort; empty when the JSON cannot be read.
std::string unsupportedRequiredExtension(const std::string& path, bool binary) {
    std::ifstream in(path, std::ios::binary);
    std::string text;
    if (binary) {
        unsigned char header[20] = {};
        if (!in.read(reinterpret_cast<char*>(header), 20) || std::memcmp(header + 16, "JSON", 4) != 0) return {};
        const std::uint32_t length = load<std::uint32_t>(header + 12);
        std::error_code ec;
        if (length > std::filesystem::file_size(path, ec) || ec) return {};
        text.resize(length);
        if (!in.read(text.data(), std::streamsize(length))) return {};
    } else {
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!j.is_object() || !j.contains("extensionsRequired") || !j["extensionsRequired"].is_array()) return {};
    for (const nlohmann::json& ext : j["extensionsRequired"])
        if (ext.is_string() && isCompressedGeometry(ext.get<std::string>())) return ext.get<std::string>();
    return {};
}

// ---- the scene ---------------------------------------------------------------------------------------------------

class Loader {
public:
    Loader(const tg::Model& model, const EncodedImages& images) : model_(model), images_(images) {
        meshCache_.resize(model.meshes.size());
        imageCache_.assign(model.images.size(), kNotImported);
        onPath_.assign(model.nodes.size(), 0);
    }

    void warn(const std::string& message) {
        if (scene_.warnings.size() < kMaxWarnings)
            scene_.warnings.push_back(message);
        else
            ++suppressedWarnings_;
    }

    // The scene, or nullopt with `error` set.
    std::optional<Scene> run(std::string& error);

private:
    static constexpr int kNotImported = -2;

    bool checkRequiredExtensions(std::string& error);
    Material convertMaterial(int index);
    void applyTextureTransform(const tg::TextureInfo& info, Material& m, const std::string& where);
    int importImage(int index, const std::string& where);
    std::optional<Mesh> convertPrimitive(int meshIndex, int primIndex);
    const std::vector<int>& meshPrimitives(int meshIndex);
    std::vector<int> rootNodes();
    void visit(int index, const glm::dmat4& parent, int depth);
    glm::dmat4 localMatrix(int index);
    void importLight(int nodeIndex, const glm::dmat4& world);
    std::string meshLabel(int meshIndex) const {
        const std::string& n = model_.meshes[meshIndex].name;
        return "mesh " + str(meshIndex) + (n.empty() ? "" : " '" + n + "'");
    }

    const tg::Model& model_;
    const EncodedImages& images_;
    Scene scene_;
    std::vector<std::optional<std::vector<int>>> meshCache_;  // glTF mesh -> Scene meshes (one per kept primitive)
    std::vector<int> imageCache_;                              // glTF image -> Scene image, -1 = unusable
    std::vector<char> onPath_;                                 // nodes on the current root-to-node path (cycles)
    std::size_t visits_ = 0, suppressedWarnings_ = 0, zeroArea_ = 0, degenerateInstances_ = 0;
    bool cycleWarned_ = false, depthWarned_ = false, visitsWarned_ = false, skinWarned_ = false, morphWarned_ = false;
};

bool Loader::checkRequiredExtensions(std::string& error) {
    for (const std::string& ext : model_.extensionsRequired) {
        if (isCompressedGeometry(ext)) {
            error = compressedGeometryError(ext);
            return false;
        }
        const bool handled = ext == "KHR_texture_transform" || ext == "KHR_lights_punctual" ||
                             ext == "KHR_mesh_quantization" || ext.rfind("KHR_materials_", 0) == 0;
        if (!handled) warn("requires extension " + ext + ", which ShadowLab ignores: the scene may look wrong");
    }
    return true;
}

Material Loader::convertMaterial(int index) {
    const tg::Material& gm = model_.materials[std::size_t(index)];
    Material m;
    m.name = gm.name.empty() ? "material " + str(index) : gm.name;
    const std::string where = "material '" + m.name + "'";
    if (gm.alphaMode == "MASK")
        m.alphaMode = AlphaMode::Mask;
    else if (gm.alphaMode == "BLEND")
        m.alphaMode = AlphaMode::Blend;
    else if (!gm.alphaMode.empty() && gm.alphaMode != "OPAQUE")
        warn(where + ": unknown alphaMode '" + gm.alphaMode + "', treated as OPAQUE");
    if (std::isfinite(gm.alphaCutoff) && gm.alphaCutoff >= 0.0)
        m.alphaCutoff = float(gm.alphaCutoff);
    else
        warn(where + ": invalid alphaCutoff, 0.5 used");
    const std::vector<double>& f = gm.pbrMetallicRoughness.baseColorFactor;
    if (f.size() == 4 && std::all_of(f.begin(), f.end(), [](double v) { return std::isfinite(v); }))
        m.baseColorFactor = glm::clamp(glm::vec4(float(f[0]), float(f[1]), float(f[2]), float(f[3])), 0.0f, 1.0f);
    else if (!f.empty())
        warn(where + ": invalid baseColorFactor, white used");
    m.doubleSided = gm.doubleSided;

    const tg::TextureInfo& info = gm.pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0) return m;
    m.baseColorTexCoord = info.texCoord;
    if (info.index >= int(model_.textures.size())) {
        warn(where + ": base colour texture " + str(info.index) + " does not exist; ignored");
        return m;
    }
    const tg::Texture& tex = model_.textures[std::size_t(info.index)];
    if (tex.source >= 0 && tex.source < int(model_.images.size()))
        m.baseColorImage = importImage(tex.source, where);
    else
        warn(where + ": base colour texture " + str(info.index) +
             " has no usable image source (e.g. only KHR_texture_basisu / EXT_texture_webp); alpha from the factor only");
    if (tex.sampler >= 0 && tex.sampler < int(model_.samplers.size())) {
        const tg::Sampler& s = model_.samplers[std::size_t(tex.sampler)];
        // One flag for both axes: clamp only when both clamp (MIRRORED_REPEAT counts as repeat).
        m.wrapRepeat = !(s.wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE && s.wrapT == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
    }
    applyTextureTransform(info, m, where);
    if (m.baseColorImage >= 0 && m.baseColorTexCoord != 0)
        warn(where + ": base colour texture uses TEXCOORD_" + str(m.baseColorTexCoord) +
             "; only TEXCOORD_0 is loaded and used instead");
    return m;
}

// KHR_texture_transform as uv' = T * R * S * (uv, 1). The rotation sign follows the sample model, the sample viewer,
// three.js and Babylon (KhronosGroup/glTF#1563): the GLSL listing in the extension's README has it the other way.
void Loader::applyTextureTransform(const tg::TextureInfo& info, Material& m, const std::string& where) {
    const auto it = info.extensions.find("KHR_texture_transform");
    if (it == info.extensions.end() || !it->second.IsObject()) return;
    const tg::Value& t = it->second;
    auto vec2 = [&](const char* key, glm::dvec2 fallback) {
        if (!t.Has(key)) return fallback;
        const tg::Value& v = t.Get(key);
        if (v.IsArray() && v.ArrayLen() == 2 && v.Get(0).IsNumber() && v.Get(1).IsNumber())
            return glm::dvec2(v.Get(0).GetNumberAsDouble(), v.Get(1).GetNumberAsDouble());
        return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
    };
    const glm::dvec2 offset = vec2("offset", glm::dvec2(0.0)), scale = vec2("scale", glm::dvec2(1.0));
    double rotation = 0.0;
    if (t.Has("rotation")) rotation = t.Get("rotation").IsNumber() ? t.Get("rotation").GetNumberAsDouble() : NAN;
    if (t.Has("texCoord") && t.Get("texCoord").IsNumber()) m.baseColorTexCoord = t.Get("texCoord").GetNumberAsInt();
    if (!std::isfinite(offset.x + offset.y + scale.x + scale.y + rotation)) {
        warn(where + ": invalid KHR_texture_transform; ignored");
        return;
    }
    const double c = std::cos(rotation), s = std::sin(rotation);
    const glm::dmat3 translate(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::dmat3 rotate(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::dmat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    m.uvTransform = glm::mat3(translate * rotate * scaling);
}

int Loader::importImage(int index, const std::string& where) {
    int& cached = imageCache_[std::size_t(index)];
    if (cached != kNotImported) return cached;
    const tg::Image& src = model_.images[std::size_t(index)];
    const auto& encoded = std::size_t(index) < images_.bytes.size() ? images_.bytes[std::size_t(index)]
                                                                     : std::vector<unsigned char>{};
    tg::Image decoded;
    Image image;
    std::string why, decodeErr, decodeWarn;
    if (encoded.empty())
        why = "is missing or empty";
    else if (encoded.size() > std::size_t(std::numeric_limits<int>::max()))
        why = "is too large";
    else if (!tg::LoadImageData(&decoded, index, &decodeErr, &decodeWarn, 0, 0, encoded.data(), int(encoded.size()),
                                nullptr))
        why = "cannot be decoded (" + joinLines(decodeErr) + ")";
    if (why.empty() && toRgba8(decoded, image, why)) {
        cached = int(scene_.images.size());
        scene_.images.push_back(std::move(image));
        return cached;
    }
    const std::string name = !src.uri.empty() ? " '" + src.uri + "'" : !src.name.empty() ? " '" + src.name + "'" : "";
    warn(where + ": image " + str(index) + name + " " + why + "; texture ignored (alpha from the factor only)");
    return cached = -1;
}

std::optional<Mesh> Loader::convertPrimitive(int meshIndex, int primIndex) {
    const tg::Mesh& gm = model_.meshes[std::size_t(meshIndex)];
    const tg::Primitive& p = gm.primitives[std::size_t(primIndex)];
    const std::string where = meshLabel(meshIndex) + " primitive " + str(primIndex);
    auto skip = [&](const std::string& why) -> std::optional<Mesh> {
        warn(where + ": " + why + "; primitive skipped");
        return std::nullopt;
    };

    const int mode = p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
        return skip("mode " + str(mode) + " is points or lines, not triangles");
    const auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) return skip("no POSITION attribute");
    if (p.extensions.count("KHR_draco_mesh_compression") && pos->second >= 0 &&
        pos->second < int(model_.accessors.size()) && model_.accessors[std::size_t(pos->second)].bufferView < 0)
        return skip("Draco-compressed geometry is not supported");

    std::string err;
    std::vector<float> raw;
    if (!readFloats(model_, pos->second, TINYGLTF_TYPE_VEC3, raw, err)) return skip("POSITION: " + err);
    const std::size_t n = raw.size() / 3;
    if (n == 0) return skip("no vertices");
    if (n >= UINT32_MAX) return skip("too many vertices");

    std::vector<std::uint32_t> idx;
    if (p.indices >= 0) {
        if (!readIndices(model_, p.indices, idx, err)) return skip("indices: " + err);
        const auto bad = std::count_if(idx.begin(), idx.end(), [&](std::uint32_t i) { return i >= n; });
        if (bad > 0)
            return skip(str(std::size_t(bad)) + " of " + str(idx.size()) + " indices are out of range (" + str(n) +
                        " vertices)");
    } else {
        idx.resize(n);
        std::iota(idx.begin(), idx.end(), 0u);
    }
    if (mode == TINYGLTF_MODE_TRIANGLES && idx.size() % 3 != 0)
        warn(where + ": index count " + str(idx.size()) + " is not a multiple of 3; the rest is ignored");

    Mesh mesh;
    mesh.name = gm.name.empty() ? "mesh " + str(meshIndex) : gm.name;
    if (gm.primitives.size() > 1) mesh.name += " #" + str(primIndex);
    mesh.indices = toTriangleList(idx, mode);
    mesh.positions.resize(n);
    std::memcpy(mesh.positions.data(), raw.data(), n * sizeof(glm::vec3));

    if (const auto it = p.attributes.find("NORMAL"); it != p.attributes.end()) {
        if (!readFloats(model_, it->second, TINYGLTF_TYPE_VEC3, raw, err))
            warn(where + ": NORMAL ignored (" + err + ")");
        else if (raw.size() != n * 3)
            warn(where + ": NORMAL has " + str(raw.size() / 3) + " entries for " + str(n) + " vertices; ignored");
        else {
            mesh.normals.resize(n);
            std::memcpy(mesh.normals.data(), raw.data(), n * sizeof(glm::vec3));
        }
    }
    if (const auto it = p.attributes.find("TEXCOORD_0"); it != p.attributes.end()) {
        if (!readFloats(model_, it->second, TINYGLTF_TYPE_VEC2, raw, err))
            warn(where + ": TEXCOORD_0 ignored (" + err + ")");
        else if (raw.size() != n * 2)
            warn(where + ": TEXCOORD_0 has " + str(raw.size() / 2) + " entries for " + str(n) + " vertices; ignored");
        else {
            mesh.uvs.resize(n);
            std::memcpy(mesh.uvs.data(), raw.data(), n * sizeof(glm::vec2));
        }
    }

    const std::size_t dropped = dropNonFiniteTriangles(mesh);
    if (mesh.indices.empty())
        return skip(dropped ? "all " + str(dropped) + " triangles have non-finite (inf/NaN) positions" : "no triangles");
    if (dropped) warn(where + ": " + str(dropped) + " triangles with non-finite (inf/NaN) positions dropped");
    zeroArea_ += countZeroArea(mesh);

    if (mesh.normals.empty()) {
        mesh.normals = smoothNormals(mesh);
    } else {
        std::vector<glm::vec3> fallback;
        std::size_t repaired = 0;
        for (std::size_t i = 0; i < n && i < mesh.normals.size(); ++i) {
            glm::vec3& v = mesh.normals[i];
            const float len = glm::length(v);
            if (finite(v) && len > 1e-12f && std::isfinite(len)) {
                v /= len;
                continue;
            }
            if (fallback.empty()) fallback = smoothNormals(mesh);
            v = fallback[i];
            ++repaired;
        }
        if (repaired) warn(where + ": " + str(repaired) + " zero or non-finite normals recomputed");
    }
    std::size_t badUv = 0;
    for (glm::vec2& uv : mesh.uvs) {
        if (std::isfinite(uv.x) && std::isfinite(uv.y)) continue;
        uv = glm::vec2(0.0f);
        ++badUv;
    }
    if (badUv) warn(where + ": " + str(badUv) + " non-finite texture coordinates set to 0");

    if (p.material >= int(model_.materials.size())) warn(where + ": material " + str(p.material) + " does not exist");
    mesh.material = p.material < int(model_.materials.size()) ? std::max(p.material, -1) : -1;
    if (!p.targets.empty() && !morphWarned_) {
        morphWarned_ = true;
        warn("morph targets are ignored: meshes are drawn in their base shape");
    }
    return mesh;
}

const std::vector<int>& Loader::meshPrimitives(int meshIndex) {
    std::optional<std::vector<int>>& cached = meshCache_[std::size_t(meshIndex)];
    if (cached) return *cached;
    cached.emplace();
    const tg::Mesh& gm = model_.meshes[std::size_t(meshIndex)];
    if (gm.primitives.empty()) warn(meshLabel(meshIndex) + " has no (valid) primitives");
    for (std::size_t i = 0; i < gm.primitives.size(); ++i) {
        if (std::optional<Mesh> mesh = convertPrimitive(meshIndex, int(i))) {
            cached->push_back(int(scene_.meshes.size()));
            scene_.meshes.push_back(std::move(*mesh));
        }
    }
    return *cached;
}

glm::dmat4 Loader::localMatrix(int index) {
    const tg::Node& node = model_.nodes[std::size_t(index)];
    const std::string where = "node " + str(index);
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, like glm
    if (!node.matrix.empty()) warn(where + ": matrix with " + str(node.matrix.size()) + " values ignored");
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) m = glm::translate(m, glm::make_vec3(node.translation.data()));
    if (node.rotation.size() == 4) {
        const auto& r = node.rotation;  // glTF order x, y, z, w
        glm::dquat q(r[3], r[0], r[1], r[2]);
        const double len = glm::length(q);
        if (len > 1e-12 && std::isfinite(len))
            m *= glm::mat4_cast(q / len);
        else
            warn(where + ": degenerate rotation quaternion ignored");
    }
    if (node.scale.size() == 3) m = glm::scale(m, glm::make_vec3(node.scale.data()));
    return m;
}

void Loader::importLight(int nodeIndex, const glm::dmat4& world) {
    const tg::Node& node = model_.nodes[std::size_t(nodeIndex)];
    const auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end()) return;
    const tg::Value& ext = it->second;
    const int li = ext.IsObject() && ext.Has("light") && ext.Get("light").IsNumber() ? ext.Get("light").GetNumberAsInt() : -1;
    if (li < 0 || li >= int(model_.lights.size())) {
        warn("node " + str(nodeIndex) + ": KHR_lights_punctual refers to a light that does not exist; ignored");
        return;
    }
    const tg::Light& gl = model_.lights[std::size_t(li)];
    SceneLight light;
    light.name = gl.name.empty() ? "light " + str(li) : gl.name;
    if (gl.type == "directional")
        light.type = SceneLightType::Directional;
    else if (gl.type == "spot")
        light.type = SceneLightType::Spot;
    else if (gl.type == "point")
        light.type = SceneLightType::Point;
    else {
        warn("light '" + light.name + "': unknown type '" + gl.type + "'; ignored");
        return;
    }
    light.position = glm::vec3(world * glm::dvec4(0, 0, 0, 1));
    const glm::dvec3 dir = glm::dmat3(world) * glm::dvec3(0, 0, -1);  // the light shines along its node's -Z
    const double len = glm::length(dir);
    if (len > 1e-12 && std::isfinite(len))
        light.direction = glm::vec3(dir / len);
    else
        warn("light '" + light.name + "': its node's transform has no -Z direction; (0,0,-1) used");
    if (light.type == SceneLightType::Spot) {
        const double outer = gl.spot.outerConeAngle;
        light.outerConeRad = float(std::isfinite(outer) ? std::clamp(outer, 1e-4, 1.5707963267948966) : 0.7853981634);
    }
    if (std::isfinite(gl.range) && gl.range > 0.0) light.range = float(gl.range);
    if (gl.color.size() == 3 && std::isfinite(gl.color[0] + gl.color[1] + gl.color[2]))
        light.color = glm::vec3(float(gl.color[0]), float(gl.color[1]), float(gl.color[2]));
    if (std::isfinite(gl.intensity) && gl.intensity >= 0.0) light.intensity = float(gl.intensity);
    scene_.lights.push_back(light);
}

void Loader::visit(int index, const glm::dmat4& parent, int depth) {
    if (index < 0 || index >= int(model_.nodes.size())) {
        warn("node " + str(index) + " does not exist; ignored");
        return;
    }
    if (onPath_[std::size_t(index)]) {  // a node that is its own ancestor: cut the loop (RecursiveNodes.gltf)
        if (!cycleWarned_) warn("the node graph has a cycle through node " + str(index) + "; the cycle is cut there");
        cycleWarned_ = true;
        return;
    }
    if (depth > kMaxNodeDepth || ++visits_ > kMaxNodeVisits) {
        bool& warned = depth > kMaxNodeDepth ? depthWarned_ : visitsWarned_;
        if (!warned) warn(depth > kMaxNodeDepth ? "node hierarchy deeper than " + str(kMaxNodeDepth) + "; cut there"
                                                : "more than " + str(kMaxNodeVisits) + " node visits; the rest is cut");
        warned = true;
        return;
    }
    const tg::Node& node = model_.nodes[std::size_t(index)];
    const glm::dmat4 world = parent * localMatrix(index);
    if (!allFinite(world)) {
        warn("node " + str(index) + ": transform is not finite; the node and its children are ignored");
        return;
    }
    if (node.mesh >= int(model_.meshes.size())) warn("node " + str(index) + ": mesh " + str(node.mesh) + " does not exist");
    if (node.mesh >= 0 && node.mesh < int(model_.meshes.size())) {
        if (node.skin >= 0 && !skinWarned_) {
            skinWarned_ = true;
            warn("skinning is ignored: skinned meshes are drawn in their bind pose");
        }
        // A singular transform (scale 0) has no normal matrix: skip it. Negative determinants (mirrors) are kept.
        const double det = glm::determinant(glm::dmat3(world));
        for (int mesh : meshPrimitives(node.mesh)) {
            if (!(std::abs(det) > 1e-30)) {
                ++degenerateInstances_;
                continue;
            }
            scene_.instances.push_back(Instance{mesh, glm::mat4(world)});
        }
    }
    importLight(index, world);
    onPath_[std::size_t(index)] = 1;
    for (int child : node.children) visit(child, world, depth + 1);
    onPath_[std::size_t(index)] = 0;
}

// The default scene, else scene 0, else every node nobody lists as a child.
std::vector<int> Loader::rootNodes() {
    const int count = int(model_.scenes.size());
    if (model_.defaultScene >= count) warn("default scene " + str(model_.defaultScene) + " does not exist");
    if (count > 0) {
        const int chosen = model_.defaultScene >= 0 && model_.defaultScene < count ? model_.defaultScene : 0;
        const std::vector<int>& nodes = model_.scenes[std::size_t(chosen)].nodes;
        if (nodes.empty()) warn("scene " + str(chosen) + " lists no nodes");
        return nodes;
    }
    std::vector<char> isChild(model_.nodes.size(), 0);
    for (const tg::Node& n : model_.nodes)
        for (int c : n.children)
            if (c >= 0 && c < int(isChild.size())) isChild[std::size_t(c)] = 1;
    std::vector<int> roots;
    for (std::size_t i = 0; i < isChild.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    if (!roots.empty()) warn("the file has no scenes; all " + str(roots.size()) + " root nodes are loaded");
    return roots;
}

std::optional<Scene> Loader::run(std::string& error) {
    if (!checkRequiredExtensions(error)) return std::nullopt;
    for (std::size_t i = 0; i < model_.materials.size(); ++i) scene_.materials.push_back(convertMaterial(int(i)));
    for (int root : rootNodes()) visit(root, glm::dmat4(1.0), 0);

    if (zeroArea_ > 0) warn(str(zeroArea_) + " zero-area triangles kept (they cast no shadow)");
    if (degenerateInstances_ > 0)
        warn(str(degenerateInstances_) + " mesh instances with a singular (zero-scale) transform skipped");
    if (scene_.instances.empty()) {
        error = "no triangle geometry";
        std::string why;
        for (std::size_t i = 0; i < scene_.warnings.size() && i < 3; ++i) why += (i ? "; " : "") + scene_.warnings[i];
        if (!why.empty()) error += " (" + why + ")";
        return std::nullopt;
    }
    if (suppressedWarnings_ > 0) scene_.warnings.push_back("... and " + str(suppressedWarnings_) + " more warnings");
    scene_.computeBounds();
    if (scene_.bounds.empty) {
        error = "no finite geometry after applying the node transforms";
        return std::nullopt;
    }
    return std::move(scene_);
}

SceneLoadResult failure(const std::string& path, const std::string& what) {
    SceneLoadResult r;
    r.error = path + ": " + what;
    return r;
}

SceneLoadResult loadImpl(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::exists(path, ec)) return failure(path, "file not found");
    if (!fs::is_regular_file(path, ec)) return failure(path, "not a regular file");
    const std::uintmax_t size = fs::file_size(path, ec);
    if (ec) return failure(path, "cannot be read (" + ec.message() + ")");
    if (size == 0) return failure(path, "the file is empty");
    if (size >= std::numeric_limits<unsigned int>::max()) return failure(path, "larger than 4 GiB, which glTF cannot be");

    char magic[4] = {};
    std::ifstream(path, std::ios::binary).read(magic, 4);
    const bool binary = std::memcmp(magic, "glTF", 4) == 0;  // GLB by content, whatever the extension says

    tg::Model model;
    tg::TinyGLTF gltf;
    EncodedImages images{&model, {}};
    gltf.SetImageLoader(&keepEncodedImage, &images);
    std::string err, warn;
    const bool ok = binary ? gltf.LoadBinaryFromFile(&model, &err, &warn, path)
                           : gltf.LoadASCIIFromFile(&model, &err, &warn, path);
    if (!ok) {
        if (const std::string ext = unsupportedRequiredExtension(path, binary); !ext.empty())
            return failure(path, compressedGeometryError(ext));
        std::string why = joinLines(err);
        if (why.empty()) why = joinLines(warn);
        if (why.find("File not found") != std::string::npos)
            return failure(path, "a file it refers to is missing (" + why + ")");
        return failure(path, std::string("cannot be loaded as ") + (binary ? "GLB" : "glTF") +
                                 (why.empty() ? "" : " (" + why + ")"));
    }

    Loader loader(model, images);
    for (const std::string& line : splitLines(warn)) loader.warn("tinygltf: " + line);
    std::string error;
    std::optional<Scene> scene = loader.run(error);
    if (!scene) return failure(path, error);
    std::string name = fs::path(path).stem().string();
    if (name.size() > 5 && name.ends_with(".gltf")) name.resize(name.size() - 5);  // X.gltf.json -> X
    scene->name = name;
    return SceneLoadResult{std::move(scene), {}};
}

}  // namespace

SceneLoadResult loadGltfScene(const std::string& path) {
    try {
        return loadImpl(path);
    } catch (const std::bad_alloc&) {
        return failure(path, "out of memory while loading");
    } catch (const std::exception& e) {
        return failure(path, std::string("failed to load: ") + e.what());
    }
}

}  // namespace shadowlab
