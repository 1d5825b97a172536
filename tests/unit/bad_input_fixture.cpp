// The definitions behind bad_input_fixture.h: the callback's log, the state snapshot and its
// comparison, the error checks, the test vertices and texels, and the calls that need an open
// window.
#include "bad_input_fixture.h"

#include <cstring>

namespace bad_input {

CallbackLog g_log;

void record_error(const char *string, FxBool fatal) {
  ++g_log.calls;
  g_log.message = string != nullptr ? string : "<NULL>";
  g_log.fatal = fatal;
}

void reset_errors() {
  g_log = CallbackLog{};
  glideShimClearError();
}

Snapshot capture() {
  const auto &c = current();
  return {c.initialized, c.color_path, c.blend, c.chroma, c.depth,
          c.raster,      c.tmu,        c.display, c.lfb};
}

#define EXPECT_FIELD(field) EXPECT_EQ(before.field, after.field) << "state field " #field " changed"
#define EXPECT_UNIT(field) EXPECT_TRUE(before.field == after.field) << "state field " #field " changed"

void expect_same_state(const Snapshot &before, const Snapshot &after) {
  EXPECT_FIELD(initialized);
  // Colour path.
  EXPECT_UNIT(color_path.color);
  EXPECT_UNIT(color_path.alpha);
  EXPECT_FIELD(color_path.constant_color);
  // Blend and alpha test.
  EXPECT_FIELD(blend.rgb_src);
  EXPECT_FIELD(blend.rgb_dst);
  EXPECT_FIELD(blend.alpha_src);
  EXPECT_FIELD(blend.alpha_dst);
  EXPECT_FIELD(blend.alpha_test_function);
  EXPECT_FIELD(blend.alpha_test_reference);
  // Chroma key.
  EXPECT_FIELD(chroma.mode);
  EXPECT_FIELD(chroma.value);
  // Depth.
  EXPECT_FIELD(depth.mode);
  EXPECT_FIELD(depth.function);
  EXPECT_FIELD(depth.mask);
  EXPECT_FIELD(depth.bias_level);
  // Raster.
  EXPECT_FIELD(raster.cull);
  EXPECT_FIELD(raster.dither);
  EXPECT_FIELD(raster.clip.min_x);
  EXPECT_FIELD(raster.clip.min_y);
  EXPECT_FIELD(raster.clip.max_x);
  EXPECT_FIELD(raster.clip.max_y);
  EXPECT_FIELD(raster.rgb_mask);
  EXPECT_FIELD(raster.alpha_mask);
  EXPECT_FIELD(raster.render_buffer);
  EXPECT_FIELD(raster.origin);
  EXPECT_FIELD(raster.stw_hint);
  // TMU.
  EXPECT_FIELD(tmu.clamp_s);
  EXPECT_FIELD(tmu.clamp_t);
  EXPECT_FIELD(tmu.min_filter);
  EXPECT_FIELD(tmu.mag_filter);
  EXPECT_FIELD(tmu.mipmap_mode);
  EXPECT_FIELD(tmu.lod_blend);
  EXPECT_FIELD(tmu.lod_bias);
  EXPECT_UNIT(tmu.combine);
  EXPECT_FIELD(tmu.source.valid);
  EXPECT_FIELD(tmu.source.address);
  EXPECT_FIELD(tmu.source.small_lod);
  EXPECT_FIELD(tmu.source.large_lod);
  EXPECT_FIELD(tmu.source.aspect);
  EXPECT_FIELD(tmu.source.format);
  EXPECT_FIELD(tmu.memory.size());
  EXPECT_TRUE(before.tmu.memory == after.tmu.memory) << "TMU memory bytes changed";
  // Display.
  EXPECT_FIELD(display.open);
  EXPECT_FIELD(display.width);
  EXPECT_FIELD(display.height);
  EXPECT_FIELD(display.color_format);
  EXPECT_FIELD(display.gamma);
  EXPECT_FIELD(display.swaps);
  EXPECT_FIELD(display.none_width);
  EXPECT_FIELD(display.none_height);
  // LFB locks.
  EXPECT_FIELD(lfb.read_locked);
  EXPECT_FIELD(lfb.write_locked);
  if (before.lfb.write_locked && after.lfb.write_locked) {
    EXPECT_FIELD(lfb.write_buffer);
    EXPECT_FIELD(lfb.write_origin);
  }
  EXPECT_TRUE(before.lfb.read_pixels == after.lfb.read_pixels) << "read-lock copy changed";
  EXPECT_TRUE(before.lfb.write_pixels == after.lfb.write_pixels) << "write-lock copy changed";
}

#undef EXPECT_FIELD
#undef EXPECT_UNIT

void expect_one_error(GlideShimError kind, const std::string &function) {
  const std::string message = glideShimGetLastErrorMessage();
  EXPECT_STREQ(glideShimErrorName(glideShimGetLastError()), glideShimErrorName(kind))
      << "message: " << message;
  EXPECT_EQ(g_log.calls, 1) << "callback calls for one bad call; message: " << message;
  EXPECT_NE(message.find(function), std::string::npos)
      << "the message does not name " << function << ": \"" << message << "\"";
  EXPECT_EQ(g_log.message, message) << "the callback received another message";
}

void expect_no_error_reported() {
  EXPECT_STREQ(glideShimErrorName(glideShimGetLastError()), "GLIDESHIM_OK")
      << glideShimGetLastErrorMessage();
  EXPECT_EQ(g_log.calls, 0) << g_log.message;
}

GrVertex make_vertex(float x, float y) {
  GrVertex v;
  std::memset(&v, 0, sizeof v);
  v.x = x, v.y = y;
  v.r = v.g = v.b = v.a = 255.0f;
  v.ooz = 1000.0f;
  v.oow = 0.5f;
  v.tmuvtx[0].oow = v.tmuvtx[1].oow = 0.5f;
  return v;
}

const GrVertex kA = make_vertex(8.0f, 8.0f);
const GrVertex kB = make_vertex(56.0f, 8.0f);
const GrVertex kC = make_vertex(8.0f, 56.0f);

std::vector<FxU8> &texel_source() {
  static std::vector<FxU8> bytes(512 * 1024, 0xAB);  // more than any mip-map chain
  return bytes;
}

GrTexInfo tex_info(GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                   GrTextureFormat_t format) {
  return {small_lod, large_lod, aspect, format, texel_source().data()};
}

std::vector<BadCall> BadInputTest::calls_needing_a_window() {
  static FxU16 word = 0;
  static std::vector<FxU8> texels(8 * 8 * 2, 0x11);
  const GrVertex a = kA, b = kB, c = kC;
  auto info = [] { return GrTexInfo{GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()}; };
  return {
      {"grDrawTriangle", [=] { grDrawTriangle(&a, &b, &c); }},
      {"grDrawLine", [=] { grDrawLine(&a, &b); }},
      {"grDrawPoint", [=] { grDrawPoint(&a); }},
      {"guDrawTriangleWithClip", [=] { guDrawTriangleWithClip(&a, &b, &c); }},
      {"grBufferClear", [] { grBufferClear(0xFFFFFFFFu, 0, 0); }},
      {"grBufferSwap", [] { grBufferSwap(0); }},
      {"grRenderBuffer", [] { grRenderBuffer(GR_BUFFER_FRONTBUFFER); }},
      {"grClipWindow", [] { grClipWindow(1, 1, 2, 2); }},
      {"grColorMask", [] { grColorMask(FXFALSE, FXTRUE); }},
      {"grLfbReadRegion",
       [] { EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 1, 1, 2, &word), FXFALSE); }},
      {"grLfbWriteRegion",
       [] {
         EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, 1, 1, 2, &word),
                   FXFALSE);
       }},
      {"grLfbLock",
       [] {
         GrLfbInfo_t lock{};
         lock.size = sizeof lock;
         EXPECT_EQ(grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_ANY,
                             GR_ORIGIN_UPPER_LEFT, FXFALSE, &lock),
                   FXFALSE);
       }},
      {"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER), FXFALSE); }},
      {"grDepthBufferMode", [] { grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER); }},
      {"grDepthBufferFunction", [] { grDepthBufferFunction(GR_CMP_GREATER); }},
      {"grDepthMask", [] { grDepthMask(FXTRUE); }},
      {"grDepthBiasLevel", [] { grDepthBiasLevel(12); }},
      {"grAlphaBlendFunction",
       [] { grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO); }},
      {"grAlphaTestFunction", [] { grAlphaTestFunction(GR_CMP_GREATER); }},
      {"grAlphaTestReferenceValue", [] { grAlphaTestReferenceValue(77); }},
      {"grChromakeyMode", [] { grChromakeyMode(GR_CHROMAKEY_ENABLE); }},
      {"grChromakeyValue", [] { grChromakeyValue(0x123456u); }},
      {"grDitherMode", [] { grDitherMode(GR_DITHER_2x2); }},
      {"grGammaCorrectionValue", [] { grGammaCorrectionValue(2.2f); }},
      {"grCullMode", [] { grCullMode(GR_CULL_NEGATIVE); }},
      {"grColorCombine",
       [] { grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_NONE, FXFALSE); }},
      {"grAlphaCombine",
       [] { grAlphaCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_NONE, FXFALSE); }},
      {"grTexCombine",
       [] { grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, FXFALSE, FXFALSE); }},
      {"grConstantColorValue", [] { grConstantColorValue(0x12345678u); }},
      {"grTexSource",
       [=] {
         GrTexInfo i = info();
         grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &i);
       }},
      {"grTexDownloadMipMap",
       [=] {
         GrTexInfo i = info();
         grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &i);
       }},
      {"grTexDownloadMipMapLevel",
       [] {
         grTexDownloadMipMapLevel(GR_TMU0, 0, GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565,
                                  GR_MIPMAPLEVELMASK_BOTH, texels.data());
       }},
      {"grTexClampMode", [] { grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP); }},
      {"grTexFilterMode",
       [] { grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR); }},
      {"grTexMipMapMode", [] { grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXTRUE); }},
      {"grTexLodBiasValue", [] { grTexLodBiasValue(GR_TMU0, 1.0f); }},
      {"grSstOrigin", [] { grSstOrigin(GR_ORIGIN_LOWER_LEFT); }},
      {"grHints", [] { grHints(GR_HINT_STWHINT, GR_STWHINT_W_DIFF_TMU0); }},
      {"grSstIdle", [] { grSstIdle(); }},
      {"glideShimFlush", [] { glideShimFlush(); }},
      {"glideShimWritePng",
       [] {
         const std::string path = ::testing::TempDir() + "bad_input_never_written.png";
         EXPECT_EQ(glideShimWritePng(GR_BUFFER_FRONTBUFFER, path.c_str()), FXFALSE);
       }},
  };
}

}  // namespace bad_input
