#include "editor/field_widgets.h"

#include "settings/settings_fields.h"
#include "shading/cascade_tints.h"

#include <string>

namespace shadowlab::editor {

namespace {

const SettingsField& fieldOf(const char* key) {
    const SettingsField* field = findSettingsField(key);
    IM_ASSERT(field && "editor control bound to an unknown preset key");
    return *field;
}

}  // namespace

std::string controlName(const char* key) {
    const SettingsField& field = fieldOf(key);
    if (field.light < 0) return field.key;
    // The panels show one light at a time, so a light's control keeps its schema-1 name whichever light it edits.
    if (field.group().empty()) return "light." + std::string(field.lightKey());
    return std::string(field.lightKey());
}

namespace {

// Shared tail of every bound control. The recorded rectangle is the control's frame, without its label, so a
// click at a fraction of its width means that fraction of a slider's range.
void finishControl(EditorState& state, const char* key) {
    const std::string name = controlName(key);
    state.controls.recordLastItem(name);
    if (const ControlRect* r = state.controls.find(name); r && r->w > ImGui::CalcItemWidth()) {
        ControlRect frame = *r;
        frame.w = ImGui::CalcItemWidth();
        state.controls.record(name, frame);
    }
    fieldHelp(state, key);
    showFieldError(state, key);
}

}  // namespace

bool sliderFloatField(EditorState& state, const char* key, const char* label, float lo, float hi, const char* format,
                      ImGuiSliderFlags flags) {
    const SettingsField& field = fieldOf(key);
    float value = field.get(state.settings).get<float>();
    bool changed = ImGui::SliderFloat(label, &value, lo, hi, format, flags) && state.edit(key, value);
    finishControl(state, key);
    return changed;
}

bool dragFloatField(EditorState& state, const char* key, const char* label, float speed, const char* format) {
    const SettingsField& field = fieldOf(key);
    float value = field.get(state.settings).get<float>();
    // No clamping here: typed values outside the key's range reach the key table, which refuses them.
    bool changed = ImGui::DragFloat(label, &value, speed, 0.0f, 0.0f, format) && state.edit(key, value);
    finishControl(state, key);
    return changed;
}

bool checkboxField(EditorState& state, const char* key, const char* label) {
    const SettingsField& field = fieldOf(key);
    bool value = field.get(state.settings).get<bool>();
    bool changed = ImGui::Checkbox(label, &value) && state.edit(key, value);
    finishControl(state, key);
    return changed;
}

bool comboField(EditorState& state, const char* key, const char* label) {
    const SettingsField& field = fieldOf(key);
    const nlohmann::json current = field.get(state.settings);
    std::vector<nlohmann::json> options;
    if (field.kind == SettingsFieldKind::Enum)
        for (const std::string& c : field.choices) options.emplace_back(c);
    else
        for (int c : field.intChoices) options.emplace_back(c);
    auto text = [](const nlohmann::json& j) { return j.is_string() ? j.get<std::string>() : j.dump(); };

    bool changed = false;
    // Every choice in view at once: ImGui's default height holds 8, and filter.kind has 9 (a scrolled list hides
    // the first choice behind the scroll to the selected one).
    if (ImGui::BeginCombo(label, text(current).c_str(), ImGuiComboFlags_HeightLargest)) {
        for (std::size_t i = 0; i < options.size(); ++i) {
            const bool selected = options[i] == current;
            if (ImGui::Selectable(text(options[i]).c_str(), selected) && !selected)
                changed = state.edit(key, options[i]);
            state.controls.recordLastItem(controlName(key) + "=" + text(options[i]));
            if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    finishControl(state, key);
    return changed;
}

std::string lightTypeText(const Settings& settings, std::size_t light) {
    // The key table's name for the type, so the editor spells it as presets do.
    const nlohmann::json type = fieldOf(("lights." + std::to_string(light) + ".type").c_str()).get(settings);
    return type.is_string() ? type.get<std::string>() : "none";
}

bool lightHeader(EditorState& state) {
    const LightSettings* light = state.selected();
    if (!light) {
        ImGui::TextDisabled("no lights: the scene is lit by ambient only (Lights panel: add one)");
        return false;
    }
    return true;
}

void fieldHelp(const EditorState&, const char* key) {
    if (!ImGui::IsItemHovered()) return;
    const SettingsField& field = fieldOf(key);
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(field.key.c_str());
    ImGui::TextUnformatted(field.description.c_str());
    ImGui::TextDisabled("allowed: %s", field.allowed.c_str());
    if (!field.unit.empty()) ImGui::TextDisabled("unit: %s", field.unit.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

void showFieldError(const EditorState& state, const char* key) {
    if (const std::string* error = state.fieldError(key)) errorText(*error);
}

ImU32 cascadeColour(int index) {
    const glm::vec3 c = cascadeTint(index);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f));
}

void cascadeSwatch(int index) {
    const float side = ImGui::GetTextLineHeight() * 0.8f;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float y = at.y + (ImGui::GetTextLineHeight() - side) * 0.5f;
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(at.x, y), ImVec2(at.x + side, y + side), cascadeColour(index));
    ImGui::Dummy(ImVec2(side, ImGui::GetTextLineHeight()));
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
}

void warningText(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

void noteText(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

void errorText(const std::string& text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

}  // namespace shadowlab::editor
