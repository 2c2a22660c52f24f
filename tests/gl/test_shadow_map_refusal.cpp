// Issue 12: a refused shadow-map size states the range the shadow.resolution key states (narrowed by the GPU) and
// what is kept; never "[1, N]" or "keeping the 0² map".
#include "gl_fixture.h"
#include "settings/settings_fields.h"
#include "shadow/shadow_map.h"

#include <gtest/gtest.h>

using namespace shadowlab;

namespace {
class ShadowMapRefusal : public test::GlTest {};
}  // namespace

TEST_F(ShadowMapRefusal, StatesTheKeysRangeAndWhatIsKept) {
    ShadowMap map;
    std::string error = map.ensure(8, DepthFormat::D32F, 16384);
    EXPECT_EQ(error, "shadow.resolution: 8 is outside what this GPU allows [16, 16384] (GL_MAX_TEXTURE_SIZE 16384); "
                     "no shadow map yet");
    ASSERT_EQ(map.ensure(64, DepthFormat::D32F, 16384), "");
    error = map.ensure(65536, DepthFormat::D32F, 65536);  // a GPU larger than the key: the key's 32768 rules
    EXPECT_EQ(error, "shadow.resolution: 65536 is outside what this GPU allows [16, 32768] (GL_MAX_TEXTURE_SIZE "
                     "65536); keeping the 64² map");
    EXPECT_EQ(findSettingsField("shadow.resolution")->allowed, "integer in [16, 32768]");
}
