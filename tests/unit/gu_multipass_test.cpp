// guMP* multipass texturing (gump.c, ddgump.c): guMPDrawTriangle against the same passes drawn
// by hand with guTexSource, grTexCombine, the blender and the depth test, as the driver sets
// them (fog colour and colour-combine bias kept out of the later passes, MULTIPLY's third fog
// pass included); the colours the ADD and MULTIPLY passes leave; the state restored afterwards;
// and the refused calls (bad function, virtual TMU, mip map, pointers, and states one TMU cannot
// split).
#include "glide_window.h"

#include "context.h"

#include <cstring>
#include <vector>

namespace {

constexpr int kSide = 8;  // the 8x8 single-level textures

FxU16 rgb565(int r5, int g6, int b5) { return static_cast<FxU16>((r5 << 11) | (g6 << 5) | b5); }
int expand5(int v) { return (v << 3) | (v >> 2); }
int expand6(int v) { return (v << 2) | (v >> 4); }

class GuMultipassTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    guMPInit();
    first_ = constant_texture(rgb565(8, 16, 4));
    second_ = constant_texture(rgb565(10, 20, 6));
    guMPTexSource(GR_TMU0, first_);
    guMPTexSource(GR_TMU1, second_);
    guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
    grDitherMode(GR_DITHER_DISABLE);
    grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
    grDepthBufferFunction(GR_CMP_LESS);
    grDepthMask(FXTRUE);
    clear();
    expect_no_error();
  }
  void TearDown() override {
    guMPInit();
    GlideWindowTest::TearDown();
  }

  static GrMipMapId_t constant_texture(FxU16 texel) {
    const GrMipMapId_t id = guTexAllocateMemory(
        GR_TMU0, GR_MIPMAPLEVELMASK_BOTH, kSide, kSide, GR_TEXFMT_RGB_565, GR_MIPMAP_DISABLE,
        GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP,
        GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_POINT_SAMPLED, 0.0f, FXFALSE);
    const std::vector<FxU16> texels(kSide * kSide, texel);
    guTexDownloadMipMap(id, texels.data(), nullptr);
    return id;
  }

  static void clear() { grBufferClear(0, 0, GR_WDEPTHVALUE_FARTHEST); }

  // A rectangle covering pixels [8,40) x [8,40), at w = 2.
  static GrVertex style() {
    GrVertex v = vertex();
    v.oow = 0.5f;
    return v;
  }
  static void draw_multipass_rect() {
    GrVertex a = style(), b = style(), c = style(), d = style();
    a.x = 8, a.y = 8;
    b.x = 40, b.y = 8;
    c.x = 40, c.y = 40;
    d.x = 8, d.y = 40;
    guMPDrawTriangle(&a, &b, &c);
    guMPDrawTriangle(&a, &c, &d);
  }

  // Fog from the iterated alpha, and a colour combine with a local bias (texture + iterated
  // RGB): the state whose fog colour and bias the driver keeps out of the later passes.
  static GrVertex fogged_style() {
    GrVertex v = style();
    v.r = 20.0f, v.g = 30.0f, v.b = 40.0f, v.a = 96.0f;
    return v;
  }
  static void fog_and_bias() {
    grFogMode(GR_FOG_WITH_ITERATED_ALPHA);
    grFogColorValue(0x00406080);
    guColorCombineFunction(GR_COLORCOMBINE_TEXTURE_ADD_ITRGB);
  }
  static void draw_fogged_multipass_rect() {
    GrVertex a = fogged_style(), b = fogged_style(), c = fogged_style(), d = fogged_style();
    a.x = 8, a.y = 8;
    b.x = 40, b.y = 8;
    c.x = 40, c.y = 40;
    d.x = 8, d.y = 40;
    guMPDrawTriangle(&a, &b, &c);
    guMPDrawTriangle(&a, &c, &d);
  }
  static void source_with_replace(GrMipMapId_t mmid) {
    guTexSource(mmid);
    grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE,
                 GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, FXFALSE, FXFALSE);
  }

  GrMipMapId_t first_ = GR_NULL_MIPMAP_HANDLE;
  GrMipMapId_t second_ = GR_NULL_MIPMAP_HANDLE;
};

// The two ADD passes by hand: each texel replaces, the second is added onto the first where the
// depth equals the first pass's.
TEST_F(GuMultipassTest, AddEqualsTheTwoPassesDrawnByHand) {
  draw_multipass_rect();
  expect_no_error();
  const std::vector<FxU16> multipass = read_buffer();

  clear();
  guTexSource(first_);
  grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE,
               GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, FXFALSE, FXFALSE);
  draw_rect(8, 8, 40, 40, style());
  guTexSource(second_);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE);
  grDepthBufferFunction(GR_CMP_EQUAL);
  grDepthMask(FXFALSE);
  draw_rect(8, 8, 40, 40, style());
  expect_no_error();
  EXPECT_EQ(multipass, read_buffer());

  // The sum of the two texels, each expanded to 8 bits, truncated back to 565.
  const FxU16 p = multipass[20 * kWidth + 20];
  EXPECT_EQ(red5(p), (expand5(8) + expand5(10)) >> 3);
  EXPECT_EQ(green6(p), (expand6(16) + expand6(20)) >> 2);
  EXPECT_EQ(blue5(p), (expand5(4) + expand5(6)) >> 3);
  EXPECT_EQ(multipass[2 * kWidth + 2], 0) << "outside the rectangle";
}

TEST_F(GuMultipassTest, MultiplyScalesTheFirstPassByTheSecondTexel) {
  guMPTexCombineFunction(GR_MPTEXTURECOMBINE_MULTIPLY);
  draw_multipass_rect();
  expect_no_error();
  const std::vector<FxU16> multipass = read_buffer();

  clear();
  guTexSource(first_);
  grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE,
               GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, FXFALSE, FXFALSE);
  draw_rect(8, 8, 40, 40, style());
  guTexSource(second_);
  grAlphaBlendFunction(GR_BLEND_DST_COLOR, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  grDepthBufferFunction(GR_CMP_EQUAL);
  grDepthMask(FXFALSE);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                 GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  draw_rect(8, 8, 40, 40, style());
  expect_no_error();
  EXPECT_EQ(multipass, read_buffer());

  // src * dst / 255 per channel (GL's blender may round where the hardware truncates: +-1).
  const FxU16 p = multipass[20 * kWidth + 20];
  EXPECT_NEAR(red5(p), (expand5(8) * expand5(10) / 255) >> 3, 1);
  EXPECT_NEAR(green6(p), (expand6(16) * expand6(20) / 255) >> 2, 1);
  EXPECT_NEAR(blue5(p), (expand5(4) * expand5(6) / 255) >> 3, 1);
}

// DETAIL0: pass 0 scales its texel by (1 - detail), pass 1 by detail; drawn by hand with the
// same TMU0 combines.
TEST_F(GuMultipassTest, Detail0EqualsItsTwoCombinesDrawnByHand) {
  grTexDetailControl(GR_TMU0, 2, 3, 0.5f);
  guMPTexCombineFunction(GR_MPTEXTURECOMBINE_DETAIL0);
  draw_multipass_rect();
  expect_no_error();
  const std::vector<FxU16> multipass = read_buffer();

  clear();
  guTexSource(first_);
  grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL,
               GR_COMBINE_FACTOR_ONE_MINUS_DETAIL_FACTOR,
               GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL,
               GR_COMBINE_FACTOR_ONE_MINUS_DETAIL_FACTOR, FXFALSE, FXFALSE);
  draw_rect(8, 8, 40, 40, style());
  guTexSource(second_);
  grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL,
               GR_COMBINE_FACTOR_DETAIL_FACTOR, GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL,
               GR_COMBINE_FACTOR_DETAIL_FACTOR, FXFALSE, FXFALSE);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE);
  grDepthBufferFunction(GR_CMP_EQUAL);
  grDepthMask(FXFALSE);
  draw_rect(8, 8, 40, 40, style());
  expect_no_error();
  EXPECT_EQ(multipass, read_buffer());
  EXPECT_NE(multipass[20 * kWidth + 20], 0);
}

// ADD with fog and a biased colour combine: the second pass is added without the fog colour
// (GR_FOG_ADD2) and without the combine's local term.
TEST_F(GuMultipassTest, AddKeepsFogColourAndBiasOutOfTheSecondPass) {
  fog_and_bias();
  draw_fogged_multipass_rect();
  expect_no_error();
  const std::vector<FxU16> multipass = read_buffer();

  clear();
  source_with_replace(first_);
  draw_rect(8, 8, 40, 40, fogged_style());
  source_with_replace(second_);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE);
  grDepthBufferFunction(GR_CMP_EQUAL);
  grDepthMask(FXFALSE);
  grFogMode(GR_FOG_WITH_ITERATED_ALPHA | GR_FOG_ADD2);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                 GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  draw_rect(8, 8, 40, 40, fogged_style());
  expect_no_error();
  EXPECT_EQ(multipass, read_buffer());

  // The fog colour and bias counted twice would give a different picture.
  clear();
  source_with_replace(first_);
  fog_and_bias();
  draw_rect(8, 8, 40, 40, fogged_style());
  source_with_replace(second_);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE);
  grDepthBufferFunction(GR_CMP_EQUAL);
  grDepthMask(FXFALSE);
  draw_rect(8, 8, 40, 40, fogged_style());
  EXPECT_NE(multipass, read_buffer());
}

// MULTIPLY with fog: the first pass without fog colour and bias, the texel multiplying the
// destination without fog, then an untextured pass adding fog x fog colour (GR_FOG_MULT2).
TEST_F(GuMultipassTest, MultiplyWithFogAddsTheFogColourInAThirdPass) {
  fog_and_bias();
  guMPTexCombineFunction(GR_MPTEXTURECOMBINE_MULTIPLY);
  draw_fogged_multipass_rect();
  expect_no_error();
  const std::vector<FxU16> multipass = read_buffer();

  clear();
  source_with_replace(first_);
  grFogMode(GR_FOG_WITH_ITERATED_ALPHA | GR_FOG_ADD2);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                 GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  draw_rect(8, 8, 40, 40, fogged_style());
  source_with_replace(second_);
  grAlphaBlendFunction(GR_BLEND_DST_COLOR, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  grDepthBufferFunction(GR_CMP_EQUAL);
  grDepthMask(FXFALSE);
  grFogMode(GR_FOG_DISABLE);
  draw_rect(8, 8, 40, 40, fogged_style());
  const std::vector<FxU16> without_third_pass = read_buffer();
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE);
  grFogMode(GR_FOG_WITH_ITERATED_ALPHA | GR_FOG_MULT2);
  grColorCombine(GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED,
                 GR_COMBINE_OTHER_ITERATED, FXFALSE);
  draw_rect(8, 8, 40, 40, fogged_style());
  expect_no_error();
  EXPECT_EQ(multipass, read_buffer());
  EXPECT_NE(multipass, without_third_pass);
}

TEST_F(GuMultipassTest, RestoresTheStateItChangedAndLeavesTheSecondMipMapSelected) {
  const auto &ctx = glide_shim::current();
  const glide_shim::BlendState blend = ctx.blend;
  const glide_shim::DepthState depth = ctx.depth;
  const glide_shim::CombineUnit color = ctx.color_path.color;
  const glide_shim::TexCombineUnit tex = ctx.tmu.combine;
  const GrFogMode_t fog = ctx.fog.mode;
  draw_multipass_rect();
  expect_no_error();
  EXPECT_EQ(ctx.blend.rgb_src, blend.rgb_src);
  EXPECT_EQ(ctx.blend.rgb_dst, blend.rgb_dst);
  EXPECT_EQ(ctx.blend.alpha_src, blend.alpha_src);
  EXPECT_EQ(ctx.blend.alpha_dst, blend.alpha_dst);
  EXPECT_EQ(ctx.depth.function, depth.function);
  EXPECT_EQ(ctx.depth.mask, depth.mask);
  EXPECT_TRUE(ctx.color_path.color == color);
  EXPECT_TRUE(ctx.tmu.combine == tex);
  EXPECT_EQ(ctx.fog.mode, fog);
  EXPECT_EQ(guTexGetCurrentMipMap(GR_TMU0), second_);
}

TEST_F(GuMultipassTest, BadArgumentsAreRefusedAndChangeNothing) {
  guMPTexCombineFunction(GR_MPTEXTURECOMBINE_SUBTRACT + 1);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM);
  glideShimClearError();
  guMPTexSource(GR_TMU2, first_);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM);
  glideShimClearError();
  guMPTexSource(GR_TMU1, 500);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_VALUE);
  glideShimClearError();
  GrVertex v = style();
  guMPDrawTriangle(&v, nullptr, &v);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  glideShimClearError();
  EXPECT_EQ(read_buffer(), std::vector<FxU16>(kWidth * kHeight, 0));

  // Still ADD with the two mip maps: the result equals a fresh ADD draw.
  draw_multipass_rect();
  expect_no_error();
  const FxU16 p = pixel(20, 20);
  EXPECT_EQ(red5(p), (expand5(8) + expand5(10)) >> 3);
}

TEST_F(GuMultipassTest, StatesOneTmuCannotSplitAreRefusedWithoutDrawing) {
  const std::vector<FxU16> empty(kWidth * kHeight, 0);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                       GR_BLEND_ZERO);
  draw_multipass_rect();
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INCONSISTENT);
  glideShimClearError();
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  grAlphaTestFunction(GR_CMP_GREATER);
  draw_multipass_rect();
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INCONSISTENT);
  glideShimClearError();
  grAlphaTestFunction(GR_CMP_ALWAYS);
  guMPTexCombineFunction(GR_MPTEXTURECOMBINE_SUBTRACT);
  draw_multipass_rect();
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_UNSUPPORTED);
  glideShimClearError();
  guMPInit();  // both virtual TMUs back to the null mip map
  draw_multipass_rect();
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INCONSISTENT);
  glideShimClearError();
  EXPECT_EQ(read_buffer(), empty);
}

}  // namespace
