#pragma once
// Counts DESIGN.md's accuracy sets on the GPU (live accuracy): the cached reference — each pixel's exact visibility,
// what the boundary knows of its distance to the true edge, its unit conversions — is uploaded once per reference
// and light space; after each tool frame a compute pass compares the frame's S with V where the frame lies, and only
// the counts, two sums and the edge-error percentiles come back (no frame read-back, no CPU pass over the pixels).
// The thresholds are the CPU metrics' own (accuracy_metrics.h); the numbers equal computeMetrics's: counts exactly,
// sums to float rounding of the order they are added in, the edge error in texels exactly (an exact nearest-rank
// selection by four histogram rounds over the keys' bytes, rather than an approximating histogram) and in world
// units / screen pixels to float rounding of the product. Causes need shadow rays: the full measure gives them.
// Needs a current GL 4.5 context.
#include "accuracy/accuracy_meter.h"
#include "accuracy/shadow_boundary.h"
#include "gl/gl_objects.h"
#include "reference/visibility.h"

#include <cstdint>
#include <vector>

namespace shadowlab {

class GpuAccuracyCounter {
public:
    // Throws std::runtime_error if its shader does not build.
    GpuAccuracyCounter();

    // The reference of a width x height view (row 0 = top, the CPU's order): per pixel its class, whether it lies on
    // the true boundary, the boundary's distance state for filter reach k (ShadowBoundary::state), world units per
    // texel and screen pixels per texel (0 where the camera cannot say). Replaces what was uploaded before.
    void upload(int width, int height, const std::vector<PixelClass>& classes, ShadowBoundary& boundary, double k,
                const std::vector<float>& worldPerTexel, const std::vector<float>& screenPixelsPerTexel);
    // Pixels whose distance state the boundary has learnt since (after ShadowBoundary::prepare).
    void update(const std::vector<std::uint32_t>& pixels, ShadowBoundary& boundary, double k);
    bool uploaded() const { return width_ > 0; }

    struct Result {
        AccuracyNumbers numbers;  // counts (no causes), ratios, edge error in texels / world / screen pixels
        // Mismatched pixels whose distance the boundary must still probe for this k: when not empty, nothing
        // else is filled; prepare them, update() and count again.
        std::vector<std::uint32_t> unresolved;
    };
    // shadowTexture: the tool's frame in the shadow view (RGBA32F, GL order: row 0 = bottom), the upload's size.
    // k, cap (the map's size), probing: as the CPU metrics use them.
    Result count(GLuint shadowTexture, double k, double cap, bool probing);

private:
    void dispatch(const gl::Program& program, GLuint groups);  // groups 0: as many as the finish stage said

    gl::Program countProgram_, finishProgram_, histogramProgram_, pickProgram_;
    gl::Buffer words_, sums_, partials_, keys_, unresolved_, reference_, units_, histogram_, listed_, dispatch_;
    int width_ = 0, height_ = 0;
    std::vector<std::uint32_t> flags_;  // per pixel: class | on-boundary flag (the reference's w component)
};

}  // namespace shadowlab
