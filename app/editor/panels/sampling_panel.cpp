// Sampling: address mode with border depth, the filter technique and the keys of the chosen one (its own list:
// shading/filters/).
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"
#include "settings/settings_fields.h"
#include "shading/filters/filter_technique.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace shadowlab::editor {

namespace {

// A comfortable slider range per float key (Ctrl+click types any value the key accepts).
struct SliderRange {
    const char* key;
    const char* label;
    float lo, hi;
    const char* format;
    ImGuiSliderFlags flags;
};
constexpr SliderRange kSliders[] = {
    {"filter.poissonRadius", "radius (texels)", 0.5f, 8.0f, "%.2f", 0},
    {"filter.blurWidth", "blur width", 1.0f, 31.0f, "%.2f", 0},
    {"filter.minVariance", "min variance", 0.0f, 1e-3f, "%.2e", ImGuiSliderFlags_Logarithmic},
    {"filter.bleedReduction", "bleeding reduction", 0.0f, 0.95f, "%.2f", 0},
    {"filter.positiveExponent", "exponent c+", 0.0f, 42.0f, "%.2f", 0},
    {"filter.negativeExponent", "exponent c-", 0.0f, 42.0f, "%.2f", 0},
    {"filter.momentBias", "moment bias", 0.0f, 1e-3f, "%.2e", ImGuiSliderFlags_Logarithmic},
};

const SliderRange* sliderOf(const char* key) {
    for (const SliderRange& s : kSliders)
        if (std::strcmp(s.key, key) == 0) return &s;
    return nullptr;
}

std::string keyLabel(const char* key) {
    if (const SliderRange* s = sliderOf(key)) return s->label;
    return std::strcmp(key, "filter.kernel") == 0 ? "kernel (NxN)" : std::string(key).substr(7);
}

void techniqueKey(EditorState& state, const char* key) {
    if (const SliderRange* s = sliderOf(key)) {
        sliderFloatField(state, key, s->label, s->lo, s->hi, s->format, s->flags);
        return;
    }
    const std::string label = keyLabel(key);
    const SettingsField* field = findSettingsField(key);
    if (field && field->kind == SettingsFieldKind::Float)
        dragFloatField(state, key, label.c_str(), 0.01f);  // a new technique's key without a slider range above
    else if (field && field->kind == SettingsFieldKind::Bool)
        checkboxField(state, key, label.c_str());
    else
        comboField(state, key, label.c_str());  // enums and keys with a list of integers
}

}  // namespace

void drawSamplingPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    // The fields leave room for the widest label shown (a moments technique's "bleeding reduction" is wider than
    // the depth techniques' labels).
    const std::vector<const char*>& keys = filterTechnique(state.settings.filter.kind).keys;
    float labels = std::max(ImGui::CalcTextSize("address mode").x, ImGui::CalcTextSize("border depth").x);
    for (const char* key : keys) labels = std::max(labels, ImGui::CalcTextSize(keyLabel(key).c_str()).x);
    ImGui::PushItemWidth(-std::max(120.0f, labels + ImGui::GetStyle().ItemInnerSpacing.x + 2.0f));
    comboField(state, "sampler.addressMode", "address mode");
    if (state.settings.sampler.addressMode == AddressMode::ClampToBorder)
        sliderFloatField(state, "sampler.borderDepth", "border depth", 0.0f, 1.0f, "%.3f");
    comboField(state, "filter.kind", "filter");
    for (const char* key : filterTechnique(state.settings.filter.kind).keys) techniqueKey(state, key);  // read again: the combo may have just changed it
    for (const std::string& warning : state.stats.warnings)
        if (warning.rfind("filter.", 0) == 0) warningText(warning);  // the technique's clamps name their key
    ImGui::PopItemWidth();
}

}  // namespace shadowlab::editor
