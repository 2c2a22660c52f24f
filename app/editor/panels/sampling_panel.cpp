// Sampling: address mode with border depth, filter kind with kernel size or Poisson radius.
#include "editor/field_widgets.h"
#include "editor/panels/panel_registry.h"

namespace shadowlab::editor {

void drawSamplingPanel(PanelContext& ctx) {
    EditorState& state = ctx.state;
    ImGui::PushItemWidth(-120.0f);
    comboField(state, "sampler.addressMode", "address mode");
    if (state.settings.sampler.addressMode == AddressMode::ClampToBorder)
        sliderFloatField(state, "sampler.borderDepth", "border depth", 0.0f, 1.0f, "%.3f");
    comboField(state, "filter.kind", "filter");
    if (state.settings.filter.kind == FilterKind::Pcf) comboField(state, "filter.kernel", "kernel (NxN)");
    if (state.settings.filter.kind == FilterKind::Poisson)
        sliderFloatField(state, "filter.poissonRadius", "radius (texels)", 0.5f, 8.0f, "%.2f");
    ImGui::PopItemWidth();
}

}  // namespace shadowlab::editor
