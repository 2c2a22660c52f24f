#include "views/map_group.h"

#include "settings/settings_fields.h"

#include <algorithm>

namespace shadowlab {

std::string shadowResolutionRefusal(int resolution, int maxTextureSize, const std::string& kept) {
    // The key's own range, narrowed by the GPU: the same bounds the preset table states.
    const SettingsField& key = *findSettingsField("shadow.resolution");
    const int lo = int(key.min), hi = std::min(int(key.max), maxTextureSize);
    if (resolution >= lo && resolution <= hi) return {};
    return "shadow.resolution: " + std::to_string(resolution) + " is outside what this GPU allows [" +
           std::to_string(lo) + ", " + std::to_string(hi) + "] (GL_MAX_TEXTURE_SIZE " + std::to_string(maxTextureSize) +
           "); " + kept;
}

}  // namespace shadowlab
