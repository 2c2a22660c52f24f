#include "editor/message_log.h"

#include <imgui.h>

#include <ctime>
#include <string>

namespace shadowlab::editor {

std::string localTimeText(const char* format) {
    const std::time_t t = std::time(nullptr);
    std::tm local{};
    localtime_r(&t, &local);
    char text[64];
    return std::strftime(text, sizeof text, format, &local) ? text : "";
}

std::string clockStamp() { return localTimeText("%H:%M:%S"); }

void messageLogButton(EditorState& state) {
    const std::string label = "Log (" + std::to_string(state.messages.size()) + ")###messageLog";
    if (ImGui::SmallButton(label.c_str())) ImGui::OpenPopup("Message log");
    state.controls.recordLastItem("status.log");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The last %d messages, with their times", int(EditorState::kMessagesKept));
    // Above the status line, as wide as a long message needs, never off the window.
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImVec2 size(std::min(display.x - 20.0f, ImGui::GetFontSize() * 60.0f), std::min(display.y * 0.6f, 420.0f));
    ImGui::SetNextWindowSize(size, ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImVec2(10.0f, ImGui::GetItemRectMin().y - 4.0f), ImGuiCond_Appearing, ImVec2(0.0f, 1.0f));
    // Opaque: the panels behind it would show through the text.
    ImVec4 background = ImGui::GetStyleColorVec4(ImGuiCol_PopupBg);
    background.w = 1.0f;
    ImGui::PushStyleColor(ImGuiCol_PopupBg, background);
    const bool open = ImGui::BeginPopup("Message log");
    ImGui::PopStyleColor();
    if (!open) return;
    const ImVec2 pos = ImGui::GetWindowPos(), windowSize = ImGui::GetWindowSize();
    state.controls.record("log", ControlRect{pos.x, pos.y, windowSize.x, windowSize.y});
    ImGui::TextDisabled("%d messages, newest last (also printed in the terminal)", int(state.messages.size()));
    ImGui::SameLine();
    if (ImGui::SmallButton("Copy all")) {
        std::string all;
        for (const Message& m : state.messages)
            all += "[" + m.clock + "] " + (m.error ? "error: " : "") + m.text + "\n";
        ImGui::SetClipboardText(all.c_str());
    }
    state.controls.recordLastItem("log.copy");
    ImGui::Separator();
    ImGui::BeginChild("##messages", ImVec2(0, 0), false, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::PushTextWrapPos(0.0f);  // wrap at the child's edge: nothing is cut
    for (std::size_t i = 0; i < state.messages.size(); ++i) {
        const Message& m = state.messages[i];
        ImGui::TextDisabled("%s", m.clock.c_str());
        ImGui::SameLine();
        if (m.error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextUnformatted(m.text.c_str());
        if (m.error) ImGui::PopStyleColor();
        state.controls.recordLastItem("log." + std::to_string(i));
    }
    ImGui::PopTextWrapPos();
    // Opened at the newest message; it stays where the user scrolled to while open.
    if (ImGui::IsWindowAppearing()) ImGui::SetScrollHereY(1.0f);
    ImGui::EndChild();
    ImGui::EndPopup();
}

}  // namespace shadowlab::editor
