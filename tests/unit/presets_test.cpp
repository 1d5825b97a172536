// The gu* presets set the combine units as 3dfx's gu.c does (checked against its source).
#include "context.h"
#include "glide_window.h"

namespace {

using PresetTest = GlideWindowTest;
using glide_shim::CombineUnit;

CombineUnit color_after(GrColorCombineFnc_t preset) {
  guColorCombineFunction(preset);
  return glide_shim::current().color_path.color;
}

TEST_F(PresetTest, ColorCombinePresetsMatch3dfx) {
  EXPECT_EQ(color_after(GR_COLORCOMBINE_CCRGB_BLEND_ITRGB_ON_TEXALPHA),
            (CombineUnit{GR_COMBINE_FUNCTION_BLEND, GR_COMBINE_FACTOR_TEXTURE_ALPHA,
                         GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_ITERATED, false}));
  EXPECT_EQ(color_after(GR_COLORCOMBINE_DIFF_SPEC_A),
            (CombineUnit{GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL, GR_COMBINE_FACTOR_LOCAL_ALPHA,
                         GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, false}));
  EXPECT_EQ(color_after(GR_COLORCOMBINE_DIFF_SPEC_B),
            (CombineUnit{GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL_ALPHA, GR_COMBINE_FACTOR_LOCAL,
                         GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, false}));
  EXPECT_EQ(color_after(GR_COLORCOMBINE_DECAL_TEXTURE),
            (CombineUnit{GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                         GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_TEXTURE, false}));
  EXPECT_EQ(color_after(GR_COLORCOMBINE_ONE),
            (CombineUnit{GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_NONE,
                         GR_COMBINE_OTHER_NONE, true}));
  expect_no_error();
}

TEST_F(PresetTest, GlideCallsAreRefusedWhilePlainGlIsBegun) {
  ASSERT_TRUE(glideShimBeginGL());
  grCullMode(GR_CULL_NEGATIVE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INCONSISTENT);
  EXPECT_EQ(glide_shim::current().raster.cull, GR_CULL_DISABLE);
  glideShimEndGL();
  glideShimClearError();
  grCullMode(GR_CULL_NEGATIVE);
  expect_no_error();
}

TEST_F(PresetTest, ClipWindowInsideATextureTargetIsBoundedByItsSquare) {
  ASSERT_TRUE(glideShimRenderToTexture(GR_TMU0, 0, GR_LOD_32));
  grClipWindow(0, 0, 64, 64);  // fits the 64x64 screen, not the 32x32 target
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  glideShimClearError();
  grClipWindow(4, 4, 32, 32);
  expect_no_error();
  glideShimRenderToFrameBuffer();
  const auto &clip = glide_shim::current().raster.clip;
  EXPECT_EQ(clip.max_x, 64u) << "the screen's clip window comes back";
}

}  // namespace
