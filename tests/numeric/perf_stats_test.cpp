// grSstPerfStats counts, exactly, on a scene whose counts are known: squares that pass, fail
// the depth test, fail the chroma key, and fail the alpha test, in the Voodoo's test order; and
// grTriStats' triangle counts.
#include "glide_window.h"

namespace {

class PerfStatsTest : public GlideWindowTest {
 protected:
  // A w x h square of one colour, alpha and ooz at (x, y).
  static void square(float x, float y, float w, float h, float r, float g, float b, float a, float ooz) {
    GrVertex style = vertex();
    style.r = r, style.g = g, style.b = b, style.a = a, style.ooz = ooz;
    draw_rect(x, y, x + w, y + h, style);
  }
};

TEST_F(PerfStatsTest, CountsEveryStageOfAKnownScene) {
  grDitherMode(GR_DITHER_DISABLE);
  // The default colour combine passes the iterated colour as 'other', which the key compares.
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthBufferFunction(GR_CMP_GREATER);  // larger ooz is nearer
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, 0);
  grChromakeyValue(0x0000FF00u);  // green
  grChromakeyMode(GR_CHROMAKEY_ENABLE);
  grAlphaTestFunction(GR_CMP_GREATER);
  grAlphaTestReferenceValue(128);

  GrSstPerfStats_t stats;
  grSstPerfStats(&stats);
  EXPECT_EQ(stats.pixelsIn, 0u) << "nothing is counted before the first reset";
  grSstResetPerfStats();
  square(0, 0, 10, 10, 255, 0, 0, 255, 40000);  // 100 pixels in and out, depth written
  // 10x10 at x 5: 50 pixels behind the first square fail the depth test; the other 50 are
  // green and fail the chroma key (tested after depth).
  square(5, 0, 10, 10, 0, 255, 0, 255, 20000);
  // 10x10 at x 20, alpha 10 against GREATER 128: 100 fail the alpha test.
  square(20, 0, 10, 10, 0, 0, 255, 10, 20000);
  // The first square again, nearer: 100 pass every test.
  square(0, 20, 10, 10, 255, 255, 255, 255, 60000);
  grSstPerfStats(&stats);
  EXPECT_EQ(stats.pixelsIn, 400u);
  EXPECT_EQ(stats.zFuncFail, 50u);
  EXPECT_EQ(stats.chromaFail, 50u);
  EXPECT_EQ(stats.aFuncFail, 100u);
  EXPECT_EQ(stats.pixelsOut, 200u);

  // The counted draws wrote exactly what an uncounted draw writes.
  const std::vector<FxU16> pixels = read_buffer();
  EXPECT_EQ(pixels[5 * kWidth + 2], 0xF800);
  EXPECT_EQ(pixels[5 * kWidth + 12], 0x0000) << "chroma-keyed green not drawn";
  EXPECT_EQ(pixels[5 * kWidth + 25], 0x0000) << "alpha-tested blue not drawn";
  EXPECT_EQ(pixels[25 * kWidth + 5], 0xFFFF);

  grSstResetPerfStats();
  grSstPerfStats(&stats);
  EXPECT_EQ(stats.pixelsIn + stats.pixelsOut + stats.zFuncFail, 0u) << "reset zeroes the counters";
  expect_no_error();
}

TEST_F(PerfStatsTest, TriangleStatsCountSetUpAndDrawnTriangles) {
  grResetTriStats();
  grCullMode(GR_CULL_NEGATIVE);
  GrVertex a = vertex(), b = vertex(), c = vertex();
  a.x = 2, a.y = 2, b.x = 30, b.y = 2, c.x = 2, c.y = 30;
  grDrawTriangle(&a, &b, &c);  // positive area on screen: drawn
  grDrawTriangle(&a, &c, &b);  // negative: culled
  grDrawTriangle(&a, &a, &b);  // zero area: dropped
  square(40, 40, 8, 8, 255, 255, 255, 255, 0);  // two more, drawn
  FxU32 processed = 0, drawn = 0;
  grTriStats(&processed, &drawn);
  EXPECT_EQ(processed, 5u);
  EXPECT_EQ(drawn, 3u);
  grResetTriStats();
  grTriStats(&processed, &drawn);
  EXPECT_EQ(processed + drawn, 0u);
  expect_no_error();
}

TEST_F(PerfStatsTest, NullPointersAreRefused) {
  grSstPerfStats(nullptr);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  glideShimClearError();
  FxU32 count = 0;
  grTriStats(&count, nullptr);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  glideShimClearError();
}

}  // namespace
