// Bad input to the Glide entry points. The rule under test (glide_shim.h): every entry point
// checks its arguments; a bad call reports exactly one error (a GlideShimError kind, with a
// message naming the function the program called), hands that message once to the
// grErrorSetCallback callback, changes no state (every group of glide_shim::current(), TMU
// memory, both colour buffers) and never crashes. Bad vertex data draws nothing; degenerate
// triangles are dropped without an error, as Glide drops them.
#include "context.h"
#include "glide_window.h"

#include <glideutl.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using glide_shim::current;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// ---- the error callback ------------------------------------------------------------------------

struct CallbackLog {
  int calls = 0;
  std::string message;
  FxBool fatal = FXFALSE;
};
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

// ---- state snapshots ---------------------------------------------------------------------------

// Every group of the context (copied), so a rejected call can be shown to have changed nothing.
struct Snapshot {
  bool initialized;
  glide_shim::ColorPathState color_path;
  glide_shim::BlendState blend;
  glide_shim::ChromaKeyState chroma;
  glide_shim::DepthState depth;
  glide_shim::RasterState raster;
  glide_shim::TmuState tmu;
  glide_shim::DisplayState display;
  glide_shim::LfbLockState lfb;
};

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

// Exactly one error of `kind` reported since reset_errors(), naming `function`, and the same
// message handed once to the callback.
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

// A bad call: the function the program calls, and the call itself (which checks the return).
struct BadCall {
  std::string function;
  std::function<void()> call;
};

// ---- vertices ----------------------------------------------------------------------------------

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

// A triangle covering pixel (16,16); lines and points are drawn through the same pixel.
const GrVertex kA = make_vertex(8.0f, 8.0f);
const GrVertex kB = make_vertex(56.0f, 8.0f);
const GrVertex kC = make_vertex(8.0f, 56.0f);
constexpr int kProbeX = 16, kProbeY = 16;

using Spoil = std::function<void(GrVertex &)>;

// Every draw entry point, with `spoil` applied to the vertex at each position in turn.
std::vector<BadCall> draws_with(const Spoil &spoil) {
  std::vector<BadCall> calls;
  for (int position = 0; position < 3; ++position) {
    GrVertex v[3] = {kA, kB, kC};
    spoil(v[position]);
    calls.push_back({"grDrawTriangle", [=] { grDrawTriangle(&v[0], &v[1], &v[2]); }});
    calls.push_back({"guDrawTriangleWithClip", [=] { guDrawTriangleWithClip(&v[0], &v[1], &v[2]); }});
  }
  for (int position = 0; position < 2; ++position) {
    GrVertex v[2] = {make_vertex(2.0f, 16.5f), make_vertex(60.0f, 16.5f)};
    spoil(v[position]);
    calls.push_back({"grDrawLine", [=] { grDrawLine(&v[0], &v[1]); }});
  }
  GrVertex p = make_vertex(16.25f, 16.25f);
  spoil(p);
  calls.push_back({"grDrawPoint", [=] { grDrawPoint(&p); }});
  return calls;
}

// ---- texture descriptions ----------------------------------------------------------------------

std::vector<FxU8> &texel_source() {
  static std::vector<FxU8> bytes(512 * 1024, 0xAB);  // more than any mip-map chain
  return bytes;
}

GrTexInfo tex_info(GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                   GrTextureFormat_t format) {
  return {small_lod, large_lod, aspect, format, texel_source().data()};
}

// Every entry point that takes a texture description, given `info` and `address`.
std::vector<BadCall> texture_calls(const GrTexInfo &info, FxU32 address) {
  std::vector<BadCall> calls;
  calls.push_back({"grTexSource", [=] {
                     GrTexInfo copy = info;
                     grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &copy);
                   }});
  calls.push_back({"grTexDownloadMipMap", [=] {
                     GrTexInfo copy = info;
                     grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &copy);
                   }});
  calls.push_back({"grTexDownloadMipMapLevel", [=] {
                     grTexDownloadMipMapLevel(GR_TMU0, address, info.smallLod, info.largeLod,
                                              info.aspectRatio, info.format,
                                              GR_MIPMAPLEVELMASK_BOTH, info.data);
                   }});
  return calls;
}

// The two size queries, which must answer 0 for a bad description.
std::vector<BadCall> size_calls(const GrTexInfo &info) {
  return {
      {"grTexCalcMemRequired",
       [=] {
         EXPECT_EQ(grTexCalcMemRequired(info.smallLod, info.largeLod, info.aspectRatio, info.format),
                   0u);
       }},
      {"grTexTextureMemRequired",
       [=] {
         GrTexInfo copy = info;
         EXPECT_EQ(grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &copy), 0u);
       }},
  };
}

// ---- the fixture -------------------------------------------------------------------------------

class BadInputTest : public GlideWindowTest {
 protected:
  static constexpr GrColor_t kFrontColor = 0x00336699u;  // ARGB; neither is white
  static constexpr GrColor_t kBackColor = 0x00204080u;

  void SetUp() override {
    GlideWindowTest::SetUp();
    grErrorSetCallback(record_error);
    grDitherMode(GR_DITHER_DISABLE);
    // Different front and back buffers, so a swap or a write to either one would show.
    grBufferClear(kFrontColor, 0, 0);
    grBufferSwap(0);
    grBufferClear(kBackColor, 0, 0);
    expect_no_error();
    reset_errors();
  }

  // `call` must be rejected with exactly one error of `kind` naming `call.function`, leave every
  // state group unchanged and (with a window open) write no pixel to either colour buffer.
  void expect_rejected(GlideShimError kind, const BadCall &call, const std::string &what = "") {
    SCOPED_TRACE(call.function + (what.empty() ? "" : " (" + what + ")"));
    const bool open = current().display.open;
    std::vector<FxU16> front, back;
    if (open) {
      front = read_buffer(GR_BUFFER_FRONTBUFFER);
      back = read_buffer(GR_BUFFER_BACKBUFFER);
      glideShimResetPixelsWritten();
    }
    const Snapshot before = capture();
    reset_errors();
    call.call();
    expect_one_error(kind, call.function);
    expect_same_state(before, capture());
    if (open) {
      EXPECT_EQ(glideShimPixelsWritten(), 0u) << "pixels were drawn";
      EXPECT_TRUE(read_buffer(GR_BUFFER_FRONTBUFFER) == front) << "the front buffer changed";
      EXPECT_TRUE(read_buffer(GR_BUFFER_BACKBUFFER) == back) << "the back buffer changed";
    }
    reset_errors();
  }

  void expect_all_rejected(GlideShimError kind, const std::vector<BadCall> &calls,
                           const std::string &what = "") {
    for (const BadCall &call : calls) expect_rejected(kind, call, what);
  }

  // `call` draws without any error: the probe pixel becomes `expected` (565).
  void expect_drawn(const BadCall &call, FxU16 expected, const std::string &what) {
    SCOPED_TRACE(call.function + " (" + what + ")");
    grBufferClear(kBackColor, 0, 0);
    ASSERT_NE(pixel(kProbeX, kProbeY), expected);
    glideShimResetPixelsWritten();
    reset_errors();
    call.call();
    EXPECT_GT(glideShimPixelsWritten(), 0u) << "nothing was drawn";
    expect_no_error_reported();
    EXPECT_EQ(pixel(kProbeX, kProbeY), expected);
    reset_errors();
  }

  // Calls that need an open window, each harmless with one open.
  static std::vector<BadCall> calls_needing_a_window() {
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
        {"glideShimWritePng",
         [] {
           const std::string path = ::testing::TempDir() + "bad_input_never_written.png";
           EXPECT_EQ(glideShimWritePng(GR_BUFFER_FRONTBUFFER, path.c_str()), FXFALSE);
         }},
    };
  }
};

// ---- calls without a library or a window -------------------------------------------------------

TEST_F(BadInputTest, CallsBeforeGrGlideInitAreNotInitialized) {
  grGlideShutdown();
  reset_errors();
  std::vector<BadCall> calls = calls_needing_a_window();
  calls.push_back({"grSstWinOpen", [] {
                     EXPECT_EQ(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                                            GR_ORIGIN_UPPER_LEFT, 2, 1),
                               FXFALSE);
                   }});
  calls.push_back({"grSstQueryHardware", [] {
                     GrHwConfiguration hw;
                     EXPECT_EQ(grSstQueryHardware(&hw), FXFALSE);
                   }});
  expect_all_rejected(GLIDESHIM_ERR_NOT_INITIALIZED, calls, "before grGlideInit");
}

TEST_F(BadInputTest, CallsBeforeGrSstWinOpenAreNotInitialized) {
  grGlideShutdown();
  grGlideInit();
  reset_errors();
  expect_all_rejected(GLIDESHIM_ERR_NOT_INITIALIZED, calls_needing_a_window(), "before grSstWinOpen");
}

TEST_F(BadInputTest, CallsAfterGrSstWinCloseAreNotInitialized) {
  grSstWinClose();
  reset_errors();
  expect_all_rejected(GLIDESHIM_ERR_NOT_INITIALIZED, calls_needing_a_window(), "after grSstWinClose");
  // Closing again is harmless and reports nothing.
  grSstWinClose();
  expect_no_error_reported();
}

// The gu presets forward to gr* entry points; a rejected preset must still name the function
// the program called, not the one it forwards to.
TEST_F(BadInputTest, RejectedGuPresetsNameThePresetCalled) {
  expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                  {"guTexCombineFunction", [] { guTexCombineFunction(GR_TMU1, GR_TEXTURECOMBINE_DECAL); }},
                  "TMU1");
  grSstWinClose();
  reset_errors();
  expect_all_rejected(
      GLIDESHIM_ERR_NOT_INITIALIZED,
      {{"guColorCombineFunction", [] { guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE); }},
       {"guAlphaSource", [] { guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA); }},
       {"guTexCombineFunction", [] { guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL); }}},
      "no window");
}

// ---- unknown enums, chapter by chapter ---------------------------------------------------------

TEST_F(BadInputTest, UnknownDepthEnumsAreInvalidEnum) {
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grDepthBufferMode", [] { grDepthBufferMode(5); }},
       {"grDepthBufferMode", [] { grDepthBufferMode(-1); }},
       {"grDepthBufferMode", [] { grDepthBufferMode(0x100); }},
       {"grDepthBufferFunction", [] { grDepthBufferFunction(8); }},
       {"grDepthBufferFunction", [] { grDepthBufferFunction(-1); }}});
}

TEST_F(BadInputTest, UnknownPixelOperationEnumsAreInvalidEnum) {
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grAlphaBlendFunction", [] { grAlphaBlendFunction(GR_BLEND_RESERVED_8, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO); }},
       {"grAlphaBlendFunction", [] { grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_RESERVED_E, GR_BLEND_ONE, GR_BLEND_ZERO); }},
       {"grAlphaBlendFunction", [] { grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ZERO, -1, GR_BLEND_ZERO); }},
       {"grAlphaBlendFunction", [] { grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ZERO, GR_BLEND_ONE, 0x10); }},
       {"grAlphaTestFunction", [] { grAlphaTestFunction(8); }},
       {"grAlphaTestFunction", [] { grAlphaTestFunction(-1); }},
       {"grChromakeyMode", [] { grChromakeyMode(2); }},
       {"grDitherMode", [] { grDitherMode(3); }},
       {"grDitherMode", [] { grDitherMode(-1); }},
       {"grCullMode", [] { grCullMode(3); }},
       {"grCullMode", [] { grCullMode(-1); }}});
}

TEST_F(BadInputTest, UnknownCombineEnumsAreInvalidEnum) {
  using Combine = void (*)(GrCombineFunction_t, GrCombineFactor_t, GrCombineLocal_t, GrCombineOther_t, FxBool);
  const std::pair<const char *, Combine> units[] = {{"grColorCombine", grColorCombine},
                                                    {"grAlphaCombine", grAlphaCombine}};
  for (const auto &unit : units) {
    const Combine f = unit.second;
    const std::string name = unit.first;
    // Bad function (0xa..0xf and 0x11 are gaps in Glide's list).
    for (int function : {0xa, 0xf, 0x11, -1}) {
      expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                      {name, [=] { f(function, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED, FXFALSE); }},
                      "function " + std::to_string(function));
    }
    // Bad factor (6, 7 and 0xe are gaps; 0x10 is past the end).
    for (int factor : {6, 7, 0xe, 0x10, -1}) {
      expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                      {name, [=] { f(GR_COMBINE_FUNCTION_SCALE_OTHER, factor, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED, FXFALSE); }},
                      "factor " + std::to_string(factor));
    }
    // Bad local.
    for (int local : {3, -1}) {
      expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                      {name, [=] { f(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, local, GR_COMBINE_OTHER_ITERATED, FXFALSE); }},
                      "local " + std::to_string(local));
    }
    // Bad other.
    for (int other : {3, -1}) {
      expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                      {name, [=] { f(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_ITERATED, other, FXFALSE); }},
                      "other " + std::to_string(other));
    }
  }
  // GR_COMBINE_LOCAL_DEPTH exists only for the alpha unit.
  expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                  {"grColorCombine", [] { grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_DEPTH, GR_COMBINE_OTHER_NONE, FXFALSE); }},
                  "local DEPTH in the colour unit");
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grTexCombine", [] { grTexCombine(GR_TMU0, 0xb, GR_COMBINE_FACTOR_ONE, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ONE, FXFALSE, FXFALSE); }},
       {"grTexCombine", [] { grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, 6, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ONE, FXFALSE, FXFALSE); }},
       {"grTexCombine", [] { grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ONE, 0x11, GR_COMBINE_FACTOR_ONE, FXFALSE, FXFALSE); }},
       {"grTexCombine", [] { grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ONE, GR_COMBINE_FUNCTION_LOCAL, 0xe, FXFALSE, FXFALSE); }}});
}

TEST_F(BadInputTest, UnknownGuPresetsAreInvalidEnum) {
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"guColorCombineFunction", [] { guColorCombineFunction(GR_COLORCOMBINE_ONE + 1); }},
       {"guColorCombineFunction", [] { guColorCombineFunction(-1); }},
       {"guTexCombineFunction", [] { guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_ONE + 1); }},
       {"guTexCombineFunction", [] { guTexCombineFunction(GR_TMU0, -1); }},
       {"guAlphaSource", [] { guAlphaSource(GR_ALPHASOURCE_TEXTURE_ALPHA_TIMES_ITERATED_ALPHA + 1); }},
       {"guAlphaSource", [] { guAlphaSource(-1); }}});
}

TEST_F(BadInputTest, UnknownTextureStateEnumsAreInvalidEnum) {
  GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grTexClampMode", [] { grTexClampMode(GR_TMU0, 2, GR_TEXTURECLAMP_WRAP); }},
       {"grTexClampMode", [] { grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, -1); }},
       {"grTexFilterMode", [] { grTexFilterMode(GR_TMU0, 2, GR_TEXTUREFILTER_BILINEAR); }},
       {"grTexFilterMode", [] { grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, 5); }},
       {"grTexMipMapMode", [] { grTexMipMapMode(GR_TMU0, 3, FXFALSE); }},
       {"grTexMipMapMode", [] { grTexMipMapMode(GR_TMU0, -1, FXTRUE); }},
       {"grTexSource", [=]() mutable { grTexSource(GR_TMU0, 0, 0, &info); }},
       {"grTexSource", [=]() mutable { grTexSource(GR_TMU0, 0, 4, &info); }},
       {"grTexDownloadMipMap", [=]() mutable { grTexDownloadMipMap(GR_TMU0, 0, 0, &info); }},
       {"grTexTextureMemRequired", [=]() mutable { EXPECT_EQ(grTexTextureMemRequired(8, &info), 0u); }}});
}

TEST_F(BadInputTest, UnknownBufferAndOriginEnumsAreInvalidEnum) {
  static FxU16 words[4] = {0, 0, 0, 0};
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grRenderBuffer", [] { grRenderBuffer(GR_BUFFER_AUXBUFFER); }},
       {"grRenderBuffer", [] { grRenderBuffer(7); }},
       {"grSstOrigin", [] { grSstOrigin(2); }},
       {"grSstOrigin", [] { grSstOrigin(GR_ORIGIN_ANY); }},
       {"grHints", [] { grHints(GR_HINTTYPE_MAX + 1, 0); }},
       {"grLfbReadRegion", [] { EXPECT_EQ(grLfbReadRegion(7, 0, 0, 1, 1, 2, words), FXFALSE); }},
       {"grLfbWriteRegion", [] { EXPECT_EQ(grLfbWriteRegion(7, 0, 0, GR_LFB_SRC_FMT_565, 1, 1, 2, words), FXFALSE); }},
       {"grLfbLock",
        [] {
          GrLfbInfo_t lock{};
          lock.size = sizeof lock;
          EXPECT_EQ(grLfbLock(GR_LFB_READ_ONLY, 7, GR_LFBWRITEMODE_ANY, GR_ORIGIN_UPPER_LEFT, FXFALSE, &lock), FXFALSE);
        }},
       {"grLfbLock",
        [] {
          GrLfbInfo_t lock{};
          lock.size = sizeof lock;
          EXPECT_EQ(grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_ANY, 2, FXFALSE, &lock), FXFALSE);
        }},
       {"grLfbLock",
        [] {
          GrLfbInfo_t lock{};
          lock.size = sizeof lock;
          EXPECT_EQ(grLfbLock(0x2, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_ANY, GR_ORIGIN_UPPER_LEFT, FXFALSE, &lock), FXFALSE);
        }}});
}

// Values Glide 2.x does not define at all are INVALID_ENUM; UNSUPPORTED is only for values
// Glide defines but the shim does not implement yet.
TEST_F(BadInputTest, UndefinedLfbFormatsAreInvalidEnumNotUnsupported) {
  static FxU16 words[4] = {0, 0, 0, 0};
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grLfbWriteRegion", [] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, 3, 1, 1, 2, words), FXFALSE); }},
       {"grLfbWriteRegion", [] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, 0x42, 1, 1, 2, words), FXFALSE); }},
       {"grLfbLock",
        [] {
          GrLfbInfo_t lock{};
          lock.size = sizeof lock;
          EXPECT_EQ(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, 0x42, GR_ORIGIN_UPPER_LEFT, FXFALSE, &lock), FXFALSE);
        }}},
      "undefined format");
  // Defined but not implemented.
  expect_all_rejected(
      GLIDESHIM_ERR_UNSUPPORTED,
      {{"grLfbWriteRegion", [] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_RLE16, 1, 1, 2, words), FXFALSE); }}},
      "defined, not implemented");
}

TEST_F(BadInputTest, UnknownWinOpenEnumsAreInvalidEnum) {
  grSstWinClose();
  reset_errors();
  auto open = [](GrScreenResolution_t resolution, GrColorFormat_t format, GrOriginLocation_t origin) {
    return [=] {
      EXPECT_EQ(grSstWinOpen(0, resolution, GR_REFRESH_60Hz, format, origin, 2, 1), FXFALSE);
    };
  };
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grSstWinOpen", open(GR_RESOLUTION_400x300 + 1, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(-1, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(0xfe, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(GR_RESOLUTION_NONE, 4, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(GR_RESOLUTION_NONE, -1, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(GR_RESOLUTION_NONE, GR_COLORFORMAT_ARGB, 2)},
       {"grSstWinOpen", open(GR_RESOLUTION_NONE, GR_COLORFORMAT_ARGB, GR_ORIGIN_ANY)}});
  EXPECT_FALSE(current().display.open);
  // A good open still works afterwards, and a second open while one is open is refused.
  EXPECT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1));
  expect_no_error_reported();
  expect_rejected(GLIDESHIM_ERR_INCONSISTENT,
                  {"grSstWinOpen", open(GR_RESOLUTION_NONE, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT)},
                  "already open");
}

// ---- NULL pointers -----------------------------------------------------------------------------

TEST_F(BadInputTest, NullPointersAreRejected) {
  const GrVertex a = kA, b = kB, c = kC;
  GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  GrTexInfo no_data = info;
  no_data.data = nullptr;
  expect_all_rejected(
      GLIDESHIM_ERR_NULL_POINTER,
      {{"grDrawTriangle", [=] { grDrawTriangle(nullptr, &b, &c); }},
       {"grDrawTriangle", [=] { grDrawTriangle(&a, nullptr, &c); }},
       {"grDrawTriangle", [=] { grDrawTriangle(&a, &b, nullptr); }},
       {"guDrawTriangleWithClip", [=] { guDrawTriangleWithClip(nullptr, &b, &c); }},
       {"guDrawTriangleWithClip", [=] { guDrawTriangleWithClip(&a, nullptr, &c); }},
       {"guDrawTriangleWithClip", [=] { guDrawTriangleWithClip(&a, &b, nullptr); }},
       {"grDrawLine", [=] { grDrawLine(nullptr, &b); }},
       {"grDrawLine", [=] { grDrawLine(&a, nullptr); }},
       {"grDrawPoint", [] { grDrawPoint(nullptr); }},
       {"grTexSource", [] { grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, nullptr); }},
       {"grTexDownloadMipMap", [] { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, nullptr); }},
       {"grTexDownloadMipMap", [=]() mutable { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &no_data); }},
       {"grTexDownloadMipMapLevel",
        [] { grTexDownloadMipMapLevel(GR_TMU0, 0, GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, nullptr); }},
       {"grTexTextureMemRequired", [] { EXPECT_EQ(grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, nullptr), 0u); }},
       {"grLfbReadRegion", [] { EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 1, 1, 2, nullptr), FXFALSE); }},
       {"grLfbWriteRegion",
        [] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, 1, 1, 2, nullptr), FXFALSE); }},
       {"grLfbLock",
        [] { EXPECT_EQ(grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_ANY, GR_ORIGIN_UPPER_LEFT, FXFALSE, nullptr), FXFALSE); }},
       {"grLfbLock",
        [] { EXPECT_EQ(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, nullptr), FXFALSE); }},
       {"grSstQueryHardware", [] { EXPECT_EQ(grSstQueryHardware(nullptr), FXFALSE); }},
       {"grSstQueryBoards", [] { EXPECT_EQ(grSstQueryBoards(nullptr), FXFALSE); }},
       {"grGlideGetVersion", [] { grGlideGetVersion(nullptr); }}});
}

// ---- texture descriptions ----------------------------------------------------------------------

TEST_F(BadInputTest, SmallLodLargerThanLargeLodIsInconsistent) {
  // smallLod must be >= largeLod (GR_LOD_256 = 0 is the largest level).
  const GrTexInfo reversed = tex_info(GR_LOD_256, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  expect_all_rejected(GLIDESHIM_ERR_INCONSISTENT, texture_calls(reversed, 0), "256 < 1");
  expect_all_rejected(GLIDESHIM_ERR_INCONSISTENT, size_calls(reversed), "256 < 1");
  const GrTexInfo off_by_one = tex_info(GR_LOD_32, GR_LOD_16, GR_ASPECT_2x1, GR_TEXFMT_ALPHA_8);
  expect_all_rejected(GLIDESHIM_ERR_INCONSISTENT, texture_calls(off_by_one, 0), "32 < 16");
  expect_all_rejected(GLIDESHIM_ERR_INCONSISTENT, size_calls(off_by_one), "32 < 16");
}

TEST_F(BadInputTest, LodOutsideTheTableIsInvalidEnum) {
  const std::pair<int, int> cases[] = {{9, GR_LOD_1}, {GR_LOD_1, -1}, {-1, -1}, {9, 9},
                                       {GR_LOD_256, -1}, {0x100, GR_LOD_256}};
  for (const auto &lods : cases) {
    const GrTexInfo info = tex_info(lods.first, lods.second, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
    const std::string what = "small " + std::to_string(lods.first) + " large " + std::to_string(lods.second);
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, texture_calls(info, 0), what);
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, size_calls(info), what);
  }
}

TEST_F(BadInputTest, UnknownAspectIsInvalidEnum) {
  for (int aspect : {GR_ASPECT_1x8 + 1, -1, 0x10}) {
    const GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, aspect, GR_TEXFMT_RGB_565);
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, texture_calls(info, 0), "aspect " + std::to_string(aspect));
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, size_calls(info), "aspect " + std::to_string(aspect));
  }
}

TEST_F(BadInputTest, ReservedTextureFormatsAreInvalidEnum) {
  for (int format : {GR_TEXFMT_RSVD0, GR_TEXFMT_RSVD1, GR_TEXFMT_RSVD2, 0x10, -1}) {
    const GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, format);
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, texture_calls(info, 0), "format " + std::to_string(format));
    expect_all_rejected(GLIDESHIM_ERR_INVALID_ENUM, size_calls(info), "format " + std::to_string(format));
  }
}

TEST_F(BadInputTest, PaletteAndNccFormatsAreAccepted) {
  // They read through grTexDownloadTable's tables (tests/numeric/texture_formats_test.cpp).
  for (int format : {GR_TEXFMT_YIQ_422, GR_TEXFMT_P_8, GR_TEXFMT_AYIQ_8422, GR_TEXFMT_AP_88}) {
    const GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, format);
    for (const BadCall &call : texture_calls(info, 0)) {
      call.call();
      SCOPED_TRACE(call.function + " format " + std::to_string(format));
      expect_no_error_reported();
    }
  }
}

TEST_F(BadInputTest, StartAddressNotEightByteAlignedIsOutOfRange) {
  const GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  for (FxU32 address : {1u, 4u, 7u, 0x1000u + 2u}) {
    expect_all_rejected(GLIDESHIM_ERR_OUT_OF_RANGE, texture_calls(info, address),
                        "address " + std::to_string(address));
  }
}

TEST_F(BadInputTest, TextureRunningPastTmuMemoryIsOutOfRange) {
  const FxU32 max = grTexMaxAddress(GR_TMU0);
  expect_no_error_reported();
  // 256x256 565 = 131072 bytes cannot start at the highest start address, nor anywhere its end
  // passes the 2 MB of TMU memory.
  const GrTexInfo big = tex_info(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  const FxU32 tmu_bytes = 2u * 1024u * 1024u;
  for (FxU32 address : {max, tmu_bytes - 131072u + 8u, tmu_bytes, 0xFFFFFFF8u, 0x80000000u}) {
    expect_all_rejected(GLIDESHIM_ERR_OUT_OF_RANGE, texture_calls(big, address),
                        "256x256 565 at " + std::to_string(address));
  }
  // A whole chain 256..1 (174768 bytes) just past the end.
  const GrTexInfo chain = tex_info(GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  expect_all_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                      {texture_calls(chain, tmu_bytes - 174768u + 8u)[0],
                       texture_calls(chain, tmu_bytes - 174768u + 8u)[1]},
                      "chain past the end");
  // The smallest texture (8 bytes after rounding) fits exactly at the highest start address;
  // 8 bytes further it does not.
  const GrTexInfo tiny = tex_info(GR_LOD_1, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  expect_all_rejected(GLIDESHIM_ERR_OUT_OF_RANGE, texture_calls(tiny, max + 8u), "1x1 after max");
  reset_errors();
  GrTexInfo copy = tiny;
  grTexDownloadMipMap(GR_TMU0, max, GR_MIPMAPLEVELMASK_BOTH, &copy);
  grTexSource(GR_TMU0, max, GR_MIPMAPLEVELMASK_BOTH, &copy);
  expect_no_error_reported();
  EXPECT_EQ(current().tmu.source.address, max);
}

TEST_F(BadInputTest, TmuOtherThanTmu0IsOutOfRange) {
  GrTexInfo info = tex_info(GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  for (GrChipID_t tmu : {GR_TMU1, GR_TMU2, GR_FBI, -1}) {
    expect_all_rejected(
        GLIDESHIM_ERR_OUT_OF_RANGE,
        {{"grTexSource", [=]() mutable { grTexSource(tmu, 0, GR_MIPMAPLEVELMASK_BOTH, &info); }},
         {"grTexDownloadMipMap", [=]() mutable { grTexDownloadMipMap(tmu, 0, GR_MIPMAPLEVELMASK_BOTH, &info); }},
         {"grTexDownloadMipMapLevel",
          [=] { grTexDownloadMipMapLevel(tmu, 0, GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, info.data); }},
         {"grTexClampMode", [=] { grTexClampMode(tmu, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP); }},
         {"grTexFilterMode", [=] { grTexFilterMode(tmu, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR); }},
         {"grTexMipMapMode", [=] { grTexMipMapMode(tmu, GR_MIPMAP_NEAREST, FXFALSE); }},
         {"grTexLodBiasValue", [=] { grTexLodBiasValue(tmu, 1.0f); }},
         {"grTexCombine",
          [=] { grTexCombine(tmu, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, FXFALSE, FXFALSE); }},
         {"grTexMinAddress", [=] { EXPECT_EQ(grTexMinAddress(tmu), 0u); }},
         {"grTexMaxAddress", [=] { EXPECT_EQ(grTexMaxAddress(tmu), 0u); }}},
        "TMU " + std::to_string(tmu));
  }
}

TEST_F(BadInputTest, RejectedDownloadLeavesTmuMemoryUnchanged) {
  // Put a known pattern at the start and the end of TMU memory first.
  const FxU32 tmu_bytes = 2u * 1024u * 1024u;
  std::vector<FxU8> pattern(131072);
  for (std::size_t i = 0; i < pattern.size(); ++i) pattern[i] = static_cast<FxU8>(i * 7 + 3);
  GrTexInfo good{GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, pattern.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &good);
  grTexDownloadMipMap(GR_TMU0, tmu_bytes - 131072u, GR_MIPMAPLEVELMASK_BOTH, &good);
  expect_no_error_reported();
  const std::vector<FxU8> memory = current().tmu.memory;
  ASSERT_EQ(memory.size(), tmu_bytes);
  ASSERT_EQ(memory[0], pattern[0]);
  ASSERT_EQ(memory[tmu_bytes - 1], pattern.back());

  // Rejected downloads of 0xAB bytes over both patterns.
  GrTexInfo big = tex_info(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  GrTexInfo chain = tex_info(GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  GrTexInfo reversed = tex_info(GR_LOD_256, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565);
  GrTexInfo reserved = tex_info(GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RSVD2);
  const std::vector<std::pair<GlideShimError, BadCall>> calls = {
      {GLIDESHIM_ERR_OUT_OF_RANGE, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, tmu_bytes - 65536u, GR_MIPMAPLEVELMASK_BOTH, &big); }}},
      // Only the odd levels (128, 32, 8, 2) run past the end: 34952 bytes from 2 MB - 32768.
      {GLIDESHIM_ERR_OUT_OF_RANGE, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, tmu_bytes - 32768u, GR_MIPMAPLEVELMASK_ODD, &chain); }}},
      {GLIDESHIM_ERR_OUT_OF_RANGE, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, 4, GR_MIPMAPLEVELMASK_BOTH, &big); }}},
      {GLIDESHIM_ERR_OUT_OF_RANGE, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU1, 0, GR_MIPMAPLEVELMASK_BOTH, &big); }}},
      {GLIDESHIM_ERR_INCONSISTENT, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &reversed); }}},
      {GLIDESHIM_ERR_INVALID_ENUM, {"grTexDownloadMipMap", [&] { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &reserved); }}},
      // Rows 200..256 of a 256-row level: the last row does not exist.
      {GLIDESHIM_ERR_OUT_OF_RANGE,
       {"grTexDownloadMipMapLevelPartial",
        [&] { grTexDownloadMipMapLevelPartial(GR_TMU0, 0, GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, big.data, 200, 256); }}},
      {GLIDESHIM_ERR_OUT_OF_RANGE,
       {"grTexDownloadMipMapLevel",
        [&] { grTexDownloadMipMapLevel(GR_TMU0, tmu_bytes - 8u, GR_LOD_256, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, big.data); }}},
      // Level 1x1 of a chain whose offset alone (174760 bytes) passes the end.
      {GLIDESHIM_ERR_OUT_OF_RANGE,
       {"grTexDownloadMipMapLevel",
        [&] { grTexDownloadMipMapLevel(GR_TMU0, tmu_bytes - 8u, GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, big.data); }}},
  };
  for (const auto &call : calls) {
    expect_rejected(call.first, call.second);
    ASSERT_TRUE(current().tmu.memory == memory) << "TMU memory changed by a rejected "
                                                << call.second.function;
  }
}

// ---- regions -----------------------------------------------------------------------------------

struct Region {
  FxU32 x, y, w, h;
};

const Region kBadRegions[] = {
    {0, 0, 0, 1},                  // width 0
    {0, 0, 1, 0},                  // height 0
    {0, 0, 0, 0},
    {64, 0, 1, 1},                 // starts just right of the buffer
    {0, 64, 1, 1},                 // starts just below it
    {63, 0, 2, 1},                 // runs one pixel past the right edge
    {0, 63, 1, 2},                 // one past the bottom
    {0, 0, 65, 64},
    {0xFFFFFFFFu, 0, 2, 1},        // x + width wraps to 1
    {1, 0, 0xFFFFFFFFu, 1},        // x + width wraps to 0
    {0, 0xFFFFFFFFu, 1, 2},        // y + height wraps to 1
    {0, 1, 1, 0xFFFFFFFFu},
    {0x80000000u, 0, 0x80000000u, 1},
    {0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu},
};

std::string describe(const Region &r) {
  return std::to_string(r.w) + "x" + std::to_string(r.h) + " at (" + std::to_string(r.x) + "," +
         std::to_string(r.y) + ")";
}

TEST_F(BadInputTest, LfbReadRegionOutsideTheBufferIsOutOfRange) {
  std::vector<FxU16> dst(4 * kWidth * kHeight, 0xBEEF);
  for (const Region &r : kBadRegions) {
    for (GrBuffer_t buffer : {GR_BUFFER_FRONTBUFFER, GR_BUFFER_BACKBUFFER, GR_BUFFER_AUXBUFFER}) {
      expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                      {"grLfbReadRegion",
                       [&] { EXPECT_EQ(grLfbReadRegion(buffer, r.x, r.y, r.w, r.h, 4 * kWidth, dst.data()), FXFALSE); }},
                      describe(r) + " of buffer " + std::to_string(buffer));
    }
  }
  // A stride shorter than one row of 16-bit pixels.
  expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                  {"grLfbReadRegion", [&] { EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 4, 1, 7, dst.data()), FXFALSE); }},
                  "stride 7 for width 4");
  expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                  {"grLfbReadRegion", [&] { EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 64, 2, 126, dst.data()), FXFALSE); }},
                  "stride 126 for width 64");
  expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                  {"grLfbReadRegion", [&] { EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 1, 1, 0, dst.data()), FXFALSE); }},
                  "stride 0");
  for (FxU16 word : dst) ASSERT_EQ(word, 0xBEEF) << "a rejected read wrote into the destination";
  // The regions at the very edges are accepted.
  for (const Region &r : {Region{63, 63, 1, 1}, Region{0, 0, 64, 64}, Region{0, 63, 64, 1}}) {
    reset_errors();
    EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, r.x, r.y, r.w, r.h, 2 * r.w, dst.data()), FXTRUE)
        << describe(r);
    expect_no_error_reported();
  }
}

TEST_F(BadInputTest, LfbWriteRegionOutsideTheBufferIsOutOfRange) {
  std::vector<FxU32> src(4 * kWidth * kHeight, 0xFFFFFFFFu);  // white in every source format
  for (const Region &r : kBadRegions) {
    for (GrLfbSrcFmt_t format : {GR_LFB_SRC_FMT_565, GR_LFB_SRC_FMT_8888}) {
      for (GrBuffer_t buffer : {GR_BUFFER_FRONTBUFFER, GR_BUFFER_BACKBUFFER}) {
        expect_rejected(
            GLIDESHIM_ERR_OUT_OF_RANGE,
            {"grLfbWriteRegion",
             [&] { EXPECT_EQ(grLfbWriteRegion(buffer, r.x, r.y, format, r.w, r.h, 16 * kWidth, src.data()), FXFALSE); }},
            describe(r) + " format " + std::to_string(format) + " buffer " + std::to_string(buffer));
      }
    }
  }
  // Strides shorter than one row.
  expect_all_rejected(
      GLIDESHIM_ERR_OUT_OF_RANGE,
      {{"grLfbWriteRegion", [&] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, 4, 2, 7, src.data()), FXFALSE); }},
       {"grLfbWriteRegion", [&] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_1555, 64, 2, 126, src.data()), FXFALSE); }},
       {"grLfbWriteRegion", [&] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_888, 4, 2, 15, src.data()), FXFALSE); }},
       {"grLfbWriteRegion", [&] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_8888, 4, 2, 8, src.data()), FXFALSE); }}},
      "stride too small");
  // The edge region is accepted and writes white.
  reset_errors();
  EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 63, 63, GR_LFB_SRC_FMT_565, 1, 1, 2, src.data()), FXTRUE);
  expect_no_error_reported();
  EXPECT_EQ(pixel(63, 63), 0xFFFF);
}

TEST_F(BadInputTest, ClipWindowOutsideTheScreenOrInvertedIsOutOfRange) {
  grClipWindow(4, 5, 60, 61);  // a non-default window, so a reset to full screen would show
  expect_no_error();
  const Region bad[] = {
      {0, 0, 65, 64},  {0, 0, 64, 65},  {10, 0, 5, 64}, {0, 10, 64, 5},
      {65, 0, 66, 64}, {0, 0, 0xFFFFFFFFu, 64}, {0xFFFFFFFFu, 0, 64, 64}, {0, 0xFFFFFFFFu, 64, 64},
  };
  for (const Region &r : bad) {  // here {x, y, w, h} hold minx, miny, maxx, maxy
    expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                    {"grClipWindow", [&] { grClipWindow(r.x, r.y, r.w, r.h); }},
                    "(" + std::to_string(r.x) + "," + std::to_string(r.y) + ")-(" +
                        std::to_string(r.w) + "," + std::to_string(r.h) + ")");
  }
  // The full screen and an empty window are valid.
  reset_errors();
  grClipWindow(0, 0, 64, 64);
  grClipWindow(7, 7, 7, 7);
  expect_no_error_reported();
  EXPECT_EQ(current().raster.clip.max_x, 7u);
}

// ---- vertex values -----------------------------------------------------------------------------

TEST_F(BadInputTest, NanOrInfinityInThePositionIsInvalidValueAndDrawsNothing) {
  const std::pair<const char *, Spoil> spoils[] = {
      {"x NaN", [](GrVertex &v) { v.x = kNaN; }},   {"y NaN", [](GrVertex &v) { v.y = kNaN; }},
      {"x +Inf", [](GrVertex &v) { v.x = kInf; }},  {"x -Inf", [](GrVertex &v) { v.x = -kInf; }},
      {"y +Inf", [](GrVertex &v) { v.y = kInf; }},  {"y -Inf", [](GrVertex &v) { v.y = -kInf; }},
  };
  for (const auto &spoil : spoils) {
    expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with(spoil.second), spoil.first);
  }
}

TEST_F(BadInputTest, AbsurdCoordinatesAreInvalidValueAndDrawNothing) {
  const std::pair<const char *, Spoil> spoils[] = {
      {"x 1e9", [](GrVertex &v) { v.x = 1e9f; }},
      {"y 1e9", [](GrVertex &v) { v.y = 1e9f; }},
      {"x -1e9", [](GrVertex &v) { v.x = -1e9f; }},
      {"y -1e9", [](GrVertex &v) { v.y = -1e9f; }},
      // guDrawTriangleWithClip clips vertices out to 1e7 (as guclip.c would); 1e8 is refused by all.
      {"x 1e8", [](GrVertex &v) { v.x = 1e8f; }},
  };
  for (const auto &spoil : spoils) {
    expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with(spoil.second), spoil.first);
  }
}

TEST_F(BadInputTest, NanInAColourTheStateReadsIsInvalidValue) {
  // Default colour combine: SCALE_OTHER with other = ITERATED, so r, g, b are read.
  ASSERT_EQ(current().color_path.color.other, GR_COMBINE_OTHER_ITERATED);
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.r = kNaN; }), "r NaN");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.g = kInf; }), "g +Inf");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.b = -kInf; }), "b -Inf");
  // Iterated alpha makes a read.
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  expect_no_error();
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.a = kNaN; }), "a NaN, iterated alpha");
}

TEST_F(BadInputTest, NanInADepthOrTextureFieldTheStateReadsIsInvalidValue) {
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  expect_no_error();
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.oow = kNaN; }), "oow NaN, W-buffer");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.oow = kInf; }), "oow +Inf, W-buffer");
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  expect_no_error();
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.ooz = kNaN; }), "ooz NaN, Z-buffer");
  grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
  // A texture source in the colour path reads s, t and w.
  static std::vector<FxU16> texels(8 * 8, 0x07E0);
  GrTexInfo info{GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  expect_no_error();
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.tmuvtx[0].sow = kNaN; }), "sow NaN, textured");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.tmuvtx[0].tow = -kInf; }), "tow -Inf, textured");
  expect_all_rejected(GLIDESHIM_ERR_INVALID_VALUE, draws_with([](GrVertex &v) { v.oow = kNaN; }), "oow NaN, textured");
}

TEST_F(BadInputTest, NanInAFieldTheStateDoesNotReadIsAcceptedAndDraws) {
  const FxU16 white = 0xFFFF;
  auto spoil_all = [](const Spoil &spoil) {
    // Spoil every vertex of every call, not just one.
    std::vector<BadCall> calls;
    GrVertex t[3] = {kA, kB, kC};
    for (GrVertex &v : t) spoil(v);
    calls.push_back({"grDrawTriangle", [=] { grDrawTriangle(&t[0], &t[1], &t[2]); }});
    calls.push_back({"guDrawTriangleWithClip", [=] { guDrawTriangleWithClip(&t[0], &t[1], &t[2]); }});
    GrVertex l[2] = {make_vertex(2.0f, 16.5f), make_vertex(60.0f, 16.5f)};
    for (GrVertex &v : l) spoil(v);
    calls.push_back({"grDrawLine", [=] { grDrawLine(&l[0], &l[1]); }});
    GrVertex p = make_vertex(16.25f, 16.25f);
    spoil(p);
    calls.push_back({"grDrawPoint", [=] { grDrawPoint(&p); }});
    return calls;
  };
  // Depth disabled, no texturing, constant alpha: ooz, oow, tmuvtx, a and z are not read.
  const std::pair<const char *, Spoil> unread[] = {
      {"ooz NaN, depth off", [](GrVertex &v) { v.ooz = kNaN; }},
      {"oow NaN, depth off, no texture", [](GrVertex &v) { v.oow = kNaN; }},
      {"tmuvtx NaN/Inf, no texture",
       [](GrVertex &v) {
         v.tmuvtx[0].sow = kNaN, v.tmuvtx[0].tow = kInf, v.tmuvtx[0].oow = -kInf;
         v.tmuvtx[1].sow = kNaN, v.tmuvtx[1].tow = kNaN, v.tmuvtx[1].oow = kNaN;
       }},
      {"a NaN, constant alpha", [](GrVertex &v) { v.a = kNaN; }},
      {"z NaN (never read)", [](GrVertex &v) { v.z = kNaN; }},
  };
  for (const auto &case_ : unread) {
    for (const BadCall &call : spoil_all(case_.second)) expect_drawn(call, white, case_.first);
  }
  // A constant colour path does not read r, g, b (the constant is white).
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  expect_no_error();
  for (const BadCall &call : spoil_all([](GrVertex &v) { v.r = kNaN, v.g = kInf, v.b = -kInf; })) {
    expect_drawn(call, white, "r,g,b NaN/Inf, constant colour");
  }
  // Z-buffer mode reads ooz but not oow.
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthBufferFunction(GR_CMP_ALWAYS);
  expect_no_error();
  for (const BadCall &call : spoil_all([](GrVertex &v) { v.oow = kNaN; })) {
    expect_drawn(call, white, "oow NaN, Z-buffer");
  }
}

TEST_F(BadInputTest, ZeroAreaAndCollinearTrianglesAreDroppedSilently) {
  const std::vector<FxU16> front = read_buffer(GR_BUFFER_FRONTBUFFER);
  const std::vector<FxU16> back = read_buffer(GR_BUFFER_BACKBUFFER);
  const GrVertex same[3] = {make_vertex(20, 20), make_vertex(20, 20), make_vertex(20, 20)};
  const GrVertex line[3] = {make_vertex(10, 10), make_vertex(30, 30), make_vertex(50, 50)};
  const GrVertex flat[3] = {make_vertex(4, 32), make_vertex(60, 32), make_vertex(30, 32)};
  const GrVertex two_same[3] = {make_vertex(10, 10), make_vertex(50, 40), make_vertex(10, 10)};
  // Collinear only after snapping to 1/16 pixel: 20.01 snaps to 20.
  const GrVertex snapped[3] = {make_vertex(10, 10), make_vertex(20, 20.01f), make_vertex(40, 40)};
  for (const GrVertex *t : {same, line, flat, two_same, snapped}) {
    for (GrCullMode_t cull : {GR_CULL_DISABLE, GR_CULL_NEGATIVE, GR_CULL_POSITIVE}) {
      grCullMode(cull);
      glideShimResetPixelsWritten();
      reset_errors();
      grDrawTriangle(&t[0], &t[1], &t[2]);
      guDrawTriangleWithClip(&t[0], &t[1], &t[2]);
      guDrawTriangleWithClip(&t[2], &t[1], &t[0]);
      EXPECT_EQ(glideShimPixelsWritten(), 0u)
          << "degenerate triangle (" << t[0].x << "," << t[0].y << ") (" << t[1].x << "," << t[1].y
          << ") (" << t[2].x << "," << t[2].y << ") drew pixels, cull " << cull;
      expect_no_error_reported();
    }
  }
  EXPECT_TRUE(read_buffer(GR_BUFFER_FRONTBUFFER) == front);
  EXPECT_TRUE(read_buffer(GR_BUFFER_BACKBUFFER) == back);
}

// ---- LFB locks ---------------------------------------------------------------------------------

// A rejected lock must leave every field of info as it was.
void expect_info_untouched(const GrLfbInfo_t &info, const GrLfbInfo_t &before) {
  EXPECT_EQ(info.size, before.size);
  EXPECT_EQ(info.lfbPtr, before.lfbPtr) << "a rejected lock handed out a pointer";
  EXPECT_EQ(info.strideInBytes, before.strideInBytes);
  EXPECT_EQ(info.writeMode, before.writeMode);
  EXPECT_EQ(info.origin, before.origin);
}

GrLfbInfo_t fresh_info() {
  GrLfbInfo_t info;
  std::memset(&info, 0x5C, sizeof info);  // a pattern a rejected lock must leave alone
  info.size = sizeof info;
  return info;
}

TEST_F(BadInputTest, SecondLockOfTheSameKindIsInconsistent) {
  for (GrLock_t type : {GrLock_t{GR_LFB_READ_ONLY}, GrLock_t{GR_LFB_WRITE_ONLY},
                        GrLock_t{GR_LFB_READ_ONLY | GR_LFB_NOIDLE}}) {
    SCOPED_TRACE("lock type " + std::to_string(type));
    GrLfbInfo_t first = fresh_info();
    ASSERT_EQ(grLfbLock(type, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, &first), FXTRUE)
        << glideShimGetLastErrorMessage();
    GrLfbInfo_t second = fresh_info();
    const GrLfbInfo_t untouched = second;
    expect_rejected(GLIDESHIM_ERR_INCONSISTENT,
                    {"grLfbLock",
                     [&] { EXPECT_EQ(grLfbLock(type, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, &second), FXFALSE); }},
                    "second lock");
    expect_info_untouched(second, untouched);
    // The first lock is still held and unlocks once.
    EXPECT_EQ(grLfbUnlock(type, GR_BUFFER_BACKBUFFER), FXTRUE) << glideShimGetLastErrorMessage();
    expect_no_error_reported();
  }
}

TEST_F(BadInputTest, UnlockWithoutLockIsInconsistent) {
  expect_all_rejected(
      GLIDESHIM_ERR_INCONSISTENT,
      {{"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER), FXFALSE); }},
       {"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER), FXFALSE); }},
       {"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_FRONTBUFFER), FXFALSE); }}});
  // A write lock on the back buffer is not released by unlocking another buffer, and the pixels
  // written through it are not copied anywhere until the right unlock.
  GrLfbInfo_t info = fresh_info();
  ASSERT_EQ(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, &info), FXTRUE);
  auto *words = static_cast<FxU16 *>(info.lfbPtr);
  words[0] = 0xF81F;
  expect_all_rejected(
      GLIDESHIM_ERR_INCONSISTENT,
      {{"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_FRONTBUFFER), FXFALSE); }},
       {"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER), FXFALSE); }}},
      "write lock held on the back buffer");
  EXPECT_EQ(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER), FXTRUE);
  expect_no_error_reported();
  EXPECT_EQ(pixel(0, 0), 0xF81F);
}

TEST_F(BadInputTest, PipelineWriteLockWhileRenderingToATextureIsUnsupported) {
  GrLfbInfo_t info = fresh_info();
  ASSERT_EQ(glideShimRenderToTexture(GR_TMU0, 0, GR_LOD_64), FXTRUE) << glideShimGetLastErrorMessage();
  expect_rejected(GLIDESHIM_ERR_UNSUPPORTED,
                  {"grLfbLock", [&] { EXPECT_EQ(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXTRUE, &info), FXFALSE); }},
                  "pixel pipeline while rendering to a texture");
  glideShimRenderToFrameBuffer();
  expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                  {"grLfbLock", [&] { EXPECT_EQ(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_AUXBUFFER, GR_LFBWRITEMODE_8888, GR_ORIGIN_UPPER_LEFT, FXFALSE, &info), FXFALSE); }},
                  "colour mode on the aux buffer");
}

TEST_F(BadInputTest, LockInfoWithWrongSizeIsRejected) {
  for (int size : {0, static_cast<int>(sizeof(GrLfbInfo_t)) - 4, static_cast<int>(sizeof(GrLfbInfo_t)) + 4, -1}) {
    for (GrLock_t type : {GrLock_t{GR_LFB_READ_ONLY}, GrLock_t{GR_LFB_WRITE_ONLY}}) {
      GrLfbInfo_t info = fresh_info();
      info.size = size;
      const GrLfbInfo_t untouched = info;
      expect_rejected(GLIDESHIM_ERR_INCONSISTENT,
                      {"grLfbLock",
                       [&] { EXPECT_EQ(grLfbLock(type, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, &info), FXFALSE); }},
                      "info->size " + std::to_string(size) + " type " + std::to_string(type));
      expect_info_untouched(info, untouched);
    }
  }
}

// ---- out-of-range numbers ----------------------------------------------------------------------

TEST_F(BadInputTest, OutOfRangeNumbersAreRejected) {
  grGammaCorrectionValue(2.2f);
  grTexLodBiasValue(GR_TMU0, 0.5f);
  expect_no_error();
  expect_all_rejected(
      GLIDESHIM_ERR_OUT_OF_RANGE,
      {{"grGammaCorrectionValue", [] { grGammaCorrectionValue(kNaN); }},
       {"grGammaCorrectionValue", [] { grGammaCorrectionValue(0.0f); }},
       {"grGammaCorrectionValue", [] { grGammaCorrectionValue(-1.0f); }},
       {"grGammaCorrectionValue", [] { grGammaCorrectionValue(kInf); }},
       {"grTexLodBiasValue", [] { grTexLodBiasValue(GR_TMU0, 100.0f); }},
       {"grTexLodBiasValue", [] { grTexLodBiasValue(GR_TMU0, -100.0f); }},
       {"grTexLodBiasValue", [] { grTexLodBiasValue(GR_TMU0, kNaN); }},
       {"grBufferSwap", [] { grBufferSwap(-1); }},
       {"grSstSelect", [] { grSstSelect(1); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(0, 10), FXFALSE); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(10, 0), FXFALSE); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(-5, 10), FXFALSE); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(100000, 100000), FXFALSE); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(2049, 16), FXFALSE); }}});
  EXPECT_FLOAT_EQ(current().display.gamma, 2.2f);
  EXPECT_FLOAT_EQ(current().tmu.lod_bias, 0.5f);
  // The refused window size is not used by the next open.
  grSstWinClose();
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT, 2, 1));
  EXPECT_EQ(current().display.width, kWidth);
  EXPECT_EQ(current().display.height, kHeight);
}

// ---- the callback ------------------------------------------------------------------------------

TEST_F(BadInputTest, CallbackReceivesTheMessageOnce) {
  grDepthBufferFunction(0x77);
  EXPECT_EQ(g_log.calls, 1);
  EXPECT_EQ(g_log.message, glideShimGetLastErrorMessage());
  EXPECT_NE(g_log.message.find("grDepthBufferFunction"), std::string::npos) << g_log.message;
  EXPECT_EQ(g_log.fatal, FXFALSE) << "a rejected argument is not a fatal error";
  // A second bad call reports again, once, with its own message.
  grCullMode(9);
  EXPECT_EQ(g_log.calls, 2);
  EXPECT_NE(g_log.message.find("grCullMode"), std::string::npos) << g_log.message;
  EXPECT_EQ(g_log.message, glideShimGetLastErrorMessage());
  // Good calls do not call it.
  grCullMode(GR_CULL_NEGATIVE);
  grDepthBufferFunction(GR_CMP_GREATER);
  EXPECT_EQ(g_log.calls, 2);
  // Clearing the error resets the last error, not the callback.
  glideShimClearError();
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK);
  EXPECT_STREQ(glideShimGetLastErrorMessage(), "");
}

TEST_F(BadInputTest, WithoutACallbackErrorsAreStillRecorded) {
  grErrorSetCallback(nullptr);
  reset_errors();
  const GrVertex a = kA, c = kC;
  GrVertex b = kB;
  b.x = kNaN;
  const Snapshot before = capture();
  grDrawTriangle(&a, &b, &c);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_VALUE);
  EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find("grDrawTriangle"), std::string::npos);
  grDrawTriangle(nullptr, nullptr, nullptr);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 0, 0, 0, nullptr);
  EXPECT_NE(glideShimGetLastError(), GLIDESHIM_OK);
  expect_same_state(before, capture());
  EXPECT_EQ(g_log.calls, 0) << "the removed callback was called";
}

}  // namespace
