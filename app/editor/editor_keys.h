#pragma once
// Key codes the editor's shortcuts read from ImGui's io.KeysDown. ImGui 1.86's GLFW backend indexes KeysDown by
// GLFW key code, so these are GLFW's values (stable since GLFW 3.0); headless tests press the same indices.
namespace shadowlab::editor::keys {

inline constexpr int kF = 70;
inline constexpr int kO = 79;
inline constexpr int kP = 80;  // held over the viewport: probe the pixel under the cursor
inline constexpr int kQ = 81;
inline constexpr int kS = 83;
inline constexpr int kF12 = 301;
inline constexpr int kLeftShift = 340;
inline constexpr int kLeftControl = 341;

}  // namespace shadowlab::editor::keys
