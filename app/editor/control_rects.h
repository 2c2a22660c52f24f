#pragma once
// Screen rectangles of the editor's named controls, recorded as the UI is built. Tests aim ImGui's mouse at them;
// the window host writes them to $SHADOWLAB_EDITOR_CONTROLS so scripts can click real widgets with xdotool.
#include <map>
#include <string>

namespace shadowlab::editor {

struct ControlRect {
    float x = 0, y = 0, w = 0, h = 0;  // pixels, origin at the window's top-left
    float centerX() const { return x + w * 0.5f; }
    float centerY() const { return y + h * 0.5f; }
    bool operator==(const ControlRect&) const = default;
};

class ControlRects {
public:
    // Records the last ImGui item under `name` (call right after the widget).
    void recordLastItem(const std::string& name);
    void record(const std::string& name, ControlRect rect) { rects_[name] = rect; }
    const ControlRect* find(const std::string& name) const;
    const std::map<std::string, ControlRect>& all() const { return rects_; }
    // {"name": [x, y, w, h], ...}
    std::string toJson() const;

private:
    std::map<std::string, ControlRect> rects_;
};

}  // namespace shadowlab::editor
