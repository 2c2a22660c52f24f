#pragma once
// ImGui controls bound to a preset key: they show the current value from EditorState::settings, send a changed value
// through EditorState::edit (the key table), show the field's description as a tooltip and the last refusal below,
// and record their rectangle under the key's name (see ControlRects).
#include "editor/editor_state.h"

#include <imgui.h>

namespace shadowlab::editor {

// A slider over [lo, hi] (a comfortable range, not the key's whole one: Ctrl+click types any value, which the key
// table accepts or refuses).
bool sliderFloatField(EditorState& state, const char* key, const char* label, float lo, float hi,
                      const char* format = "%.3f", ImGuiSliderFlags flags = 0);
// A drag field for values without a natural range (bias units, world sizes).
bool dragFloatField(EditorState& state, const char* key, const char* label, float speed, const char* format = "%.3f");
bool checkboxField(EditorState& state, const char* key, const char* label);
// A combo over the key's enum names (or its allowed integers).
bool comboField(EditorState& state, const char* key, const char* label);

// The name a bound control is recorded under (ControlRects): the key itself for a global field, and for a light's
// field its schema-1 name ("shadow.depthBias", "light.type") whichever light it edits.
std::string controlName(const char* key);

// "directional", "spot" or "point", as presets spell it.
std::string lightTypeText(const Settings& settings, std::size_t light);

// For the panels that edit the selected light (their title names it): false, with a note, when there are none.
bool lightHeader(EditorState& state);

// Tooltip with the key, its meaning and allowed values; and the key's last refusal, in red, under the control.
void fieldHelp(const EditorState& state, const char* key);
void showFieldError(const EditorState& state, const char* key);

// Cascade `index`'s colour (shading/cascade_tints.h: the tint view's and the frusta's), and a square of it inline
// before the next item (the lists that name cascades mark them with it).
ImU32 cascadeColour(int index);
void cascadeSwatch(int index);

// Text in the theme's warning / error / disabled colours, wrapped at the panel's edge (nothing cut in a sidebar).
void warningText(const std::string& text);
void noteText(const std::string& text);
void errorText(const std::string& text);

}  // namespace shadowlab::editor
