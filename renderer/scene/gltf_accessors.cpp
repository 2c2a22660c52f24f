#include "scene/gltf_accessors.h"

#include <algorithm>

namespace shadowlab::gltf {
namespace {

constexpr std::size_t kMaxZeroElements = 1u << 26;  // an accessor without data is zeros, but not absurdly many

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

}  // namespace

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

}  // namespace shadowlab::gltf
