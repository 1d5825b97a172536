// Bad input across the chapters, and error reporting itself: a NULL pointer to any entry point
// that takes one is NULL_POINTER; the grErrorSetCallback callback receives each message once,
// and without a callback errors are still recorded.
#include "bad_input_fixture.h"

#include <string>

namespace {

using namespace bad_input;

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
