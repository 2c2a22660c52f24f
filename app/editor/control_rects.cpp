#include "editor/control_rects.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

namespace shadowlab::editor {

void ControlRects::recordLastItem(const std::string& name) {
    const ImVec2 min = ImGui::GetItemRectMin();
    const ImVec2 max = ImGui::GetItemRectMax();
    rects_[name] = ControlRect{min.x, min.y, max.x - min.x, max.y - min.y};
}

const ControlRect* ControlRects::find(const std::string& name) const {
    auto it = rects_.find(name);
    return it == rects_.end() ? nullptr : &it->second;
}

std::string ControlRects::toJson() const {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [name, r] : rects_) out[name] = {r.x, r.y, r.w, r.h};
    return out.dump(1);
}

}  // namespace shadowlab::editor
