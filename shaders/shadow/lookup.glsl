// The chosen filter technique's lookup: shadow2D (directional and spot views, cascades) and shadowCube (point lights).
// Depth techniques compare taps (lookup_2d.glsl, lookup_cube.glsl); moments techniques read their filtered moments
// (moments_lookup.glsl with the technique's own file). Only the chosen branch is compiled.
#include "shadow/light_data.glsl"
#include "shadow/view_select.glsl"
#include "shadow/cube_face_depth.glsl"
#ifdef MOMENT_TECHNIQUE
#include "shadow/moments_lookup.glsl"
#else
#include "shadow/lookup_2d.glsl"
#include "shadow/lookup_cube.glsl"
#endif
