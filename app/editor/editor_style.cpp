#include "editor/editor_style.h"

#include <imgui.h>

#include <filesystem>

namespace shadowlab::editor {

const char* applyEditorStyle() {
    ImGuiIO& io = ImGui::GetIO();
    ImGui::StyleColorsDark();
    ImGuiStyle& style = ImGui::GetStyle();
    style.WindowRounding = 3.0f;
    style.FrameRounding = 2.0f;
    style.ItemSpacing = ImVec2(7.0f, 5.0f);
    style.WindowPadding = ImVec2(8.0f, 7.0f);
    style.WindowTitleAlign = ImVec2(0.0f, 0.5f);

    static constexpr const char* kFonts[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                             "/usr/share/fonts/TTF/DejaVuSans.ttf"};
    for (const char* path : kFonts) {
        std::error_code ec;
        if (std::filesystem::exists(path, ec) && io.Fonts->AddFontFromFileTTF(path, 15.0f)) return path;
    }
    io.Fonts->AddFontDefault();
    return "";
}

}  // namespace shadowlab::editor
