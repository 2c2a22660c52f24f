#include "shading/variant_key.h"

#include "settings/settings_fields.h"
#include "shading/cascade_tints.h"
#include "shading/filter_taps.h"
#include "shading/filters/filter_technique.h"
#include "views/map_group.h"
#include "views/view_builders.h"

#include <cctype>
#include <set>
#include <stdexcept>

namespace shadowlab {

std::string upperCase(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

std::vector<std::string> MainVariantKey::defines() const {
    FilterSettings filterSettings;
    filterSettings.kind = filter;
    filterSettings.kernel = kernel;
    // A moments technique reads its moments through its own file (the program's "alias:technique"), no taps.
    // A technique with a lookup of its own (PCSS) takes the taps it scales and its file ("alias:lookup").
    const bool moments = filterTechnique(filter).moments != nullptr;
    std::vector<std::string> d = moments ? std::vector<std::string>{"MOMENT_TECHNIQUE"} : filterDefines(filterSettings);
    if (filterTechnique(filter).ownLookup) d.push_back("OWN_LOOKUP");
    if (moments && momentMips) d.push_back("MOMENT_MIPS");
    switch (view) {
        case ViewMode::Lit: d.push_back("VIEW_LIT"); break;
        case ViewMode::Shadow: d.push_back("VIEW_SHADOW"); break;
        case ViewMode::LightDepth: d.push_back("VIEW_LIGHT_DEPTH"); break;
        case ViewMode::Cascades:
            d.push_back("VIEW_CASCADES");
            d.push_back(cascadeTintsDefine());  // the colours the editor's lists and frusta use too
            break;
        case ViewMode::TexelDensity: d.push_back("VIEW_TEXEL_DENSITY"); break;
    }
    d.push_back("DIR_LIGHTS " + std::to_string(lights.directional));
    d.push_back("DIR_CASTERS " + std::to_string(lights.directionalCasters));
    d.push_back("SPOT_LIGHTS " + std::to_string(lights.spot));
    d.push_back("SPOT_CASTERS " + std::to_string(lights.spotCasters));
    d.push_back("POINT_LIGHTS " + std::to_string(lights.point));
    d.push_back("POINT_CASTERS " + std::to_string(lights.pointCasters));
    d.push_back("MAP_ARRAYS_2D " + std::to_string(lights.mapArrays2D));
    d.push_back("MAP_ARRAYS_CUBE " + std::to_string(lights.mapArraysCube));
    d.push_back("CASCADES " + std::to_string(lights.cascades));
    if (normalOffset) d.push_back("NORMAL_OFFSET");
    if (receiverPlane) d.push_back("RECEIVER_PLANE");
    if (receiverPlane && !filterTechnique(filter).bilinear) d.push_back("FILTER_NEAREST");
    if (alphaMask) d.push_back("ALPHA_MASK");
    if (alphaMask && alphaTexture) d.push_back("BASE_COLOR_TEXTURE");
    return d;
}

std::string MainVariantKey::name() const {
    std::string joined;
    for (std::string d : defines()) {
        if (d.starts_with("FILTER_TAP_OFFSETS") || d.starts_with("FILTER_GRID_RADIUS")) continue;  // the numbers follow from the filter, said by FILTER_TAPS
        if (d.starts_with("CASCADE_TINTS")) continue;  // fixed colours, said by VIEW_CASCADES
        if (d == "MOMENT_TECHNIQUE") d = "FILTER_" + upperCase(filterTechnique(filter).name) + " " + d;
        if (d.starts_with("FILTER_TAPS")) d = "FILTER_" + upperCase(filterTechnique(filter).name) +
                                              (filter == FilterKind::Pcf ? " PCF_KERNEL " + std::to_string(kernel) : "") +
                                              " " + d;
        joined += (joined.empty() ? "" : " ") + d;
    }
    return joined;
}

Settings variantInputs(const Settings& effective) {
    Settings inputs;
    inputs.lights.assign(effective.lights.size(), LightSettings{});
    for (const SettingsField* field : settingsFieldsOf(effective)) {
        if (!(field->invalidates & kInvalidatesVariant)) continue;
        // A value read from valid settings is always accepted; a refusal is a bug in the key table.
        if (std::string error = field->set(inputs, field->get(effective)); !error.empty())
            throw std::logic_error("variantInputs: " + error);
    }
    return inputs;
}

MainVariantKey mainVariantKey(const Settings& effective) {
    const Settings s = variantInputs(effective);
    MainVariantKey key;
    key.filter = s.filter.kind;
    key.kernel = s.filter.kind == FilterKind::Pcf ? s.filter.kernel : 0;
    key.view = s.view;
    const FilterTechnique& technique = filterTechnique(s.filter.kind);
    key.momentMips = technique.moments && s.filter.momentMips;
    std::set<MapGroup> arrays2D, arraysCube;
    for (const LightSettings& light : s.lights) {
        if (!light.enabled) continue;  // the main pass walks enabled lights only
        const bool casts = light.castsShadows;
        switch (light.type) {
            case LightType::Directional: ++key.lights.directional; key.lights.directionalCasters += casts; break;
            case LightType::Spot: ++key.lights.spot; key.lights.spotCasters += casts; break;
            case LightType::Point: ++key.lights.point; key.lights.pointCasters += casts; break;
        }
        if (!casts) continue;
        const MapGroup group = mapGroupOf(light);
        (group.cube ? arraysCube : arrays2D).insert(group);
        if (cascadesApply(light)) key.lights.cascades += light.projection.cascadeCount;
        key.normalOffset = key.normalOffset || light.shadow.normalOffset > 0.0f;
        key.receiverPlane = key.receiverPlane || (light.shadow.receiverPlaneBias && light.type != LightType::Point &&
                                                  technique.receiverPlane);
    }
    key.lights.mapArrays2D = int(arrays2D.size());
    key.lights.mapArraysCube = int(arraysCube.size());
    return key;
}

}  // namespace shadowlab
