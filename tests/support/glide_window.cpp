// The per-test Glide window and its drawing/reading helpers.
#include "glide_window.h"

#include <cstring>

void GlideWindowTest::SetUp() {
  grGlideInit();
  ASSERT_TRUE(glideShimSetWindowSize(kWidth, kHeight));
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  glideShimClearError();
}

void GlideWindowTest::TearDown() {
  grGlideShutdown();
  grErrorSetCallback(nullptr);
  glideShimClearError();
}

std::vector<FxU16> GlideWindowTest::read_buffer(GrBuffer_t buffer) {
  std::vector<FxU16> pixels(kWidth * kHeight);
  EXPECT_TRUE(grLfbReadRegion(buffer, 0, 0, kWidth, kHeight, kWidth * 2, pixels.data()))
      << glideShimGetLastErrorMessage();
  return pixels;
}

FxU16 GlideWindowTest::pixel(int x, int y, GrBuffer_t buffer) {
  FxU16 value = 0;
  EXPECT_TRUE(grLfbReadRegion(buffer, static_cast<FxU32>(x), static_cast<FxU32>(y), 1, 1, 2, &value));
  return value;
}

GrVertex GlideWindowTest::vertex() {
  GrVertex v;
  std::memset(&v, 0, sizeof v);
  v.oow = 1.0f;
  return v;
}

void GlideWindowTest::draw_rect(float x0, float y0, float x1, float y1, const GrVertex &style) {
  GrVertex a = style, b = style, c = style, d = style;
  a.x = x0, a.y = y0;
  b.x = x1, b.y = y0;
  c.x = x1, c.y = y1;
  d.x = x0, d.y = y1;
  grDrawTriangle(&a, &b, &c);
  grDrawTriangle(&a, &c, &d);
}

void GlideWindowTest::expect_no_error() {
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

void GlideWindowTest::draw_plane(const TexturePlane &plane) {
  GrVertex v[4];
  const float xs[4] = {0, kWidth, kWidth, 0}, ys[4] = {0, 0, kHeight, kHeight};
  for (int k = 0; k < 4; ++k) {
    v[k] = vertex();
    v[k].x = xs[k], v[k].y = ys[k];
    v[k].oow = static_cast<float>(plane.oow(ys[k]));
    v[k].tmuvtx[0].sow = static_cast<float>(plane.s_dx * xs[k]);
    v[k].tmuvtx[0].tow = static_cast<float>(plane.t_dy * ys[k]);
  }
  grDrawTriangle(&v[0], &v[1], &v[2]);
  grDrawTriangle(&v[0], &v[2], &v[3]);
}

void DecalTextureTest::SetUp() {
  GlideWindowTest::SetUp();
  grDitherMode(GR_DITHER_DISABLE);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
}
