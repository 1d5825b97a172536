// Polygons: grDrawPolygon(VertexList) and the planar forms draw the same fan of triangles as
// grDrawTriangle would, guDrawPolygonVertexListWithClip clips to the clip window, and the AA
// forms add one-pixel alpha fringes outside the chosen edges. Counts and pixels are compared
// with the same shape drawn as triangles.
#include "glide_window.h"

#include <glideutl.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

class PolygonTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    grDitherMode(GR_DITHER_DISABLE);
    guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  }

  // A convex pentagon in screen pixels with a planar (linear in x and y) Gouraud colour, as
  // planar polygons require, wound the same way as the triangles that fan it.
  static std::vector<GrVertex> pentagon() {
    const float xs[5] = {32, 56, 48, 16, 8}, ys[5] = {6, 24, 56, 56, 24};
    std::vector<GrVertex> v(5, vertex());
    for (std::size_t i = 0; i < 5; ++i) {
      v[i].x = xs[i], v[i].y = ys[i];
      v[i].r = 2.0f * xs[i] + 60.0f, v[i].g = 3.0f * ys[i] + 20.0f, v[i].b = 90;
      v[i].a = 255;
    }
    return v;
  }

  // The pentagon as grDrawTriangle fans it, for comparison.
  std::vector<FxU16> as_triangles(const std::vector<GrVertex> &v) {
    grBufferClear(0, 0, 0);
    for (std::size_t i = 2; i < v.size(); ++i) grDrawTriangle(&v[0], &v[i - 1], &v[i]);
    return read_buffer();
  }
};

TEST_F(PolygonTest, EveryPolygonCallDrawsTheTriangleFan) {
  const std::vector<GrVertex> v = pentagon();
  const std::vector<FxU16> want = as_triangles(v);
  const int lit = static_cast<int>(std::count_if(want.begin(), want.end(), [](FxU16 p) { return p != 0; }));
  ASSERT_GT(lit, 1000);  // the pentagon covers about 1,700 pixels

  grBufferClear(0, 0, 0);
  grDrawPolygonVertexList(5, v.data());
  EXPECT_EQ(read_buffer(), want) << "grDrawPolygonVertexList";
  grBufferClear(0, 0, 0);
  grDrawPlanarPolygonVertexList(5, v.data());
  EXPECT_EQ(read_buffer(), want) << "grDrawPlanarPolygonVertexList";

  // Indexed: the vertices stored in another order, picked back through ilist.
  const std::vector<GrVertex> shuffled = {v[3], v[0], v[4], v[2], v[1]};
  const int ilist[5] = {1, 4, 3, 0, 2};
  grBufferClear(0, 0, 0);
  grDrawPolygon(5, ilist, shuffled.data());
  EXPECT_EQ(read_buffer(), want) << "grDrawPolygon";
  grBufferClear(0, 0, 0);
  grDrawPlanarPolygon(5, ilist, shuffled.data());
  EXPECT_EQ(read_buffer(), want) << "grDrawPlanarPolygon";
  expect_no_error();
}

TEST_F(PolygonTest, ClippedPolygonStaysInsideTheClipWindow) {
  std::vector<GrVertex> v = pentagon();
  for (GrVertex &p : v) p.x += 20;  // hangs off the right edge of the 64-pixel screen
  grBufferClear(0, 0, 0);
  grClipWindow(10, 10, 50, 50);
  guDrawPolygonVertexListWithClip(5, v.data());
  const std::vector<FxU16> pixels = read_buffer();
  int inside = 0, outside = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const bool lit = pixels[static_cast<std::size_t>(y * kWidth + x)] != 0;
      (x >= 10 && x < 50 && y >= 10 && y < 50 ? inside : outside) += lit;
    }
  EXPECT_EQ(outside, 0);
  EXPECT_GT(inside, 600);
  // The part inside the window is what the unclipped fan draws there (the scissor clips it).
  grClipWindow(0, 0, kWidth, kHeight);
  grBufferClear(0, 0, 0);
  grClipWindow(10, 10, 50, 50);
  for (std::size_t i = 2; i < v.size(); ++i) grDrawTriangle(&v[0], &v[i - 1], &v[i]);
  const std::vector<FxU16> fan = read_buffer();
  int differ = 0;
  for (std::size_t i = 0; i < fan.size(); ++i) differ += pixels[i] != fan[i];
  // Clipping moves the fan's shared vertex and re-snaps the new vertices: with a planar colour
  // the pixels may differ by rounding only, never the coverage inside.
  int coverage_differ = 0;
  for (std::size_t i = 0; i < fan.size(); ++i) coverage_differ += (pixels[i] != 0) != (fan[i] != 0);
  EXPECT_EQ(coverage_differ, 0);
  EXPECT_LT(differ, inside / 10);
  expect_no_error();
}

TEST_F(PolygonTest, AntialiasedEdgesAddAnAlphaFringe) {
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
  const std::vector<GrVertex> v = pentagon();
  const std::vector<FxU16> solid = as_triangles(v);

  grBufferClear(0, 0, 0);
  grAADrawPolygonVertexList(5, v.data());
  const std::vector<FxU16> aa = read_buffer();
  int inside_changed = 0, fringe = 0, far_outside = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kWidth + x);
      if (solid[i] != 0) {
        inside_changed += aa[i] != solid[i];
        continue;
      }
      // Outside the solid polygon: lit only within two pixels of a lit solid pixel.
      bool near = false;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const int nx = x + dx, ny = y + dy;
          near = near || (nx >= 0 && ny >= 0 && nx < kWidth && ny < kHeight &&
                          solid[static_cast<std::size_t>(ny * kWidth + nx)] != 0);
        }
      if (aa[i] != 0) (near ? fringe : far_outside)++;
    }
  EXPECT_EQ(far_outside, 0);
  EXPECT_GT(fringe, 60);  // a fringe along the outline (about 150 pixels of perimeter)
  // The fringe covers the polygon's own edge pixels too, blended over them.
  EXPECT_LT(inside_changed, 300);

  // Fringe pixels are partial: dimmer than the solid interior next to them.
  grBufferClear(0, 0, 0);
  GrVertex a = v[0], b = v[1], c = v[2];
  grAADrawTriangle(&a, &b, &c, FXFALSE, FXFALSE, FXFALSE);
  const std::vector<FxU16> no_edges = read_buffer();
  grBufferClear(0, 0, 0);
  grDrawTriangle(&a, &b, &c);
  EXPECT_EQ(no_edges, read_buffer()) << "no AA edge asked: the plain triangle";
  expect_no_error();
}

TEST_F(PolygonTest, ClippedAntialiasedTriangleKeepsItsFringeInsideTheWindow) {
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
  GrVertex a = vertex(), b = vertex(), c = vertex();
  a.x = 10, a.y = 12, b.x = 90, b.y = 30, c.x = 20, c.y = 55;  // b is off the screen's right
  for (GrVertex *v : {&a, &b, &c}) v->r = v->g = v->b = v->a = 255;
  grBufferClear(0, 0, 0);
  grClipWindow(4, 4, 48, 60);
  guAADrawTriangleWithClip(&a, &b, &c);
  const std::vector<FxU16> aa = read_buffer();
  grClipWindow(0, 0, kWidth, kHeight);
  grBufferClear(0, 0, 0);
  grClipWindow(4, 4, 48, 60);
  guDrawTriangleWithClip(&a, &b, &c);
  const std::vector<FxU16> plain = read_buffer();
  int outside = 0, fringe = 0, white_lost = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kWidth + x);
      if (x < 4 || x >= 48 || y < 4 || y >= 60) outside += aa[i] != 0;
      if (plain[i] == 0 && aa[i] != 0) ++fringe;
      if (plain[i] == 0xFFFF && aa[i] == 0) ++white_lost;
    }
  EXPECT_EQ(outside, 0);
  EXPECT_GT(fringe, 30);  // along the two unclipped edges
  EXPECT_EQ(white_lost, 0);
  expect_no_error();
}

TEST_F(PolygonTest, AntialiasedLineHasFadingSides) {
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
  GrVertex a = vertex(), b = vertex();
  a.x = 4.5f, a.y = 20.5f, b.x = 60.5f, b.y = 30.5f;
  a.r = a.g = a.b = b.r = b.g = b.b = 255;
  a.a = b.a = 255;
  grBufferClear(0, 0, 0);
  grAADrawLine(&a, &b);
  const std::vector<FxU16> pixels = read_buffer();
  // Every column along the line has its white core, the rows beside it fade (neither black nor
  // white), and nothing is lit more than two rows from the line.
  int partial = 0, stray = 0, columns_with_core = 0;
  for (int x = 8; x < 56; ++x) {
    const float line_y = 20.5f + (static_cast<float>(x) + 0.5f - 4.5f) * 10.0f / 56.0f;
    bool core = false;
    for (int y = 0; y < kHeight; ++y) {
      const FxU16 p = pixels[static_cast<std::size_t>(y * kWidth + x)];
      if (p == 0) continue;
      if (std::fabs(static_cast<float>(y) + 0.5f - line_y) > 2.0f) ++stray;
      if (p == 0xFFFF) core = true;
      else ++partial;
    }
    columns_with_core += core;
  }
  EXPECT_EQ(columns_with_core, 48);
  EXPECT_GT(partial, 30);
  EXPECT_EQ(stray, 0);
  expect_no_error();
}

TEST_F(PolygonTest, BadPolygonsAreRefusedAndDrawNothing) {
  const std::vector<GrVertex> v = pentagon();
  grBufferClear(0, 0, 0);
  grDrawPolygonVertexList(2, v.data());
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  grDrawPolygon(5, nullptr, v.data());
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  const int negative[3] = {0, -1, 2};
  grDrawPolygon(3, negative, v.data());
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  grAADrawPolygonVertexList(5, nullptr);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  guDrawPolygonVertexListWithClip(1, v.data());
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  std::vector<GrVertex> bad = v;
  bad[3].x = NAN;
  grDrawPolygonVertexList(5, bad.data());
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_VALUE);
  grAADrawTriangle(&v[0], nullptr, &v[1], FXTRUE, FXTRUE, FXTRUE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  const std::vector<FxU16> pixels = read_buffer();
  EXPECT_TRUE(std::all_of(pixels.begin(), pixels.end(), [](FxU16 p) { return p == 0; }));
}

}  // namespace
