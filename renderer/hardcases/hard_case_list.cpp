#include "hardcases/cases.h"

namespace shadowlab::hardcases {

const std::vector<HardCase>& hardCaseList() {
    static const std::vector<HardCase> list = {
        {1, "light direction parallel to the lookAt up vector (pole sweep)", runPoleSweep},
        {2, "grazing light and the slope-scaled bias blowing up (clamp)", runGrazingClamp},
        {3, "large world coordinates", runLargeWorld},
        {4, "small near / large far, D16 / D24 / D32F (precision per format)", runPrecisionPerFormat},
        {5, "reversed-Z (every other case in both conventions)", runReversedZ},
        {6, "border texels, address modes and PCF crossing the border", runBorderTexels},
        {7, "shimmering under sub-texel camera or light motion", runShimmer},
        {8, "spot light perspective aliasing", runSpotAliasing},
        {9, "point light cube seams", runCubeSeams},
        {10, "Peter Panning of thin casters", runThinCasters},
        {11, "alpha-tested casters (cutoff 0.25 / 0.5 / 0.75)", runAlphaCutoffs},
        {12, "casters behind the light's near plane (pancaking)", runPancaking},
        {13, "mirrored instances and winding", runMirroredInstances},
        {14, "degenerate light parameters", runDegenerateLight},
        {15, "degenerate and non-power-of-two resolutions", runDegenerateResolution},
        {16, "degenerate geometry", runDegenerateGeometry},
        {17, "scale extremes and texel-relative biases", runScaleExtremes},
        {18, "cascade splits at extreme near / far", runCascadeSplits},
        {19, "cascade seams (texel jump per split, blend band)", runCascadeSeams},
        {20, "stale depth bounds and fast camera motion", runStaleDepthBounds},
    };
    return list;
}

}  // namespace shadowlab::hardcases
