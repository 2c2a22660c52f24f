#pragma once
// The editor's look: a readable font (DejaVu Sans from fonts-dejavu-core when installed, else ImGui's built-in
// one) and a dark theme with a little more room than ImGui's defaults. Call once after ImGui::CreateContext.
namespace shadowlab::editor {

// Returns the font file used, or "" for ImGui's built-in font.
const char* applyEditorStyle();

}  // namespace shadowlab::editor
