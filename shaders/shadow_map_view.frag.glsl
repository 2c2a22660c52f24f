#version 450 core
// The shadow map as a picture: stored depth (or a spot light's linear depth) stretched over uRange to black..white,
// texels no caster wrote (depth 1) in blue, a checkerboard outside the map, and a texel grid when zoomed in. Or, with
// uChannel k > 0, the k-th stored moment of a moments technique's layer stretched over uRange (no "no caster" there).
layout(binding = 0) uniform sampler2D uDepth;  // read with a sampler without comparison
layout(binding = 1) uniform sampler2D uMoments;  // the view's moments layer (uChannel > 0)
uniform int uChannel;      // 0: depth; 1..4: that moment

uniform vec2 uUvMin;       // map uv at the view's bottom-left corner
uniform vec2 uUvMax;       // ... and top-right
uniform vec2 uViewSize;    // pixels
uniform vec2 uRange;       // shown value at black, at white
uniform bool uLinearize;   // perspective depth -> linear between near (0) and far (1)
uniform vec2 uNearFar;
uniform bool uReversedZ;   // the map stores near 1, far 0: shown as 1 - stored (near dark in both conventions)
uniform float uGridTexelPixels;  // view pixels per texel when the grid is on, else 0

layout(location = 0) out vec4 outColor;

const vec3 kNoCaster = vec3(0.22, 0.34, 0.62);
const vec3 kGrid = vec3(0.95, 0.55, 0.10);

float linearDepth(float stored) {
    float n = uNearFar.x, f = uNearFar.y;
    float zNdc = stored * 2.0 - 1.0;
    float viewDepth = 2.0 * n * f / (f + n - zNdc * (f - n));
    return (viewDepth - n) / (f - n);
}

void main() {
    vec2 uv = mix(uUvMin, uUvMax, gl_FragCoord.xy / uViewSize);
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) {
        ivec2 check = ivec2(gl_FragCoord.xy) / 8;
        outColor = vec4(vec3(((check.x + check.y) & 1) == 0 ? 0.10 : 0.14), 1.0);
        return;
    }
    ivec2 size = uChannel > 0 ? textureSize(uMoments, 0) : textureSize(uDepth, 0);
    vec2 texelPos = uv * vec2(size);
    vec3 color;
    float stored = uChannel > 0 ? 0.0 : texelFetch(uDepth, min(ivec2(texelPos), size - 1), 0).r;
    if (uReversedZ) stored = 1.0 - stored;
    if (uChannel > 0) {
        float moment = texelFetch(uMoments, min(ivec2(texelPos), size - 1), 0)[uChannel - 1];
        color = vec3(clamp((moment - uRange.x) / max(uRange.y - uRange.x, 1e-12), 0.0, 1.0));
    } else if (stored >= 1.0) {
        color = kNoCaster;
    } else {
        float shown = uLinearize ? linearDepth(stored) : stored;
        color = vec3(clamp((shown - uRange.x) / max(uRange.y - uRange.x, 1e-12), 0.0, 1.0));
    }
    if (uGridTexelPixels > 0.0) {
        vec2 f = fract(texelPos);
        vec2 edgePixels = min(f, 1.0 - f) * uGridTexelPixels;
        if (min(edgePixels.x, edgePixels.y) < 0.5) color = mix(color, kGrid, 0.7);
    }
    outColor = vec4(color, 1.0);
}
