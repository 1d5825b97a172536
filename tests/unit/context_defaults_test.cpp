// The state grSstWinOpen establishes (3dfx's gsst.c, as summarised in the team's notes, shared/docs/glide_api.md section 1, "Defaults set by
// grSstWinOpen", from 3dfx's gsst.c), group by group in glide_shim::current(); that a
// close/open cycle restores it after changes; the hardware query and version string; and that
// the window's colour format decides how GrColor_t values (clear colour, constant colour) are read.
#include "context.h"
#include "glide_window.h"

#include <cstring>
#include <string>

namespace {

using glide_shim::CombineUnit;
using glide_shim::current;
using glide_shim::TexCombineUnit;

constexpr FxU32 kTmuBytes = 2u * 1024u * 1024u;

// Every group holds the gsst.c defaults for a window of this size, format and origin.
void expect_window_defaults(int width, int height, GrColorFormat_t format, GrOriginLocation_t origin) {
  const glide_shim::GlideContext &c = current();
  EXPECT_TRUE(c.initialized);

  // Colour path: colour = SCALE_OTHER, ONE, ITERATED, ITERATED (the vertex colour);
  // alpha = SCALE_OTHER, ONE, NONE, CONSTANT (the constant alpha); constant colour all ones.
  const CombineUnit color{GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                          GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED, false};
  const CombineUnit alpha{GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                          GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_CONSTANT, false};
  EXPECT_EQ(c.color_path.color.function, color.function);
  EXPECT_EQ(c.color_path.color.factor, color.factor);
  EXPECT_EQ(c.color_path.color.local, color.local);
  EXPECT_EQ(c.color_path.color.other, color.other);
  EXPECT_EQ(c.color_path.color.invert, color.invert);
  EXPECT_TRUE(c.color_path.color == color);
  EXPECT_EQ(c.color_path.alpha.function, alpha.function);
  EXPECT_EQ(c.color_path.alpha.factor, alpha.factor);
  EXPECT_EQ(c.color_path.alpha.local, alpha.local);
  EXPECT_EQ(c.color_path.alpha.other, alpha.other);
  EXPECT_EQ(c.color_path.alpha.invert, alpha.invert);
  EXPECT_TRUE(c.color_path.alpha == alpha);
  EXPECT_EQ(c.color_path.constant_color, 0xFFFFFFFFu);

  // Blending ONE/ZERO (off) for colour and alpha; alpha test ALWAYS.
  EXPECT_EQ(c.blend.rgb_src, GR_BLEND_ONE);
  EXPECT_EQ(c.blend.rgb_dst, GR_BLEND_ZERO);
  EXPECT_EQ(c.blend.alpha_src, GR_BLEND_ONE);
  EXPECT_EQ(c.blend.alpha_dst, GR_BLEND_ZERO);
  EXPECT_EQ(c.blend.alpha_test_function, GR_CMP_ALWAYS);

  // Chroma key off.
  EXPECT_EQ(c.chroma.mode, GR_CHROMAKEY_DISABLE);

  // Depth: DISABLE, LESS, writes off, no bias.
  EXPECT_EQ(c.depth.mode, GR_DEPTHBUFFER_DISABLE);
  EXPECT_EQ(c.depth.function, GR_CMP_LESS);
  EXPECT_FALSE(c.depth.mask);
  EXPECT_EQ(c.depth.bias_level, 0);

  // Raster: cull off, dither 4x4, clip = the whole screen, grColorMask(TRUE, FALSE), drawing to
  // the back buffer in the origin the window was opened with, no STW hint.
  EXPECT_EQ(c.raster.cull, GR_CULL_DISABLE);
  EXPECT_EQ(c.raster.dither, GR_DITHER_4x4);
  EXPECT_EQ(c.raster.clip.min_x, 0u);
  EXPECT_EQ(c.raster.clip.min_y, 0u);
  EXPECT_EQ(c.raster.clip.max_x, static_cast<FxU32>(width));
  EXPECT_EQ(c.raster.clip.max_y, static_cast<FxU32>(height));
  EXPECT_TRUE(c.raster.rgb_mask);
  EXPECT_FALSE(c.raster.alpha_mask);
  EXPECT_EQ(c.raster.render_buffer, GR_BUFFER_BACKBUFFER);
  EXPECT_EQ(c.raster.origin, origin);
  EXPECT_EQ(c.raster.stw_hint, 0u);

  // TMU: CLAMP, POINT_SAMPLED, no mip-mapping, no bias, grTexCombine(ZERO) so the texture
  // outputs 0; no texture selected; 2 MB of texture memory.
  EXPECT_EQ(c.tmu.clamp_s, GR_TEXTURECLAMP_CLAMP);
  EXPECT_EQ(c.tmu.clamp_t, GR_TEXTURECLAMP_CLAMP);
  EXPECT_EQ(c.tmu.min_filter, GR_TEXTUREFILTER_POINT_SAMPLED);
  EXPECT_EQ(c.tmu.mag_filter, GR_TEXTUREFILTER_POINT_SAMPLED);
  EXPECT_EQ(c.tmu.mipmap_mode, GR_MIPMAP_DISABLE);
  EXPECT_FALSE(c.tmu.lod_blend);
  EXPECT_EQ(c.tmu.lod_bias, 0.0f);
  EXPECT_EQ(c.tmu.combine.rgb_function, GR_COMBINE_FUNCTION_ZERO);
  EXPECT_EQ(c.tmu.combine.alpha_function, GR_COMBINE_FUNCTION_ZERO);
  EXPECT_EQ(c.tmu.combine.rgb_factor, GR_COMBINE_FACTOR_ZERO);
  EXPECT_EQ(c.tmu.combine.alpha_factor, GR_COMBINE_FACTOR_ZERO);
  EXPECT_FALSE(c.tmu.combine.rgb_invert);
  EXPECT_FALSE(c.tmu.combine.alpha_invert);
  EXPECT_FALSE(c.tmu.source.valid);
  EXPECT_EQ(c.tmu.memory.size(), kTmuBytes);

  // Display: open, the requested size and colour format, gamma 1.7.
  EXPECT_TRUE(c.display.open);
  EXPECT_EQ(c.display.width, width);
  EXPECT_EQ(c.display.height, height);
  EXPECT_EQ(c.display.color_format, format);
  EXPECT_FLOAT_EQ(c.display.gamma, 1.7f);

  // No LFB lock held.
  EXPECT_FALSE(c.lfb.read_locked);
  EXPECT_FALSE(c.lfb.write_locked);
}

using ContextDefaultsTest = GlideWindowTest;

TEST_F(ContextDefaultsTest, EveryGroupHoldsTheGrSstWinOpenDefaults) {
  expect_window_defaults(kWidth, kHeight, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT);
}

TEST_F(ContextDefaultsTest, CloseAndReopenRestoresTheDefaultsAfterChanges) {
  // Change every group away from its default.
  grColorCombine(GR_COMBINE_FUNCTION_BLEND, GR_COMBINE_FACTOR_TEXTURE_ALPHA, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_TEXTURE, FXTRUE);
  grAlphaCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED,
                 GR_COMBINE_OTHER_ITERATED, FXTRUE);
  grConstantColorValue(0x12345678u);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ZERO, GR_BLEND_ONE);
  grAlphaTestFunction(GR_CMP_GEQUAL);
  grAlphaTestReferenceValue(0x80);
  grChromakeyMode(GR_CHROMAKEY_ENABLE);
  grChromakeyValue(0x00FF00FFu);
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_GEQUAL);
  grDepthMask(FXTRUE);
  grDepthBiasLevel(-100);
  grCullMode(GR_CULL_NEGATIVE);
  grDitherMode(GR_DITHER_DISABLE);
  grClipWindow(3, 4, 30, 40);
  grColorMask(FXFALSE, FXTRUE);
  grRenderBuffer(GR_BUFFER_FRONTBUFFER);
  grSstOrigin(GR_ORIGIN_LOWER_LEFT);
  grHints(GR_HINT_STWHINT, GR_STWHINT_W_DIFF_TMU0);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXTRUE);
  grTexLodBiasValue(GR_TMU0, 1.5f);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  std::vector<FxU16> texels(8 * 8, 0xABCD);
  GrTexInfo info{GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grGammaCorrectionValue(2.2f);
  expect_no_error();
  // The changes took (spot checks, so the reopen below has something to undo).
  ASSERT_EQ(current().depth.mode, GR_DEPTHBUFFER_WBUFFER);
  ASSERT_EQ(current().raster.clip.max_x, 30u);
  ASSERT_EQ(current().raster.origin, GR_ORIGIN_LOWER_LEFT);
  ASSERT_TRUE(current().tmu.source.valid);
  ASSERT_EQ(current().tmu.memory[0], 0xCD);
  ASSERT_FLOAT_EQ(current().display.gamma, 2.2f);

  grSstWinClose();
  EXPECT_FALSE(current().display.open);
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  expect_window_defaults(kWidth, kHeight, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT);
  // The TMU memory of the old window is gone.
  EXPECT_EQ(current().tmu.memory[0], 0);
  expect_no_error();

  // A second cycle, with another colour format, origin and size.
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grCullMode(GR_CULL_POSITIVE);
  grSstWinClose();
  ASSERT_TRUE(glideShimSetWindowSize(32, 16));
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ABGR,
                           GR_ORIGIN_LOWER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  expect_window_defaults(32, 16, GR_COLORFORMAT_ABGR, GR_ORIGIN_LOWER_LEFT);
  expect_no_error();
}

TEST_F(ContextDefaultsTest, ShutdownAndInitRestoreTheDefaults) {
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthMask(FXTRUE);
  grDitherMode(GR_DITHER_2x2);
  grConstantColorValue(0u);
  grGlideShutdown();
  grGlideInit();
  ASSERT_TRUE(glideShimSetWindowSize(kWidth, kHeight));
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  expect_window_defaults(kWidth, kHeight, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT);
}

TEST_F(ContextDefaultsTest, HardwareQueryReportsOneVoodooWithOneTmu) {
  GrHwConfiguration hw;
  std::memset(&hw, 0x7F, sizeof hw);
  ASSERT_EQ(grSstQueryHardware(&hw), FXTRUE) << glideShimGetLastErrorMessage();
  EXPECT_EQ(hw.num_sst, 1);
  EXPECT_EQ(hw.SSTs[0].type, GR_SSTTYPE_VOODOO);
  const GrVoodooConfig_t &voodoo = hw.SSTs[0].sstBoard.VoodooConfig;
  EXPECT_EQ(voodoo.nTexelfx, 1);
  EXPECT_EQ(voodoo.tmuConfig[0].tmuRam, 2);  // MB, matching the 2 MB of TMU memory
  EXPECT_GE(voodoo.fbRam, 2);                // two 640x480 colour buffers and the aux buffer
  EXPECT_EQ(voodoo.sliDetect, FXFALSE);
  expect_no_error();
}

TEST_F(ContextDefaultsTest, GlideGetVersionWritesANulTerminatedString) {
  char version[80];
  std::memset(version, 'x', sizeof version);
  grGlideGetVersion(version);
  const void *nul = std::memchr(version, '\0', sizeof version);
  ASSERT_NE(nul, nullptr) << "no NUL in the 80 bytes";
  const std::size_t length = std::strlen(version);
  EXPECT_GT(length, 0u);
  for (std::size_t i = 0; i < length; ++i) {
    EXPECT_TRUE(version[i] >= 0x20 && version[i] < 0x7F) << "byte " << i << " is not printable";
  }
  EXPECT_NE(std::string(version).find("Glide"), std::string::npos) << version;
  expect_no_error();
}

// ---- the colour format -------------------------------------------------------------------------

// A window of its own in a given colour format (the fixture's is ARGB).
class ColorFormatTest : public ::testing::Test {
 protected:
  static constexpr int kSide = 16;

  void TearDown() override {
    grGlideShutdown();
    glideShimClearError();
  }

  static void open(GrColorFormat_t format) {
    grGlideShutdown();
    grGlideInit();
    ASSERT_TRUE(glideShimSetWindowSize(kSide, kSide));
    ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, format,
                             GR_ORIGIN_UPPER_LEFT, 2, 1))
        << glideShimGetLastErrorMessage();
    ASSERT_EQ(current().display.color_format, format);
    grDitherMode(GR_DITHER_DISABLE);
  }

  static FxU16 pixel(int x, int y) {
    FxU16 word = 0;
    EXPECT_TRUE(grLfbReadRegion(GR_BUFFER_BACKBUFFER, static_cast<FxU32>(x),
                                static_cast<FxU32>(y), 1, 1, 2, &word));
    return word;
  }

  static FxU16 clear_and_read(GrColorFormat_t format, GrColor_t color) {
    open(format);
    grBufferClear(color, 0, 0);
    const FxU16 word = pixel(kSide / 2, kSide / 2);
    EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
    return word;
  }

  // Fills the window with the constant colour through grColorCombine(LOCAL, NONE, CONSTANT).
  static FxU16 constant_and_read(GrColorFormat_t format, GrColor_t color) {
    open(format);
    grBufferClear(0, 0, 0);
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                   GR_COMBINE_OTHER_NONE, FXFALSE);
    grConstantColorValue(color);
    GrVertex v[4];
    std::memset(v, 0, sizeof v);
    const float side = static_cast<float>(kSide);
    v[0].x = 0, v[0].y = 0;
    v[1].x = side, v[1].y = 0;
    v[2].x = side, v[2].y = side;
    v[3].x = 0, v[3].y = side;
    for (GrVertex &vertex : v) vertex.oow = 1.0f;
    grDrawTriangle(&v[0], &v[1], &v[2]);
    grDrawTriangle(&v[0], &v[2], &v[3]);
    const FxU16 word = pixel(kSide / 2, kSide / 2);
    EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
    return word;
  }
};

TEST_F(ColorFormatTest, ClearColourIsReadInTheWindowsFormat) {
  // 0x000000FF: the low byte is red in ABGR (0xAABBGGRR) and blue in ARGB (0xAARRGGBB).
  EXPECT_EQ(clear_and_read(GR_COLORFORMAT_ABGR, 0x000000FFu), 0xF800);
  EXPECT_EQ(clear_and_read(GR_COLORFORMAT_ARGB, 0x000000FFu), 0x001F);
  // 0xFF000000: the high byte is red in RGBA (0xRRGGBBAA) and blue in BGRA (0xBBGGRRAA).
  EXPECT_EQ(clear_and_read(GR_COLORFORMAT_RGBA, 0xFF000000u), 0xF800);
  EXPECT_EQ(clear_and_read(GR_COLORFORMAT_BGRA, 0xFF000000u), 0x001F);
  // A colour with three distinct channels, 0x00FF8040:
  // ARGB: r 0xFF, g 0x80, b 0x40 -> 565 (31, 32, 8) = 0xF800 | 0x0400 | 0x0008 = 0xFC08.
  // ABGR: r 0x40, g 0x80, b 0xFF -> 565 (8, 32, 31) = 0x4000 | 0x0400 | 0x001F = 0x441F.
  EXPECT_EQ(clear_and_read(GR_COLORFORMAT_ARGB, 0x00FF8040u), 0xFC08);
  EXPECT_EQ(clear_and_read(GR_COLORFORMAT_ABGR, 0x00FF8040u), 0x441F);
}

TEST_F(ColorFormatTest, ConstantColourIsReadInTheWindowsFormat) {
  EXPECT_EQ(constant_and_read(GR_COLORFORMAT_ABGR, 0x000000FFu), 0xF800);
  EXPECT_EQ(constant_and_read(GR_COLORFORMAT_ARGB, 0x000000FFu), 0x001F);
  EXPECT_EQ(constant_and_read(GR_COLORFORMAT_RGBA, 0xFF000000u), 0xF800);
  EXPECT_EQ(constant_and_read(GR_COLORFORMAT_BGRA, 0xFF000000u), 0x001F);
  EXPECT_EQ(constant_and_read(GR_COLORFORMAT_ARGB, 0x00FF8040u), 0xFC08);
  EXPECT_EQ(constant_and_read(GR_COLORFORMAT_ABGR, 0x00FF8040u), 0x441F);
}

}  // namespace
