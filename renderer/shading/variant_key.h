#pragma once
// The main pass's shader variant key: the #defines a frame needs. Only the features the scene and settings use are
// compiled in: the light set (how many directional, spot and point lights, how many of each cast), the map arrays,
// the filter technique's taps, the view (no runtime branches on them). No GL: the key is derived from the key table
// (the fields tagged kInvalidatesVariant), so unit tests check that exactly those keys reach it.
#include "settings/settings.h"

#include <compare>
#include <string>
#include <vector>

namespace shadowlab {

// The lights a variant is built for, counted per kind; casters come first within each kind.
struct LightSetKey {
    int directional = 0, directionalCasters = 0;
    int spot = 0, spotCasters = 0;
    int point = 0, pointCasters = 0;
    int mapArrays2D = 0;    // sampler2DArrayShadow groups (directional and spot views)
    int mapArraysCube = 0;  // samplerCubeArrayShadow groups (point lights)
    int cascades = 0;       // every cascaded light's cascades together (the Cascades block's length)
    int lights() const { return directional + spot + point; }
    auto operator<=>(const LightSetKey&) const = default;
};

struct MainVariantKey {
    FilterKind filter = FilterKind::Pcf;
    int kernel = 3;  // FilterKind::Pcf only (other filters' taps do not depend on it)
    ViewMode view = ViewMode::Lit;
    LightSetKey lights;
    bool normalOffset = false;  // some casting light offsets its lookup
    bool receiverPlane = false; // some casting directional / spot light uses receiver-plane bias with a filter that
                                // supports it (RECEIVER_PLANE; each light's flag picks it at run time)
    bool momentMips = false;    // a moments technique reads its moments' mip levels (MOMENT_MIPS: filter.momentMips)
    // Per draw, from its material (not settings):
    bool alphaMask = false;
    bool alphaTexture = false;

    std::vector<std::string> defines() const;
    std::string name() const;  // the defines joined (tap offsets shortened), for FrameStats and logs
    auto operator<=>(const MainVariantKey&) const = default;
};

// The settings a variant is built from: the fields the key table tags kInvalidatesVariant copied through the table
// (get, then set), every other field at its default, so no untagged key can reach the program.
Settings variantInputs(const Settings& effective);

// The frame's variant (its per-draw part, alphaMask and alphaTexture, left false) for these effective settings (the
// frame's lights, useSceneLights resolved): read from variantInputs(effective) only.
MainVariantKey mainVariantKey(const Settings& effective);

// A name as a GLSL define spells it: upper case ("vsm" -> FILTER_VSM; the export's "light0" -> LIGHT0_ constants).
std::string upperCase(std::string s);

}  // namespace shadowlab
