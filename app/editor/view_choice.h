#pragma once
// A panel's choice among one light's shadow views (the Probe and Export panels; issue 20): "all views" or one view,
// named as the CLI's `--view` names it ("+X" .. "-Z", "cascade:N") and resolved against the light's views by the same
// findView (views/shadow_view.h). The choice belongs to the light and the views it was made among: when the light,
// its kind or its cascade count changes it falls back to all views, so it never names a view that does not exist.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace shadowlab::editor {

struct EditorState;

struct ViewChoice {
    std::string view;                  // "" = all views; else a view's --view name
    std::optional<std::size_t> light;  // the light it was made for
    std::vector<std::string> among;    // that light's views when it was made (their --view names)
};

// Light `light`'s views in the newest frame, by their --view names; empty for a light with one view (or none).
std::vector<std::string> viewNamesOf(const EditorState& state, std::size_t light);

// Keeps `choice` for light `light` whose views are now `views`: a different light or a different list of views
// (another kind, another cascade count) resets it to all views. Returns true when it was reset from a chosen view.
bool followLight(ViewChoice& choice, std::size_t light, const std::vector<std::string>& views);

// "light 0, all views (4 cascades)" / "light 0 cascade:1": what the numbers below it describe.
std::string viewChoiceLabel(const ViewChoice& choice, std::size_t light);

// The combo `id` (items recorded as "<id>=all views", "<id>=cascade:1"): all views and each view of light `light`.
// Follows the light first; disabled for a light with one view. Returns true when the user picked another item.
bool drawViewChoice(EditorState& state, ViewChoice& choice, std::size_t light, const std::string& id);

}  // namespace shadowlab::editor
