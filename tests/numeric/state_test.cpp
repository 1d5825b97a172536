// Whole-state calls and the SST queries: a grGlideGetState / grGlideSetState round trip through
// a different state draws the same frame, bit for bit; grDisableAllEffects turns off what
// gglide.c turns off; the board queries answer for an idle, always-in-retrace Voodoo 1; and
// the window's colour format (ARGB or ABGR) decides how constant, chroma and clear colours read.
#include "glide_window.h"

#include "context.h"

#include <cstring>
#include <vector>

namespace {

class StateTest : public GlideWindowTest {
 protected:
  // Clears the back buffer to black and the depth buffer to the farthest code through the LFB,
  // which leaves every pipeline setting alone.
  static void reset_buffers() {
    std::vector<FxU16> black(kWidth * kHeight, 0), far(kWidth * kHeight, 0xFFFF);
    ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, kWidth, kHeight,
                                 kWidth * 2, black.data()));
    ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_AUXBUFFER, 0, 0, GR_LFB_SRC_FMT_ZA16, kWidth, kHeight,
                                 kWidth * 2, far.data()));
  }

  // A state touching every group: texture, combine, alpha test, blend, chroma key, W buffer
  // with bias, fog, dither, culling, clip window, origin.
  static void set_state_a(const std::vector<FxU16> &texels) {
    GrTexInfo info{GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565,
                   const_cast<FxU16 *>(texels.data())};
    grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
    grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_CLAMP);
    guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
    guColorCombineFunction(GR_COLORCOMBINE_TEXTURE_TIMES_ITRGB);
    guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
    grAlphaTestFunction(GR_CMP_GREATER);
    grAlphaTestReferenceValue(40);
    grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
    grChromakeyMode(GR_CHROMAKEY_ENABLE);
    grChromakeyValue(0x0000F800u);
    grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
    grDepthBufferFunction(GR_CMP_LEQUAL);
    grDepthMask(FXTRUE);
    grDepthBiasLevel(40);
    GrFog_t table[GR_FOG_TABLE_SIZE];
    guFogGenerateLinear(table, 1.0f, 40.0f);
    grFogTable(table);
    grFogColorValue(0x00305080u);
    grFogMode(GR_FOG_WITH_TABLE);
    grDitherMode(GR_DITHER_2x2);
    grCullMode(GR_CULL_NEGATIVE);
    grClipWindow(3, 5, 61, 58);
    grSstOrigin(GR_ORIGIN_LOWER_LEFT);
    grConstantColorValue(0x80402010u);
  }

  // The opposite of state A in every group (and the front buffer as target).
  static void set_state_b() {
    grDisableAllEffects();
    grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_POINT_SAMPLED);
    grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_WRAP);
    guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_ONE);
    guColorCombineFunction(GR_COLORCOMBINE_CCRGB);
    guAlphaSource(GR_ALPHASOURCE_CC_ALPHA);
    grAlphaTestReferenceValue(200);
    grChromakeyValue(0x00FFFFFFu);
    grDepthBufferFunction(GR_CMP_GREATER);
    grDepthMask(FXFALSE);
    grFogColorValue(0x00FFFFFFu);
    grDitherMode(GR_DITHER_4x4);
    grCullMode(GR_CULL_POSITIVE);
    grClipWindow(0, 0, 20, 20);
    grSstOrigin(GR_ORIGIN_UPPER_LEFT);
    grConstantColorValue(0xFF00FF00u);
    grRenderBuffer(GR_BUFFER_FRONTBUFFER);
  }

  // Overlapping fogged, textured triangles at several depths, wound both ways.
  static void draw_scene() {
    for (int k = 0; k < 6; ++k) {
      GrVertex a = vertex(), b = vertex(), c = vertex();
      const float shift = static_cast<float>(k * 7);
      a.x = 2 + shift, a.y = 2, b.x = 60, b.y = 10 + shift, c.x = 10 + shift, c.y = 62;
      if (k % 3 == 2) std::swap(b, c);
      const float w = 1.5f + static_cast<float>(k) * 3.0f;
      for (GrVertex *v : {&a, &b, &c}) {
        v->oow = 1.0f / w;
        v->r = 255.0f - static_cast<float>(k) * 30.0f, v->g = 180, v->b = 40.0f + static_cast<float>(k) * 30.0f;
        v->a = 30.0f + static_cast<float>(k) * 40.0f;
        v->tmuvtx[0].sow = v->x * 5.0f / w, v->tmuvtx[0].tow = v->y * 4.0f / w;
        v->tmuvtx[0].oow = 1.0f / w;
      }
      grDrawTriangle(&a, &b, &c);
    }
  }

  static std::vector<FxU16> checker() {
    std::vector<FxU16> texels(64);
    for (int i = 0; i < 64; ++i) texels[static_cast<std::size_t>(i)] = ((i + i / 8) % 2) ? 0xF800 : 0x07FF;
    return texels;
  }
};

TEST_F(StateTest, RoundTripThroughAnotherStateDrawsTheSameFrame) {
  const std::vector<FxU16> texels = checker();
  set_state_a(texels);
  reset_buffers();
  draw_scene();
  const std::vector<FxU16> frame_a = read_buffer(GR_BUFFER_BACKBUFFER);
  int lit = 0;
  for (FxU16 p : frame_a) lit += p != 0;
  ASSERT_GT(lit, 500) << "state A draws a visible scene";

  GrState saved;
  grGlideGetState(&saved);
  set_state_b();
  reset_buffers();  // state B draws into the front buffer: the back one stays black
  draw_scene();
  EXPECT_NE(read_buffer(GR_BUFFER_BACKBUFFER), frame_a) << "state B must draw differently";
  EXPECT_NE(read_buffer(GR_BUFFER_FRONTBUFFER), frame_a);

  grGlideSetState(&saved);
  reset_buffers();
  draw_scene();
  EXPECT_EQ(read_buffer(GR_BUFFER_BACKBUFFER), frame_a);
  expect_no_error();
}

TEST_F(StateTest, StateFitsGrStateAndBadStatesAreRefused) {
  EXPECT_EQ(sizeof(GrState), static_cast<std::size_t>(GLIDE_STATE_PAD_SIZE));
  grCullMode(GR_CULL_POSITIVE);
  GrState garbage;
  std::memset(&garbage, 0x5A, sizeof garbage);
  grGlideSetState(&garbage);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_VALUE);
  EXPECT_EQ(glide_shim::current().raster.cull, GR_CULL_POSITIVE) << "a refused state changes nothing";
  glideShimClearError();
  grGlideSetState(nullptr);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  grGlideGetState(nullptr);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
}

TEST_F(StateTest, DisableAllEffectsTurnsOffWhatGglideDoes) {
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
  grAlphaTestFunction(GR_CMP_LESS);
  grChromakeyMode(GR_CHROMAKEY_ENABLE);
  grDepthBiasLevel(12);
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grFogMode(GR_FOG_WITH_TABLE);
  grCullMode(GR_CULL_NEGATIVE);
  grDisableAllEffects();
  const glide_shim::GlideContext &ctx = glide_shim::current();
  EXPECT_EQ(ctx.blend.rgb_src, GR_BLEND_ONE);
  EXPECT_EQ(ctx.blend.rgb_dst, GR_BLEND_ZERO);
  EXPECT_EQ(ctx.blend.alpha_test_function, GR_CMP_ALWAYS);
  EXPECT_EQ(ctx.chroma.mode, GR_CHROMAKEY_DISABLE);
  EXPECT_EQ(ctx.depth.bias_level, 0);
  EXPECT_EQ(ctx.depth.mode, GR_DEPTHBUFFER_DISABLE);
  EXPECT_EQ(ctx.fog.mode, GR_FOG_DISABLE);
  EXPECT_EQ(ctx.raster.cull, GR_CULL_NEGATIVE) << "culling is not an effect";
  expect_no_error();
}

TEST_F(StateTest, BoardQueriesDescribeAnIdleVoodoo) {
  EXPECT_EQ(grSstScreenWidth(), static_cast<FxU32>(kWidth));
  EXPECT_EQ(grSstScreenHeight(), static_cast<FxU32>(kHeight));
  EXPECT_EQ(grSstIsBusy(), FXFALSE);
  EXPECT_EQ(grSstVRetraceOn(), FXTRUE);
  EXPECT_EQ(grSstVideoLine(), 0u);
  EXPECT_EQ(grBufferNumPending(), 0);
  const FxU32 status = grSstStatus();
  EXPECT_EQ(status & 0x3Fu, 0x3Fu) << "PCI FIFO all free";
  EXPECT_EQ(status & (7u << 7), 0u) << "nothing busy";
  EXPECT_EQ((status >> 12) & 0xFFFFu, 0xFFFFu) << "memory FIFO all free";
  const FxU32 displayed = (status >> 10) & 3u;
  grBufferSwap(1);
  EXPECT_EQ((grSstStatus() >> 10) & 3u, displayed ^ 1u) << "the displayed buffer flips on a swap";
  GrHwConfiguration boards;
  EXPECT_EQ(grSstQueryBoards(&boards), FXTRUE);
  EXPECT_EQ(boards.num_sst, 1);
  grSplash(0, 0, 64, 64, 0);
  grGlideShamelessPlug(FXTRUE);
  grCheckForRoom(64);
  EXPECT_EQ(grSstControl(GR_CONTROL_DEACTIVATE), FXTRUE);
  EXPECT_EQ(grSstControl(GR_CONTROL_ACTIVATE), FXTRUE);
  expect_no_error();
  EXPECT_EQ(grSstControl(9), FXFALSE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM);
  glideShimClearError();
}

TEST(StateQueries, QueriesWithoutAWindowReportNotInitialized) {
  glideShimClearError();
  EXPECT_EQ(grSstScreenWidth(), 0u);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NOT_INITIALIZED);
  glideShimClearError();
  EXPECT_EQ(grSstStatus(), 0u);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NOT_INITIALIZED);
  glideShimClearError();
}

// The same frame described in ARGB and in ABGR words: clear, constant and chroma colours.
std::vector<FxU16> frame_in_format(GrColorFormat_t format) {
  auto encode = [format](unsigned r, unsigned g, unsigned b) -> GrColor_t {
    return format == GR_COLORFORMAT_ABGR ? (0xFFu << 24) | (b << 16) | (g << 8) | r
                                         : (0xFFu << 24) | (r << 16) | (g << 8) | b;
  };
  grGlideInit();
  EXPECT_TRUE(glideShimSetWindowSize(32, 32));
  EXPECT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, format, GR_ORIGIN_UPPER_LEFT, 2, 1));
  grDitherMode(GR_DITHER_DISABLE);
  grBufferClear(encode(16, 80, 200), 0, 0);
  GrVertex v[4];
  std::memset(v, 0, sizeof v);
  const float xs[4] = {4, 28, 28, 4}, ys[4] = {4, 4, 14, 14};
  for (int i = 0; i < 4; ++i) v[i].x = xs[i], v[i].y = ys[i], v[i].oow = 1;
  grConstantColorValue(encode(240, 120, 8));
  guColorCombineFunction(GR_COLORCOMBINE_CCRGB);
  grDrawTriangle(&v[0], &v[1], &v[2]);
  grDrawTriangle(&v[0], &v[2], &v[3]);
  // Iterated colours as the combine's 'other' input, which the chroma key compares: the
  // triangle equal to the key is not drawn.
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                 GR_COMBINE_OTHER_ITERATED, FXFALSE);
  grChromakeyMode(GR_CHROMAKEY_ENABLE);
  grChromakeyValue(encode(0, 255, 0));
  for (int i = 0; i < 4; ++i) v[i].y += 14, v[i].g = 255, v[i].r = 0;
  grDrawTriangle(&v[0], &v[1], &v[2]);  // all green: keyed out
  for (int i = 0; i < 4; ++i) v[i].r = 255;
  grDrawTriangle(&v[0], &v[2], &v[3]);  // yellow: drawn
  std::vector<FxU16> pixels(32 * 32);
  EXPECT_TRUE(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 32, 32, 64, pixels.data()));
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
  grGlideShutdown();
  return pixels;
}

TEST(ColorFormat, ArgbAndAbgrWindowsReadTheirOwnColourWords) {
  glideShimClearError();
  const std::vector<FxU16> argb = frame_in_format(GR_COLORFORMAT_ARGB);
  const std::vector<FxU16> abgr = frame_in_format(GR_COLORFORMAT_ABGR);
  EXPECT_EQ(argb, abgr);
  const FxU16 clear = ((16 >> 3) << 11) | ((80 >> 2) << 5) | (200 >> 3);
  const FxU16 constant = ((240 >> 3) << 11) | ((120 >> 2) << 5) | (8 >> 3);
  EXPECT_EQ(argb[0], clear);
  EXPECT_EQ(argb[8 * 32 + 16], constant);
  EXPECT_EQ(argb[20 * 32 + 26], clear) << "the keyed-out green triangle left the clear colour";
  EXPECT_EQ(argb[26 * 32 + 6], 0xFFE0) << "the yellow triangle is drawn";
}

}  // namespace
