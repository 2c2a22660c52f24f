#pragma once
// A shadow filter technique, in one place: the map storage it reads (depth, or 2 / 4 moments), the passes it needs
// after the shadow pass (moments and blur), its GLSL lookup file, its CPU mirror (the pixel probe recomputes S with
// it), its keys (the editor shows them only while it is chosen; sweep and tuner vary them through the key table) and
// how far from the lookup it reads (the accuracy metrics' k). One file per technique under filters/; adding one is
// that file, its GLSL file, a FilterKind value and a line in filter_technique.cpp's table (the filter.kind key's
// names come from that table), and its keys' fields.
#include "settings/settings.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/ext/vector_uint2.hpp>

#include <functional>
#include <string>
#include <vector>

namespace shadowlab {

// A moments technique: its storage, its encoding (the moments pass) and its lookup, in GLSL (its own file under
// shaders/shadow/techniques/: encodeMoments, momentShadow) and mirrored here in float for the probe.
struct MomentTechnique {
    int channels = 2;          // 2 (RG) or 4 (RGBA)
    bool unorm16 = false;      // 16-bit storage is unsigned normalized (MSM's optimized quantization), else half float
    const char* glslFile;      // "shadow/techniques/vsm.glsl"
    // uTechnique, the one vec4 its GLSL reads (exponents, min variance, bleeding reduction, moment bias...), from the
    // settings after the technique's clamps.
    glm::vec4 (*uniforms)(const FilterSettings& filter);
    // The moments of one texel's depth z (in [0, 1], near 0: reversed-Z maps are flipped first), as stored.
    glm::vec4 (*encode)(float z, const glm::vec4& uniforms);
    // The shadow factor of a receiver at depth z given the filtered stored moments.
    float (*shadow)(const glm::vec4& moments, float z, const glm::vec4& uniforms);
    // The lookup in words (mean, variance, the bound...) for the probe.
    std::string (*explain)(const glm::vec4& moments, float z, const glm::vec4& uniforms);
    // What the settings ask for that the storage cannot hold, each naming its key and what is used instead ("" none).
    std::vector<std::string> (*clamps)(const FilterSettings& filter) = nullptr;
};

// One key of a technique's own trade-off, which `tune` searches (accuracy/bias_tuner.h): `steps` candidates from
// `low` to `high` (both included), spaced by a constant ratio when `geometric` (a variance floor spans decades), else
// evenly. `limit` (optional) lowers `high` to what these settings can use (EVSM: the exponent the storage holds), so
// the tuner never proposes a value the renderer would clamp. A light's key is written "lights.#.size": the tuner
// works on one light, #.
struct TradeOffRange {
    const char* key;
    double low = 0.0;
    double high = 0.0;
    int steps = 2;
    bool geometric = false;
    double (*limit)(const Settings& settings) = nullptr;
};

// The candidates of a trade-off key for these settings, low to high, each within the key's own range.
std::vector<double> tradeOffCandidates(const TradeOffRange& range, const Settings& settings);
// The largest value the tuner may propose for it with these settings (high, or its limit when lower).
double tradeOffTop(const TradeOffRange& range, const Settings& settings);

// One lookup of a technique with a lookup of its own, as the GPU's file computes it (in float): what its CPU mirror
// reads. Inside the map only (beyond it every technique makes one comparison, the address mode's).
struct OwnLookupInput {
    glm::vec2 tex{0.0f};       // the lookup's texture coordinate
    float receiver = 0.0f;     // its window depth, clamped to the far plane
    glm::vec2 plane{0.0f};     // receiver-plane slope: depth per texel (0 without)
    int resolution = 0;
    bool reversedZ = false;
    bool perspective = false;  // spot view or cube face
    float nearPlane = 0.0f, farPlane = 0.0f;
    float distance = 0.0f;       // perspective: the receiver's distance along the view's axis (0: from its depth)
    float depthPerWorld = 0.0f;  // orthographic: window depth per world unit along the light
    float texelWorld = 0.0f;     // orthographic: a texel's world size; perspective: per unit of distance
    float lightSize = 0.0f;      // lightSpread(): LightData.views.z
    glm::uvec2 pixel{0u};        // gl_FragCoord's integer part (window x, y from the bottom)
    // A point light: its taps move across the lookup's cube face by direction (cube_face_frame.h) and each reads the
    // face its direction selects. `fromLight`: the lookup minus the light's position, in float as the GPU's.
    bool cube = false;
    glm::vec3 fromLight{0.0f};
    std::function<float(int face, int x, int y)> storedDepth;  // a texel's stored depth (face: -1 for a 2D view)
    double depthEps = 0.0;       // float rounding of the receiver's depth: a search comparison within it is uncertain
    double texelEps = 0.0;       // and of the lookup's texel coordinate: a search tap this near a texel's edge may
                                 // read its neighbour
};

// What the mirror found: the comparison taps it then reads (texels from the lookup, bilinear, each 1/N of S; none:
// S = 1) and its search in words.
struct OwnLookupResult {
    std::vector<glm::vec2> taps;
    std::vector<glm::vec3> directions;  // a point light: each tap's direction from the light (the GPU's float d)
    int searchTaps = 0, blockers = 0;
    float searchTexels = 0.0f;    // the blocker search's radius
    float blockerDepth = 0.0f;    // the blockers' mean stored depth
    float penumbraTexels = 0.0f;  // the estimated penumbra's width
    float radiusTexels = 0.0f;    // the filter's radius (half the penumbra, clamped)
    bool uncertain = false;       // a blocker test within depthEps: rounding may change the search's outcome
    // When uncertain: the other outcomes the GPU may reach (each with its own taps; no taps: no blocker, S = 1), and
    // whether they are all of them (only depth tests in doubt, few enough to list); if not, S may be anything.
    std::vector<OwnLookupResult> alternatives;
    bool alternativesComplete = false;
    std::string text;
};

// A technique whose lookup is all its own GLSL file (shadow2D and shadowCube: PCSS). It reads the maps' depths as
// well as comparing them: the main pass binds each depth map a second time through a plain sampler (uDepth2D,
// uDepthCube) and gives each light's size in LightData.views.z (lightSpread). Its unitTaps are the disk its file
// rotates and scales per pixel.
struct OwnLookup {
    const char* glslFile;  // "shadow/techniques/pcss.glsl", the variant's "alias:lookup"
    glm::vec4 (*uniforms)(const FilterSettings& filter);  // uTechnique
    OwnLookupResult (*mirror)(const OwnLookupInput& in, const FilterSettings& filter);
};

struct FilterTechnique {
    FilterKind kind;
    const char* name;  // the filter.kind value
    bool bilinear;     // compared through the sampler's bilinear filter (2x2 texels), else one texel per tap
    // Tap offsets in texels before scaling, in the shader's order; each carries 1/N of S.
    std::vector<glm::vec2> (*unitTaps)(const FilterSettings& filter);
    // uFilterScale: multiplies every offset (Poisson: the radius; grids: 1).
    float (*scale)(const FilterSettings& filter);
    // How many texels from the lookup the filter reads: within k of an edge acne and leak are not judged.
    double (*radiusTexels)(const FilterSettings& filter);
    // Optional: when the taps are the square grid -R..R (row by row), R; the shader then loops instead of reading a
    // constant array (much faster for large kernels on some drivers).
    int (*gridRadius)(const FilterSettings& filter) = nullptr;
    // Whether shadow.receiverPlaneBias applies: taps away from the lookup (PCF, Poisson) compare the receiver plane's
    // depth there. A single centred tap has nothing to tilt.
    bool receiverPlane = false;
    // Its keys besides filter.kind (the editor shows them only while it is chosen).
    std::vector<const char*> keys = {};
    // Set for a moments technique: the map is converted to moments and blurred after the shadow pass.
    const MomentTechnique* moments = nullptr;
    // The keys and ranges of its own trade-off (bleeding against acne, softness against error), in the order `tune`
    // searches them; empty: tune searches the depth bias only.
    std::vector<TradeOffRange> tradeOff = {};
    // Set for a technique with a lookup of its own (PCSS).
    const OwnLookup* ownLookup = nullptr;
    // Optional: what its lookup costs inside the main pass, in words (Stats and render's report beside the passes).
    std::string (*cost)(const FilterSettings& filter) = nullptr;
};

// A light's size as the lookups spread it (LightData.views.z): a directional light's width per unit of distance,
// 2 tan(angular diameter / 2); a spot or point light's diameter.
float lightSpread(const LightSettings& light);

// The table: every technique, in filter.kind's order.
const std::vector<const FilterTechnique*>& filterTechniques();
const FilterTechnique& filterTechnique(FilterKind kind);

// The moments techniques' blur width in a view's texels (filter.blurUnit world: divided by the view's texel world
// size), within [1, kMaxBlurTexels]; `clamped` says when the width asked for was beyond it.
inline constexpr double kMaxBlurTexels = 63.0;
double blurTexels(const FilterSettings& filter, double texelWorldSize, bool* clamped = nullptr);
// The box blur's weights for a width in texels: taps -R..R, the outermost pair weighted by the width's fraction
// (so the width is continuous), normalized. The moments pass (GLSL) and its CPU mirror use these numbers.
std::vector<float> blurWeights(double widthTexels);

// The largest exponent c whose warped second moment exp(2c) a moments storage holds: fp16's max 65504 (ln 11.09)
// gives 5.54, fp32's 3.4e38 (ln 88.7) 44.3, of which the usual 42 is used.
float maxWarpExponent(int momentBits);

// The techniques, one per file.
const FilterTechnique& pointFilter();
const FilterTechnique& hardware2x2Filter();
const FilterTechnique& pcfFilter();
const FilterTechnique& poissonFilter();
const FilterTechnique& vsmFilter();
const FilterTechnique& evsm2Filter();
const FilterTechnique& evsm4Filter();
const FilterTechnique& msmFilter();
const FilterTechnique& pcssFilter();

}  // namespace shadowlab
