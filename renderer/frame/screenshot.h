#pragma once
// Screenshots: a RenderTarget's colour as PNG in a folder, named shadowlab-YYYYMMDD-HHMMSS.png (local time), with
// -2, -3, ... appended when that name is taken: an existing file is never overwritten. Optionally the shadow map
// beside it, as float EXR and viewable PNG (same stem + "-shadowmap"). Creates the folder if missing.
#include "frame/render_target.h"
#include "image/png_text.h"
#include "shadow/shadow_map.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

struct ScreenshotResult {
    std::string error;         // "" on success; else what failed and why (folder not writable, disk full, ...)
    std::string viewPng;       // paths written
    std::string shadowMapExr;  // empty unless the shadow map was asked for
    std::string shadowMapPng;
    bool ok() const { return error.empty(); }
};

// `shadowMap` null: the view only. `text` rides in the view PNG (the preset it shows, preset_png.h). On failure `error` says which file failed and why; files written before it are
// complete and keep their paths in the result.
ScreenshotResult writeScreenshot(const RenderTarget& target, const std::string& folder,
                                 const ShadowMap* shadowMap = nullptr,
                                 std::chrono::system_clock::time_point when = std::chrono::system_clock::now(),
                                 const PngText& text = {});

// As above with the picture the user saw instead of a target's (e.g. A/B's split view): RGBA8, width x height, row 0
// at the top.
ScreenshotResult writeScreenshot(const std::vector<std::uint8_t>& rgbaTopFirst, int width, int height,
                                 const std::string& folder, const ShadowMap* shadowMap = nullptr,
                                 std::chrono::system_clock::time_point when = std::chrono::system_clock::now(),
                                 const PngText& text = {});

}  // namespace shadowlab
