#include "scene/gltf_materials.h"

#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace shadowlab::gltf {
namespace {

class MaterialImporter {
public:
    MaterialImporter(const tg::Model& model, const Warn& warn) : model_(model), warn_(warn) {}

    // The material, and in `source` the glTF image of its base colour texture (-1: none).
    Material convert(int index, int& source);

private:
    void applyTextureTransform(const tg::TextureInfo& info, Material& m, const std::string& where);

    const tg::Model& model_;
    const Warn& warn_;
};

Material MaterialImporter::convert(int index, int& source) {
    source = -1;
    const tg::Material& gm = model_.materials[std::size_t(index)];
    Material m;
    m.name = gm.name.empty() ? "material " + str(index) : gm.name;
    const std::string where = "material '" + m.name + "'";
    if (gm.alphaMode == "MASK")
        m.alphaMode = AlphaMode::Mask;
    else if (gm.alphaMode == "BLEND")
        m.alphaMode = AlphaMode::Blend;
    else if (!gm.alphaMode.empty() && gm.alphaMode != "OPAQUE")
        warn_(where + ": unknown alphaMode '" + gm.alphaMode + "', treated as OPAQUE");
    // Alpha is in [0, 1], so is a meaningful cutoff; a larger one (1e308) would also overflow the float.
    if (gm.alphaCutoff >= 0.0 && gm.alphaCutoff <= 1.0)
        m.alphaCutoff = float(gm.alphaCutoff);
    else
        warn_(where + ": alphaCutoff " + str(gm.alphaCutoff) +
              " is out of range (allowed [0, 1]); 0.5 used");
    const std::vector<double>& f = gm.pbrMetallicRoughness.baseColorFactor;
    if (f.size() == 4 && std::all_of(f.begin(), f.end(), [](double v) { return std::isfinite(v); }))
        m.baseColorFactor = glm::vec4(glm::clamp(glm::dvec4(f[0], f[1], f[2], f[3]), 0.0, 1.0));
    else if (!f.empty())
        warn_(where + ": invalid baseColorFactor, white used");
    m.doubleSided = gm.doubleSided;

    const tg::TextureInfo& info = gm.pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0) return m;
    m.baseColorTexCoord = info.texCoord;
    if (info.index >= int(model_.textures.size())) {
        warn_(where + ": base colour texture " + str(info.index) + " does not exist; ignored");
        return m;
    }
    const tg::Texture& tex = model_.textures[std::size_t(info.index)];
    if (tex.source >= 0 && tex.source < int(model_.images.size()))
        source = tex.source;
    else
        warn_(where + ": base colour texture " + str(info.index) +
             " has no usable image source (e.g. only KHR_texture_basisu / EXT_texture_webp); alpha from the factor only");
    if (tex.sampler >= 0 && tex.sampler < int(model_.samplers.size())) {
        const tg::Sampler& s = model_.samplers[std::size_t(tex.sampler)];
        // One flag for both axes: clamp only when both clamp (MIRRORED_REPEAT counts as repeat).
        m.wrapRepeat = !(s.wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE && s.wrapT == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
    }
    applyTextureTransform(info, m, where);
    if (source >= 0 && m.baseColorTexCoord != 0)
        warn_(where + ": base colour texture uses TEXCOORD_" + str(m.baseColorTexCoord) +
             "; only TEXCOORD_0 is loaded and used instead");
    return m;
}

// KHR_texture_transform as uv' = T * R * S * (uv, 1). The rotation sign follows the sample model, the sample viewer,
// three.js and Babylon (KhronosGroup/glTF#1563): the GLSL listing in the extension's README has it the other way.
void MaterialImporter::applyTextureTransform(const tg::TextureInfo& info, Material& m, const std::string& where) {
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
        warn_(where + ": invalid KHR_texture_transform; ignored");
        return;
    }
    const double c = std::cos(rotation), s = std::sin(rotation);
    const glm::dmat3 translate(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::dmat3 rotate(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::dmat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    const glm::dmat3 transform = translate * rotate * scaling;
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row)
            if (!fitsFloat(transform[col][row])) {
                warn_(where + ": KHR_texture_transform beyond float range; ignored");
                return;
            }
    m.uvTransform = glm::mat3(transform);
}

}  // namespace

std::vector<int> importMaterials(const tg::Model& model, Scene& scene, const Warn& warn) {
    MaterialImporter importer(model, warn);
    std::vector<int> sources(model.materials.size(), -1);
    for (std::size_t i = 0; i < model.materials.size(); ++i)
        scene.materials.push_back(importer.convert(int(i), sources[i]));
    return sources;
}

std::string importMaterialImages(const tg::Model& model, const EncodedImages& images,
                                 const std::vector<int>& baseColorSources, Scene& scene, DecodeBudget& budget,
                                 const Warn& warn) {
    // The materials drawn: those of the meshes the instances use (a material no drawn primitive names costs nothing).
    std::vector<char> drawn(scene.materials.size(), 0);
    for (const Instance& instance : scene.instances) {
        const int material = scene.meshes[std::size_t(instance.mesh)].material;
        if (material >= 0 && std::size_t(material) < drawn.size()) drawn[std::size_t(material)] = 1;
    }
    // Each image once: sized from its header and counted against the budget before anything is decoded.
    constexpr int kUnusable = -1, kNotSeen = -2;
    std::vector<int> planned(model.images.size(), kNotSeen);  // by canonical glTF image: its place in toDecode
    std::vector<int> toDecode;                                // canonical glTF images, in order of first use
    std::vector<std::size_t> firstUser;                       // by place in toDecode: the first material using it
    for (std::size_t m = 0; m < scene.materials.size() && m < baseColorSources.size(); ++m) {
        if (!drawn[m] || baseColorSources[m] < 0) continue;
        const int source = images.canonical(baseColorSources[m]);
        if (source < 0 || std::size_t(source) >= planned.size()) continue;
        int& slot = planned[std::size_t(source)];
        if (slot != kNotSeen) continue;
        std::string why;
        const std::optional<ImageSize> size = imageSize(images, source, why);
        if (!size) {
            warn("material '" + scene.materials[m].name + "': " + imageLabel(model, source) + " " + why +
                 "; texture ignored (alpha from the factor only)");
            slot = kUnusable;
            continue;
        }
        if (!budget.take(size->decodedBytes()))
            return imageLabel(model, source) + " (base colour of material '" + scene.materials[m].name +
                   "') decodes to " + str(size->width) + "x" + str(size->height) + " RGBA8 = " +
                   str(size->decodedBytes() >> 20) + " MiB, which passes the scene's " + str(kMaxDecodedBytes >> 20) +
                   " MiB limit: " + str(budget.used >> 20) + " MiB of buffers, vertex data and images come before it";
        slot = int(toDecode.size());
        toDecode.push_back(source);
        firstUser.push_back(m);
    }
    std::vector<int> decodedAs(toDecode.size(), kUnusable);  // by position in toDecode: the Scene image
    for (std::size_t i = 0; i < toDecode.size(); ++i) {
        Image image;
        std::string why;
        if (decodeImage(images, toDecode[i], image, why)) {
            decodedAs[i] = int(scene.images.size());
            scene.images.push_back(std::move(image));
        } else {
            warn("material '" + scene.materials[firstUser[i]].name + "': " + imageLabel(model, toDecode[i]) + " " +
                 why + "; texture ignored (alpha from the factor only)");
        }
    }
    for (std::size_t m = 0; m < scene.materials.size() && m < baseColorSources.size(); ++m) {
        if (!drawn[m] || baseColorSources[m] < 0) continue;
        const int source = images.canonical(baseColorSources[m]);
        if (source < 0 || std::size_t(source) >= planned.size()) continue;
        const int slot = planned[std::size_t(source)];
        scene.materials[m].baseColorImage = slot >= 0 ? decodedAs[std::size_t(slot)] : -1;
    }
    return {};
}

}  // namespace shadowlab::gltf
