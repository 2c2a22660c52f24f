// The shadow pass's culling rule (renderer/frame/face_culling.h) is one function that both the GL shadow pass and
// the reference's cause rays use: if they disagreed, the roof's "caster culled" cause would name the wrong faces.
#include "frame/face_culling.h"

#include <gtest/gtest.h>

namespace shadowlab {
namespace {

TEST(FaceCullingRule, NoneAndDoubleSidedKeepEveryFace) {
    for (bool facesLight : {false, true}) {
        EXPECT_FALSE(shadowPassCulls(CullMode::None, false, facesLight));
        EXPECT_FALSE(shadowPassCulls(CullMode::Back, true, facesLight)) << "double-sided materials cast both ways";
        EXPECT_FALSE(shadowPassCulls(CullMode::Front, true, facesLight));
    }
    EXPECT_FALSE(shadowPassCullsAny(CullMode::None, false));
    EXPECT_FALSE(shadowPassCullsAny(CullMode::Back, true));
    EXPECT_TRUE(shadowPassCullsAny(CullMode::Front, false));
}

TEST(FaceCullingRule, BackDropsFacesLookingAwayFromTheLightAndFrontTheOthers) {
    // A single-sided roof facing down under a light from above: its front looks away, so back culling drops it.
    EXPECT_TRUE(shadowPassCulls(CullMode::Back, false, /*frontFacesLight=*/false));
    EXPECT_FALSE(shadowPassCulls(CullMode::Back, false, true));
    EXPECT_TRUE(shadowPassCulls(CullMode::Front, false, true));
    EXPECT_FALSE(shadowPassCulls(CullMode::Front, false, false));
}

}  // namespace
}  // namespace shadowlab
