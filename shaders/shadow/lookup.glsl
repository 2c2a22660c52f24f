// The chosen filter technique's lookup: shadow2D (directional and spot views, cascades) and shadowCube (point lights).
// Depth techniques compare taps (lookup_2d.glsl, lookup_cube.glsl); moments techniques read their filtered moments
// (moments_lookup.glsl with the technique's own file); a technique with a lookup of its own (PCSS) is that file
// alone, under a name of its own ("alias:lookup": each file is included once, where it first appears, so the
// moments branch's "alias:technique" must not be it). Only the chosen branch is compiled.
#include "shadow/light_data.glsl"
#include "shadow/view_select.glsl"
#include "shadow/cube_face_depth.glsl"
#ifdef MOMENT_TECHNIQUE
#include "shadow/moments_lookup.glsl"
#elif defined(OWN_LOOKUP)
#include "alias:lookup"
#else
#include "shadow/lookup_2d.glsl"
#include "shadow/lookup_cube.glsl"
#endif
