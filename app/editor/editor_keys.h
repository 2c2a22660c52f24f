#pragma once
// Key codes the editor's shortcuts read from ImGui's io.KeysDown. ImGui 1.86's GLFW backend indexes KeysDown by
// GLFW key code, so these are GLFW's values (stable since GLFW 3.0); headless tests press the same indices.
namespace shadowlab::editor::keys {

// Fly mode (right button held on the view): W A S D travel, Q / E down / up.
inline constexpr int kA = 65;
inline constexpr int kD = 68;
inline constexpr int kE = 69;
inline constexpr int kW = 87;
inline constexpr int kF = 70;
inline constexpr int kO = 79;
inline constexpr int kP = 80;  // held over the viewport: probe the pixel under the cursor
inline constexpr int kQ = 81;
inline constexpr int kS = 83;
inline constexpr int kF12 = 301;
inline constexpr int kLeftShift = 340;
inline constexpr int kLeftControl = 341;
inline constexpr int kLeftAlt = 342;

}  // namespace shadowlab::editor::keys
