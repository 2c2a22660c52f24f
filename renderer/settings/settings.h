#pragma once
// Every tunable of a frame, as a plain value type (no GL handles). The editor edits one, a preset is one as JSON,
// the CLI builds one from a preset plus --set overrides. Keys and ranges live in settings_fields.h.
// Schema version 2: a list of lights, each with its own shadow map and projection; sampler, filter, camera, view and
// ambient are global.
#include <glm/ext/vector_double3.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace shadowlab {

enum class DepthFormat { D16, D24, D32F };
enum class CullMode { Back, Front, None };
enum class LightType { Directional, Spot, Point };
enum class AddressMode { Wrap, ClampToEdge, ClampToBorder };
// Filter techniques (shading/filters/: one file each). The first four compare depths; the others filter moments.
enum class FilterKind { Point, Hardware2x2, Pcf, Poisson, Vsm, Evsm2, Evsm4, Msm, Pcss };
// Where a moments technique's blur width is given: in each view's texels, or in world units (the same in every
// cascade: converted by each view's texel size).
enum class BlurUnit { Texels, World };
// A light's shadow update policy (ShadowMapSettings::update).
enum class ShadowUpdate { EveryFrame, OnChange, CachedStatic, EveryNthFrame };
// What the main view shows: the lit scene, the shadow factor, the first light's depth, the cascade that holds each
// pixel (tinted over the lit scene), or shadow-map texels per screen pixel (a log colour scale).
enum class ViewMode { Lit, Shadow, LightDepth, Cascades, TexelDensity };

struct ShadowMapSettings {
    int resolution = 2048;              // square map, texels per side
    DepthFormat format = DepthFormat::D32F;
    float depthBias = 2.0f;             // D3D DepthBias: units of the format's smallest depth step
    float slopeScaledDepthBias = 1.0f;  // D3D SlopeScaledDepthBias: times the polygon's max depth slope
    float depthBiasClamp = 0.0f;        // D3D DepthBiasClamp: max |bias| in depth units; 0 = no clamp
    float normalOffset = 0.5f;          // lookup moved along the normal, in shadow-map texels (world size)
    // None: the map holds every caster, as the reference does. Back loses single-sided roofs lit from above (91 %
    // leak), front leaks at contacts (1.2-3.2 %); none is never worse than back on any scene (README, "Policies").
    CullMode cullMode = CullMode::None;
    // Reversed-Z: the map stores near = 1, far = 0 (glClipControl zero-to-one, GEQUAL compare); the bias keys keep
    // their meaning (toward the light). D32F's float steps then fall where perspective depth needs them.
    bool reversedZ = false;
    // Receiver-plane depth bias (Isidoro, GDC 2006): each PCF / Poisson tap compares the depth of the receiver's plane
    // at that tap, not the centre's, so wide kernels need no slope bias of their own. Directional and spot lights.
    // On by default: with it the default's slope 1 is clean on every built-in and ../shared scene (docs/accuracy.md).
    bool receiverPlaneBias = true;
    // When the light's views render again (docs/moving-scenes.md): every frame; on change (a key, the light space or a
    // caster in the view's volume moved); cached static (static casters rendered once into a cached depth per view,
    // moving ones drawn over a copy of it, scissored to what they cover); every Nth frame (motion waits for it).
    ShadowUpdate update = ShadowUpdate::OnChange;
    int updateInterval = 4;  // everyNthFrame's N

    bool operator==(const ShadowMapSettings&) const = default;
};

// How a directional light's views are fitted: one view around the whole scene, or cascades that follow the camera.
enum class ProjectionFit { Scene, Cascades };
// How a cascade is fitted to its slice of the camera's frustum: stable (the slice's bounding sphere, size rounded and
// origin snapped to whole texels: camera motion moves no texel edge) or tight (the slice's box in light space: more
// texels on screen, edges that crawl as the camera moves).
enum class CascadeFit { Stable, Tight };
// Where the cascades' depth range comes from: off (the camera's near plane to the shadow distance), or the nearest
// and farthest depth the camera sees, reduced on the GPU: this frame's (a depth prepass and a read-back before the
// views are planned) or the previous frame's (no stall; a frame late after a fast camera move).
enum class DepthBounds { Off, SameFrame, PreviousFrame };

struct ProjectionSettings {
    bool autoFit = true;      // fit ortho size / near / far (spot: near / far) to the scene's bounding sphere
    float orthoSize = 20.0f;  // full width of the square ortho volume, world units
    float nearPlane = 0.1f;
    float farPlane = 50.0f;
    bool depthClamp = true;   // GL_DEPTH_CLAMP in the shadow pass: casters before the near plane still cast
    // Cascades (directional lights with fit = Cascades); the scene fit ignores them.
    ProjectionFit fit = ProjectionFit::Scene;
    int cascadeCount = 4;        // 1..4
    float splitLambda = 0.75f;   // practical split scheme: 0 = uniform, 1 = logarithmic
    // Manual split distances from the camera (world units, increasing); all 0 = the practical scheme decides.
    glm::vec3 splits{0.0f};
    float shadowDistance = 0.0f; // how far from the camera shadows reach; 0 = the camera's far plane
    float blendBand = 0.1f;      // share of each cascade (0..0.5) where it fades into the next
    CascadeFit cascadeFit = CascadeFit::Stable;
    DepthBounds depthBounds = DepthBounds::Off;

    bool operator==(const ProjectionSettings&) const = default;
};

// One light: how it shines and how its shadow map is made. A directional or spot light has one shadow view, a point
// light six (cube faces).
struct LightSettings {
    LightType type = LightType::Directional;
    glm::vec3 direction{-0.4f, -1.0f, -0.3f};  // direction the light travels (need not be normalized); not point
    glm::vec3 position{4.0f, 8.0f, 4.0f};      // spot and point
    float range = 0.0f;                        // spot and point: light reaches this far (glTF's range); 0 = no limit
    float spotConeDeg = 60.0f;                 // spot full cone angle, degrees
    float intensity = 1.0f;
    glm::vec3 color{1.0f, 1.0f, 1.0f};
    bool enabled = true;       // off: the light neither shines nor casts
    bool castsShadows = true;  // off: it shines everywhere, no shadow view is rendered for it
    // Its size, for the soft reference (reference/soft_visibility.h): directional = angular diameter in degrees,
    // spot / point = radius of a disc in world units. 0 = a hard light (glTF has no size, so only a preset sets it).
    float size = 0.0f;
    ShadowMapSettings shadow;
    ProjectionSettings projection;

    bool operator==(const LightSettings&) const = default;

    // GL_DEPTH_CLAMP applies to a directional light's orthographic view only. A perspective view (spot, cube face)
    // cannot keep what lies behind the light, and with clamping on NVIDIA's driver drops triangles that cross the
    // light's plane (builtin:room on an H200 lost the pillar's shadow in the cube's +-Y faces: 9.3 % leak).
    bool depthClampApplies() const { return projection.depthClamp && type == LightType::Directional; }
};

// Enough for every sample we compare with (bgfx: 16 maps); the shader's light loop is specialised to the count used.
inline constexpr std::size_t kMaxLights = 32;

// The widest angular diameter a directional light's size may have (its cone's half angle is then 45 degrees).
inline constexpr float kMaxAngularDiameterDeg = 90.0f;

struct SamplerSettings {
    AddressMode addressMode = AddressMode::ClampToBorder;
    float borderDepth = 1.0f;  // depth returned outside the map with clamp-to-border; 1 = lit

    bool operator==(const SamplerSettings&) const = default;
};

struct FilterSettings {
    FilterKind kind = FilterKind::Pcf;
    int kernel = 3;          // NxN grid PCF: 1,3,5,7,9
    float poissonRadius = 2.0f;  // Poisson disk radius, texels
    // Moments techniques (VSM, EVSM2/4, MSM): storage precision, the blur after the moments pass, their own terms.
    int momentBits = 32;             // 16 or 32-bit float moments (MSM 16: optimized quantization in 16-bit unorm)
    float blurWidth = 5.0f;          // box blur width (1 = none), in blurUnit
    BlurUnit blurUnit = BlurUnit::Texels;
    bool momentMips = false;         // mip levels of the blurred moments, read trilinearly (distant receivers)
    float minVariance = 1e-6f;       // VSM / EVSM: variance floor (depth units squared; EVSM scales it by the warp)
    float bleedReduction = 0.2f;     // VSM / EVSM / MSM: shadow below this share of light is cut to 0, the rest rescaled
    float positiveExponent = 40.0f;  // EVSM: c+ of exp(c+ d); clamped to what momentBits hold (5.54 / 42)
    float negativeExponent = 5.0f;   // EVSM4: c- of -exp(-c- d); the same clamp
    float momentBias = 3e-5f;        // MSM: moments pulled toward a constant vector by this share
    // PCSS: the largest blocker-search and filter radii, in texels (the light's size and the depths set them below).
    float blockerSearchTexels = 16.0f;
    float penumbraMaxTexels = 16.0f;

    bool operator==(const FilterSettings&) const = default;
};

struct CameraSettings {
    bool autoFrame = true;  // the scene's viewpoint, else its vertices filling the view (position/target ignored)
    // Double: a scene 1e6 from the origin must still move when the camera moves 1 mm (a float's step there is 6 cm).
    glm::dvec3 position{8.0, 6.0, 10.0};
    glm::dvec3 target{0.0, 0.0, 0.0};
    float fovYDeg = 45.0f;
    // A camera of the scene's file (an index into Scene::cameras) replaces all of the above; -1 = the free camera.
    int sceneCamera = -1;

    bool operator==(const CameraSettings&) const = default;
};

// What casts shadows: every mesh, except those under the scene's nodes named here by path (SceneNode::path, e.g.
// "City/SkyBox"); such a node's whole subtree casts none. Both the shadow maps and the reference leave them out.
struct CasterSettings {
    std::vector<std::string> excluded;
    // Node paths forced static (kept in a cachedStatic light's cached depth even if an animation moves them: a cache
    // error the frame warns about) or dynamic (drawn every update though nothing animates them); by default a caster
    // is static when none of the playing animations moves it (scene/scene_casters.h).
    std::vector<std::string> forcedStatic;
    std::vector<std::string> forcedDynamic;

    bool operator==(const CasterSettings&) const = default;
};

// Which of the scene file's animations play and at what time (scene/scene_animation.h poses the scene from these).
struct AnimationSettings {
    std::string play = "all";  // "all", "none", an animation's name or its index in the file
    float time = 0.0f;         // seconds; outside an animation's keys its first or last pose holds

    bool operator==(const AnimationSettings&) const = default;
};

// The accuracy reference: how many rays the soft reference traces per pixel toward a light of size > 0.
struct ReferenceSettings {
    int softRays = 256;

    bool operator==(const ReferenceSettings&) const = default;
};

struct Settings {
    std::vector<LightSettings> lights = std::vector<LightSettings>(1);  // one default light
    float ambient = 0.15f;        // ambient term, unaffected by shadows
    bool useSceneLights = false;  // the scene's KHR_lights_punctual lights replace `lights` (see light_space.h)
    SamplerSettings sampler;
    FilterSettings filter;
    CameraSettings camera;
    CasterSettings casters;
    AnimationSettings animation;
    ReferenceSettings reference;
    ViewMode view = ViewMode::Lit;

    // Every problem as "key: what is wrong (allowed range)"; empty when the settings can be rendered.
    std::vector<std::string> validate() const;

    bool operator==(const Settings&) const = default;
};


}  // namespace shadowlab
