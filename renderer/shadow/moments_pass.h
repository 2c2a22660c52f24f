#pragma once
// The moments pass of a moments technique (VSM, EVSM, MSM; shading/filters/): after the shadow pass, each view whose
// depth map changed (or whose moments settings changed) is converted to the technique's moments and blurred by a
// separable box of filter.blurWidth, into moments storage of its own, one array per map group (2D layers, cascades,
// point lights' cube faces: blurred across their edges, so a face whose neighbour changed is made again); with
// filter.momentMips its mip levels follow. Perspective views (spot, cube faces)
// store moments of their linear depth (shaders/shadow/linear_depth.glsl). Nothing runs for a depth technique, and nothing for views whose moments are current.
// Compute shaders: shaders/moments.comp.glsl, moments_cube_blur.comp.glsl; their CPU mirror: shading/filters/moments_mirror.h.
#include "frame/frame_stats.h"
#include "gl/gl_objects.h"
#include "settings/settings.h"
#include "shading/filters/moment_filter.h"  // momentLevels
#include "shadow/shadow_map.h"
#include "timing/pass_timer.h"
#include "views/map_group.h"
#include "views/shadow_view.h"

#include <glm/vec4.hpp>

#include <map>
#include <string>
#include <vector>

namespace shadowlab {

struct FilterTechnique;

// Where a view's moments are stored: its layer of a group's moments array (the map viewer shows them).
struct MomentsLayer {
    GLuint texture = 0;  // GL_TEXTURE_2D_ARRAY, or GL_TEXTURE_CUBE_MAP_ARRAY (layer = 6 x cube + face)
    GLenum format = 0;   // its GL internal format
    int layer = 0;
    int resolution = 0;
    std::uint64_t generation = 0;  // changes with the allocation
};

// A view the main pass reads this frame: where its depth is and whether the shadow pass just wrote it.
struct MomentsView {
    ShadowViewId id;
    std::string name;        // "light 0 cascade:1", for the pass's reason
    MapGroup group;
    int layer = 0;           // its layer in the group's array (a cube face: 6 x cube + face)
    bool rendered = false;   // the shadow pass drew (or cleared) it this frame
    double texelWorldSize = 0.0;  // for filter.blurUnit world
    bool perspective = false;     // a spot view or cube face: moments of linear depth between its near and far
    float nearPlane = 0.0f, farPlane = 1.0f;
};

struct MomentsPassResult {
    PassStats moments;  // the conversion
    PassStats blur;
    PassStats mips;  // filter.momentMips: the mip levels of the views converted
    std::vector<std::string> warnings;  // clamps (EVSM exponents, a blur beyond its widest)
};

class MomentsPass {
public:
    // Needs a current GL 4.5 context; programs are built on first use.
    MomentsPass();
    ~MomentsPass();

    // Brings every view's moments up to date for `filter` (a moments technique). `arrays`: the depth arrays by group.
    MomentsPassResult run(const FilterSettings& filter, const std::map<MapGroup, ShadowMapArray>& arrays,
                          const std::vector<MomentsView>& views, PassTimer& timer);
    // Frees the storage (a depth technique is chosen).
    void release();

    // The moments array of a group (2D array or cube-map array), 0 when none.
    GLuint texture(const MapGroup& group) const;
    // A group's storage with `layer` filled in (texture 0 when none).
    MomentsLayer layer(const MapGroup& group, int layer) const;
    // The sampler moments are read through: bilinear, the address mode's wrap, the border depth's moments outside.
    GLuint sampler() const { return sampler_.id(); }
    void configureSampler(const FilterSettings& filter, const SamplerSettings& sampler);

    // Texels [x0, x0+w) x [y0, y0+h) of a view's moments as stored (row 0 = bottom), read back from the GPU.
    // `level`: a mip level (filter.momentMips), its texels.
    std::vector<glm::vec4> read(const MapGroup& group, int layer, int x0, int y0, int w, int h, int level = 0) const;
    // How many views the last run converted (tests: nothing runs when nothing changed).
    int lastConverted() const { return lastConverted_; }

private:
    struct Storage;
    struct Inputs {
        FilterKind kind;
        int bits;
        double blurTexels;
        glm::vec4 uniforms;
        std::uint64_t storage;  // the moments array's allocation
        int layer;
        bool mips;
        bool perspective;
        float nearPlane, farPlane;
        bool operator==(const Inputs&) const = default;
    };
    struct Work {
        const MomentsView* view;
        double blurTexels;
        const char* why;  // for the pass's reason
    };
    void blurViews(const std::vector<Work>& work, GLenum format, const FilterSettings& filter,
                   const std::string& reasons, PassTimer& timer, MomentsPassResult& result);
    // A point light's cubes: each face blurred across its edges (shaders/moments_cube_blur.comp.glsl).
    void blurCubes(const std::vector<Work>& work, GLenum format);
    void mipViews(const std::vector<Work>& work, GLenum format, const FilterSettings& filter,
                  const std::string& reasons, PassTimer& timer, MomentsPassResult& result);
    std::map<MapGroup, Storage> storage_;
    std::map<ShadowViewId, Inputs> current_;  // what each view's moments were computed from
    std::map<std::pair<FilterKind, int>, gl::Program> convertPrograms_;
    std::map<int, gl::Program> blurPrograms_;  // by GL internal format
    std::map<int, gl::Program> mipsPrograms_;  // by GL internal format
    gl::Texture temp_;  // one layer's horizontal blur
    int tempResolution_ = 0;
    GLenum tempFormat_ = 0;
    std::map<std::pair<int, int>, gl::Program> cubeBlurPrograms_;  // by GL internal format and pass (1, 2)
    gl::Texture tempCube_;  // a cube's first blur pass: two cubes (along each face's s, and along its t)
    int tempCubeResolution_ = 0;
    GLenum tempCubeFormat_ = 0;
    gl::Sampler nearest_;  // the cube blur's reads
    gl::Sampler sampler_;
    int lastConverted_ = 0;
};

// The storage's GL internal format for a technique at filter.momentBits.
GLenum momentInternalFormat(const FilterTechnique& technique, int momentBits);

}  // namespace shadowlab
