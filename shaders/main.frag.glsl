#version 450 core
// Main pass: for each light, projects the pixel into that light's shadow view and compares depths. The renderer
// prepends #defines (renderer/shading/shader_variants.cpp):
//   light set  DIR_LIGHTS, DIR_CASTERS, SPOT_LIGHTS, SPOT_CASTERS, POINT_LIGHTS, POINT_CASTERS: how many lights of
//              each kind, casters first (uLights holds them in that order: directional, spot, point)
//   maps       MAP_ARRAYS_2D (sampler2DArrayShadow, directional and spot views), MAP_ARRAYS_CUBE
//              (samplerCubeArrayShadow, point lights: per-face perspective depth)
//   filter     FILTER_TAPS and FILTER_GRID_RADIUS or FILTER_TAP_OFFSETS (texels; scaled by uFilterScale): the filter
//              technique's taps
//              (renderer/shading/filter_taps.cpp, shared with the pixel probe)
//   view       VIEW_LIT | VIEW_SHADOW | VIEW_LIGHT_DEPTH; NORMAL_OFFSET, ALPHA_MASK (+ BASE_COLOR_TEXTURE)
//   RECEIVER_PLANE  some directional / spot caster uses receiver-plane depth bias (its LightData flag says which);
//              with FILTER_NEAREST (taps that read one texel) the plane is taken at the texel's centre
// Only the lights, kinds and features a frame uses are compiled in; loop counts are compile-time constants.
layout(location = 0) in vec3 vWorldPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) in vec2 vUv;
layout(location = 0) out vec4 outColor;

#define LIGHT_COUNT (DIR_LIGHTS + SPOT_LIGHTS + POINT_LIGHTS)
#define SPOT_BEGIN DIR_LIGHTS
#define POINT_BEGIN (DIR_LIGHTS + SPOT_LIGHTS)

struct LightData {
    mat4 viewProjection;  // directional / spot: render-origin-relative world -> light clip
    vec4 position;        // xyz: spot / point position (render-origin-relative); w: range, 0 = no limit
    vec4 direction;       // xyz: unit direction the light travels; w: cos(half cone) (spot)
    vec4 radiance;        // rgb: colour; w: intensity
    vec4 shadow;          // x: map array, y: layer (2D) or cube index, z: 1 / resolution, w: normal offset (texels)
    vec4 depth;           // x: near, y: far, z: texel world size (directional) or per unit of depth (spot, point),
                          // w: flags: 1 = reversed-Z (the map stores near 1, far 0; its sampler compares GEQUAL),
                          //    2 = receiver-plane depth bias
};
#if LIGHT_COUNT > 0
layout(std140, binding = 0) uniform Lights { LightData uLights[LIGHT_COUNT]; };
#endif
#if MAP_ARRAYS_2D > 0
uniform sampler2DArrayShadow uMaps2D[MAP_ARRAYS_2D];
#endif
#if MAP_ARRAYS_CUBE > 0
uniform samplerCubeArrayShadow uMapsCube[MAP_ARRAYS_CUBE];
#endif

uniform vec3 uCameraPosition;  // render-origin-relative
uniform vec3 uBaseColor;
uniform float uAmbient;
uniform float uFilterScale;    // tap offsets are multiplied by it (Poisson: the radius; grids: 1)
#ifdef ALPHA_MASK
uniform float uAlphaFactor;
uniform float uAlphaCutoff;
#ifdef BASE_COLOR_TEXTURE
uniform sampler2D uBaseColorTexture;
#endif
#endif

// The filter's taps: a square grid (FILTER_GRID_RADIUS: offsets -R..R, row by row, as loops a compiler unrolls) or
// a list (FILTER_TAP_OFFSETS). Large constant arrays are slow on some drivers (llvmpipe: 81 taps 1.7x).
#ifdef FILTER_GRID_RADIUS
#define FOR_EACH_TAP for (int ty = -FILTER_GRID_RADIUS; ty <= FILTER_GRID_RADIUS; ++ty) \
                     for (int tx = -FILTER_GRID_RADIUS; tx <= FILTER_GRID_RADIUS; ++tx)
#define TAP_OFFSET vec2(tx, ty)
#else
const vec2 TAP_OFFSETS[FILTER_TAPS] = vec2[](FILTER_TAP_OFFSETS);
#define FOR_EACH_TAP for (int ti = 0; ti < FILTER_TAPS; ++ti)
#define TAP_OFFSET TAP_OFFSETS[ti]
#endif

// Texture coordinates and window depth in the view's depth convention: GL's [-1, 1] clip depth, or reversed-Z's
// zero-to-one depth (near 1, far 0). The CPU's copy is LightSpace::textureOf.
bool reversedZ(LightData L) { return (int(L.depth.w) & 1) != 0; }

vec3 toLightTexture(LightData L, vec3 worldPosition) {
    vec4 clip = L.viewProjection * vec4(worldPosition, 1.0);
    vec3 ndc = clip.xyz / clip.w;
    return vec3(ndc.xy * 0.5 + 0.5, reversedZ(L) ? ndc.z : ndc.z * 0.5 + 0.5);
}

// Receivers beyond the far plane compare as if on it (far = 1, or 0 reversed).
float clampToFar(LightData L, float depth) { return reversedZ(L) ? max(depth, 0.0) : min(depth, 1.0); }

// glTF's range window (KHR_lights_punctual's recommended falloff, without the inverse square): 1 with no range.
float rangeWindow(float distance, float range) {
    if (range <= 0.0) return 1.0;
    float r = distance / range;
    return clamp(1.0 - r * r * r * r, 0.0, 1.0) * clamp(1.0 - r * r * r * r, 0.0, 1.0);
}

#ifdef RECEIVER_PLANE
// Screen-space derivatives of the surface position, taken in main() where control flow is uniform (a light's cone
// test is not): the receiver's plane for every light.
vec3 gPositionDx, gPositionDy;

// A plane steeper than this many texel-world-sizes of depth along the light per texel across is clamped (grazing
// receivers, silhouettes): the tilt then stops growing and the slope bias covers the rest.
const float kReceiverPlaneMaxSlope = 8.0;

// Receiver-plane depth bias (Isidoro, GDC 2006): the receiver's depth change per texel along the map's u and v. The
// pixel's steps in x and y, taken into the map, give the Jacobian d(u,v)/d(x,y) and d(depth)/d(x,y); its inverse
// gives d(depth)/d(u,v). 0 when the light does not use it or the Jacobian is (near) singular (an edge-on receiver).
// `ray`: the unit direction light travels at the lookup; `texelWorld`: a texel's world size there.
vec2 receiverPlaneSlope(LightData L, vec3 lookup, vec3 lightTex, vec3 ray, float texelWorld) {
    if ((int(L.depth.w) & 2) == 0) return vec2(0.0);
    float texels = 1.0 / L.shadow.z;
    vec3 dx = toLightTexture(L, lookup + gPositionDx) - lightTex;
    vec3 dy = toLightTexture(L, lookup + gPositionDy) - lightTex;
    dx.xy *= texels;
    dy.xy *= texels;
    float det = dx.x * dy.y - dx.y * dy.x;
    if (!(abs(det) > 1e-3 * length(dx.xy) * length(dy.xy))) return vec2(0.0);
    vec2 slope = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
    float limit = kReceiverPlaneMaxSlope * abs(toLightTexture(L, lookup + ray * texelWorld).z - lightTex.z);
    float length2 = dot(slope, slope);
    return length2 > limit * limit ? slope * (limit * inversesqrt(length2)) : slope;
}
#endif

// Map arrays are read with constant indices only. Mesa 22.3's LLVM 15 (llvmpipe: CI and every machine without a GPU)
// crashed in EarlyCSE compiling a sampler array indexed by a uniform-block value (uMaps2D[int(L.shadow.x)]) beside a
// cube-map array; a loop over the arrays that the compiler unrolls gives each texture() a constant index instead.
#if MAP_ARRAYS_2D > 0
float sampleMap2D(int map, vec4 coord) {
#if MAP_ARRAYS_2D == 1
    return texture(uMaps2D[0], coord);  // one array: no selection at all (a dynamic one is 3x slower on llvmpipe)
#else
    float result = 1.0;
    for (int k = 0; k < MAP_ARRAYS_2D; ++k)
        if (k == map) result = texture(uMaps2D[k], coord);
    return result;
#endif
}
#endif
#if MAP_ARRAYS_CUBE > 0
float sampleMapCube(int map, vec4 coord, float ref) {
#if MAP_ARRAYS_CUBE == 1
    return texture(uMapsCube[0], coord, ref);
#else
    float result = 1.0;
    for (int k = 0; k < MAP_ARRAYS_CUBE; ++k)
        if (k == map) result = texture(uMapsCube[k], coord, ref);
    return result;
#endif
}
#endif

#if MAP_ARRAYS_2D > 0
// Fraction of light reaching the point through a 2D view, 1 = lit. `ray` and `texelWorld` (the direction light
// travels and a texel's world size at the lookup) bound the receiver plane's tilt.
float shadow2D(LightData L, vec3 lookup, vec3 ray, float texelWorld) {
    vec3 lightTex = toLightTexture(L, lookup);
    float ref = clampToFar(L, lightTex.z);
#ifdef RECEIVER_PLANE
    vec2 plane = receiverPlaneSlope(L, lookup, lightTex, ray, texelWorld);
#endif
    int map = int(L.shadow.x);
    // A lookup inside the map keeps its taps inside it (half a texel from the edge: a bilinear tap's footprint too),
    // so a kernel near the edge reads the map's own border texels, not the address mode's "outside" (HARD_CASES 6).
    // The pixel probe mirrors this (probe/pixel_probe.cpp).
    bool inside = all(greaterThanEqual(lightTex.xy, vec2(0.0))) && all(lessThanEqual(lightTex.xy, vec2(1.0)));
    vec2 lo = inside ? vec2(0.5 * L.shadow.z) : vec2(-1e30), hi = inside ? vec2(1.0 - 0.5 * L.shadow.z) : vec2(1e30);
    float sum = 0.0;
    FOR_EACH_TAP {
        vec2 tapTex = clamp(lightTex.xy + TAP_OFFSET * uFilterScale * L.shadow.z, lo, hi);
#ifdef RECEIVER_PLANE
        vec2 offset = (tapTex - lightTex.xy) / L.shadow.z;  // texels, to the tap actually read (after the clamp)
#ifdef FILTER_NEAREST
        // A nearest tap reads one texel, whose stored depth is its caster's at the texel's centre: the plane there.
        vec2 lookupTexels = lightTex.xy / L.shadow.z;
        vec2 toCentre = floor(lookupTexels + offset) + 0.5 - lookupTexels;
        float tapRef = clampToFar(L, lightTex.z + dot(plane, toCentre));
#else
        float tapRef = clampToFar(L, lightTex.z + dot(plane, offset));  // the receiver's plane at the tap
#endif
#else
        float tapRef = ref;
#endif
        sum += sampleMap2D(map, vec4(tapTex, L.shadow.y, tapRef));
    }
    return sum / float(FILTER_TAPS);
}
#endif

#if MAP_ARRAYS_CUBE > 0
// The stored value of a cube face is that face's perspective depth, so the reference is the receiver's depth in the
// face the tap's direction selects: its distance along that face's axis, through the same near/far mapping.
float faceDepth(vec3 fromLight, vec3 tapDirection, LightData L) {
    vec3 a = abs(tapDirection);
    vec3 axis = a.x >= a.y && a.x >= a.z ? vec3(sign(tapDirection.x), 0.0, 0.0)
              : a.y >= a.z                ? vec3(0.0, sign(tapDirection.y), 0.0)
                                          : vec3(0.0, 0.0, sign(tapDirection.z));
    float near = L.depth.x, far = L.depth.y;
    float z = max(dot(fromLight, axis), near);
    if (reversedZ(L)) return near * (far - z) / (z * (far - near));  // zero-to-one, near 1, far 0
    return ((far + near) / (far - near) - 2.0 * far * near / ((far - near) * z)) * 0.5 + 0.5;
}

float shadowCube(LightData L, vec3 lookup) {
    vec3 v = lookup - L.position.xyz;
    vec3 a = abs(v);
    float major = max(a.x, max(a.y, a.z));
    // The face's two tangent axes: taps move across the face by texels (2 / resolution at unit distance).
    vec3 s = a.x >= a.y && a.x >= a.z ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 t = a.y >= a.x && a.y >= a.z ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
    float texelAtMajor = 2.0 * L.shadow.z * major;
    int map = int(L.shadow.x);
    float sum = 0.0;
    FOR_EACH_TAP {
        vec2 o = TAP_OFFSET * uFilterScale * texelAtMajor;
        vec3 d = v + o.x * s + o.y * t;
        float ref = clampToFar(L, faceDepth(v, d, L));
        sum += sampleMapCube(map, vec4(d, L.shadow.y), ref);
    }
    return sum / float(FILTER_TAPS);
}
#endif

// What the lights add up to at this pixel.
struct Shading {
    vec3 n;          // unit normal, facing the viewer's side
    vec3 v;          // unit vector to the camera
    vec3 lambert;    // (1 - ambient) x N.L x light, summed over lights
    vec3 specular;
    float shadowSum; // VIEW_SHADOW: the mean shadow factor of the lights that reach the pixel
    float reaching;
};

void addLight(inout Shading s, LightData L, vec3 l, float shadow, float attenuation) {
    s.shadowSum += shadow;
    s.reaching += 1.0;
    float nDotL = max(dot(s.n, l), 0.0);
    vec3 h = normalize(l + s.v);
    float highlight = nDotL > 0.0 ? pow(max(dot(s.n, h), 0.0), 48.0) * 0.25 : 0.0;
    float direct = L.radiance.w * shadow * attenuation;
    s.lambert += (1.0 - uAmbient) * nDotL * direct * L.radiance.rgb;
    s.specular += highlight * direct * L.radiance.rgb;
}

// The lookup moved along the normal by a fixed number of texels' world size (Holbert's normal offset).
vec3 offsetLookup(Shading s, LightData L, float texelWorld) {
#ifdef NORMAL_OFFSET
    return vWorldPosition + s.n * (L.shadow.w * texelWorld);
#else
    return vWorldPosition;
#endif
}

// One function per kind; `casts` is a constant at every call, so no runtime branch decides whether to take taps.
void directionalLight(inout Shading s, LightData L, const bool casts) {
    float shadow = 1.0;
#if MAP_ARRAYS_2D > 0
    if (casts) shadow = shadow2D(L, offsetLookup(s, L, L.depth.z), L.direction.xyz, L.depth.z);
#endif
    addLight(s, L, -L.direction.xyz, shadow, 1.0);
}

void spotLight(inout Shading s, LightData L, const bool casts) {
    vec3 toLight = L.position.xyz - vWorldPosition;
    float lightDistance = length(toLight);
    vec3 l = toLight / max(lightDistance, 1e-20);
    float attenuation = rangeWindow(lightDistance, L.position.w);
    if (dot(-l, L.direction.xyz) < L.direction.w || attenuation <= 0.0) {  // outside the cone or the range: no taps
        return;
    }
    float shadow = 1.0;
#if MAP_ARRAYS_2D > 0
    if (casts) {
        float texelWorld = L.depth.z * dot(vWorldPosition - L.position.xyz, L.direction.xyz);
        shadow = shadow2D(L, offsetLookup(s, L, texelWorld), -l, texelWorld);
    }
#endif
    addLight(s, L, l, shadow, attenuation);
}

void pointLight(inout Shading s, LightData L, const bool casts) {
    vec3 toLight = L.position.xyz - vWorldPosition;
    float lightDistance = length(toLight);
    vec3 l = toLight / max(lightDistance, 1e-20);
    float attenuation = rangeWindow(lightDistance, L.position.w);
    if (attenuation <= 0.0) return;  // beyond its range: no taps
    float shadow = 1.0;
#if MAP_ARRAYS_CUBE > 0
    vec3 a = abs(vWorldPosition - L.position.xyz);
    if (casts) shadow = shadowCube(L, offsetLookup(s, L, L.depth.z * max(a.x, max(a.y, a.z))));
#endif
    addLight(s, L, l, shadow, attenuation);
}

void main() {
#ifdef ALPHA_MASK
    float alpha = uAlphaFactor;
#ifdef BASE_COLOR_TEXTURE
    alpha *= texture(uBaseColorTexture, vUv).a;
#endif
    if (alpha < uAlphaCutoff) discard;
#endif
#ifdef RECEIVER_PLANE
    gPositionDx = dFdx(vWorldPosition);
    gPositionDy = dFdy(vWorldPosition);
#endif
    Shading s;
    s.n = normalize(vNormal);
    if (!gl_FrontFacing) s.n = -s.n;  // two-sided lighting: broken windings and double-sided materials shade right
    s.v = normalize(uCameraPosition - vWorldPosition);
    s.lambert = vec3(0.0);
    s.specular = vec3(0.0);
    s.shadowSum = 0.0;
    s.reaching = 0.0;

    // uLights: directional, spot, point; casters first within each kind. Loop bounds are compile-time constants.
#if DIR_CASTERS > 0
    for (int i = 0; i < DIR_CASTERS; ++i) directionalLight(s, uLights[i], true);
#endif
#if DIR_LIGHTS > DIR_CASTERS
    for (int i = DIR_CASTERS; i < DIR_LIGHTS; ++i) directionalLight(s, uLights[i], false);
#endif
#if SPOT_CASTERS > 0
    for (int i = SPOT_BEGIN; i < SPOT_BEGIN + SPOT_CASTERS; ++i) spotLight(s, uLights[i], true);
#endif
#if SPOT_LIGHTS > SPOT_CASTERS
    for (int i = SPOT_BEGIN + SPOT_CASTERS; i < POINT_BEGIN; ++i) spotLight(s, uLights[i], false);
#endif
#if POINT_CASTERS > 0
    for (int i = POINT_BEGIN; i < POINT_BEGIN + POINT_CASTERS; ++i) pointLight(s, uLights[i], true);
#endif
#if POINT_LIGHTS > POINT_CASTERS
    for (int i = POINT_BEGIN + POINT_CASTERS; i < LIGHT_COUNT; ++i) pointLight(s, uLights[i], false);
#endif

#if defined(VIEW_SHADOW)
    outColor = vec4(vec3(s.reaching > 0.0 ? s.shadowSum / s.reaching : 0.0), 1.0);
#elif defined(VIEW_LIGHT_DEPTH)
    // The first light's depth: directional as stored, spot and point as linear distance (not all white).
    float depth = 0.0;
#if LIGHT_COUNT > 0
    LightData first = uLights[0];
    if (DIR_LIGHTS > 0) {
        depth = toLightTexture(first, vWorldPosition).z;
        if (reversedZ(first)) depth = 1.0 - depth;  // near dark in both conventions
    } else {
        vec3 fromLight = vWorldPosition - first.position.xyz;
        float viewDepth = SPOT_LIGHTS > 0 ? dot(fromLight, first.direction.xyz) : length(fromLight);
        depth = (viewDepth - first.depth.x) / (first.depth.y - first.depth.x);
    }
#endif
    outColor = vec4(vec3(clamp(depth, 0.0, 1.0)), 1.0);
#else
    vec3 color = uBaseColor * (uAmbient + s.lambert) + s.specular;
    outColor = vec4(pow(color, vec3(1.0 / 2.2)), 1.0);
#endif
}
