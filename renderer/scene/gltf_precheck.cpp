#include "scene/gltf_precheck.h"

#include "settings/json_nesting.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>

namespace shadowlab::gltf {

namespace {

using nlohmann::json;

// "-4" / "0.5": the number as the file wrote it, for messages.
std::string numberText(const json& v) { return v.dump(); }

// A property glTF requires to be a non-negative integer, when present.
std::string checkCount(const json& object, const char* key, const std::string& where) {
    if (!object.is_object()) return {};
    const auto it = object.find(key);
    if (it == object.end() || !it->is_number()) return {};
    const double v = it->get<double>();
    if (v < 0) return where + "." + key + ": " + numberText(*it) + " is negative (allowed an integer >= 0)";
    if (std::trunc(v) != v) return where + "." + key + ": " + numberText(*it) + " is not an integer";
    return {};
}

// Bytes a base64 payload decodes to (padding '=' excluded).
std::size_t base64DecodedSize(std::string_view payload) {
    std::size_t n = payload.size();
    while (n > 0 && payload[n - 1] == '=') --n;
    return n * 3 / 4;
}

std::string checkDataUri(const json& buffer, const std::string& where) {
    if (!buffer.is_object()) return {};
    const auto uri = buffer.find("uri");
    const auto length = buffer.find("byteLength");
    if (uri == buffer.end() || !uri->is_string() || length == buffer.end() || !length->is_number()) return {};
    const std::string& text = uri->get_ref<const std::string&>();
    if (text.rfind("data:", 0) != 0) return {};
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos || !std::string_view(text).substr(0, comma).ends_with(";base64")) return {};
    const std::size_t decoded = base64DecodedSize(std::string_view(text).substr(comma + 1));
    if (double(decoded) == length->get<double>()) return {};
    return where + ": its data: URI holds " + std::to_string(decoded) + " bytes but byteLength says " +
           numberText(*length);
}

}  // namespace

std::string_view glbJsonChunk(const std::vector<unsigned char>& bytes) {
    auto u32 = [&](std::size_t at) {
        std::uint32_t v = 0;
        std::memcpy(&v, bytes.data() + at, 4);
        return v;  // GLB is little-endian, as is every machine this builds on
    };
    if (bytes.size() < 20 || std::memcmp(bytes.data(), "glTF", 4) != 0 || u32(16) != 0x4E4F534Au) return {};
    const std::size_t length = u32(12);
    if (length > bytes.size() - 20) return {};
    return std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20, length);
}

std::string precheckGltfJson(std::string_view text) {
    if (std::string deep = checkJsonNesting(text); !deep.empty()) return deep;
    const json doc = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object()) return {};

    auto each = [&](const char* array, auto check) -> std::string {
        const auto it = doc.find(array);
        if (it == doc.end() || !it->is_array()) return {};
        for (std::size_t i = 0; i < it->size(); ++i)
            if (std::string e = check((*it)[i], std::string(array) + "[" + std::to_string(i) + "]"); !e.empty())
                return e;
        return {};
    };
    std::string error = each("bufferViews", [](const json& v, const std::string& where) {
        for (const char* key : {"byteOffset", "byteLength", "byteStride", "buffer"})
            if (std::string e = checkCount(v, key, where); !e.empty()) return e;
        return std::string();
    });
    if (error.empty())
        error = each("accessors", [](const json& a, const std::string& where) {
            for (const char* key : {"byteOffset", "count", "bufferView"})
                if (std::string e = checkCount(a, key, where); !e.empty()) return e;
            const auto sparse = a.is_object() ? a.find("sparse") : a.end();
            if (sparse == a.end() || !sparse->is_object()) return std::string();
            if (std::string e = checkCount(*sparse, "count", where + ".sparse"); !e.empty()) return e;
            for (const char* part : {"indices", "values"}) {
                const auto p = sparse->find(part);
                if (p == sparse->end()) continue;
                const std::string at = where + ".sparse." + part;
                if (std::string e = checkCount(*p, "byteOffset", at); !e.empty()) return e;
                if (std::string e = checkCount(*p, "bufferView", at); !e.empty()) return e;
            }
            return std::string();
        });
    if (error.empty())
        error = each("buffers", [](const json& b, const std::string& where) {
            if (std::string e = checkCount(b, "byteLength", where); !e.empty()) return e;
            return checkDataUri(b, where);
        });
    return error;
}

}  // namespace shadowlab::gltf
