// Depth: W-buffer and Z-buffer compare semantics, and the property the article's second pass
// needs: the same vertices drawn again with LEQUAL pass the depth test on every pixel.
#include "glide_window.h"

#include <random>

namespace {

class DepthTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    grDitherMode(GR_DITHER_DISABLE);
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                   GR_COMBINE_OTHER_NONE, FXFALSE);
  }

  // Random overlapping triangles with perspective-like depths: w in [1, 1000], and ooz from
  // the same w, so W and Z buffers see the same ordering.
  static std::vector<GrVertex> random_mesh(unsigned seed, int triangles) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> coordinate(-8.0f, 72.0f), w(1.0f, 1000.0f);
    std::vector<GrVertex> vertices;
    for (int i = 0; i < 3 * triangles; ++i) {
      GrVertex v = vertex();
      v.x = coordinate(random), v.y = coordinate(random);
      const float depth = w(random);
      v.oow = 1.0f / depth;
      v.ooz = 65535.0f / depth;
      vertices.push_back(v);
    }
    return vertices;
  }

  static void draw_mesh(const std::vector<GrVertex> &mesh, GrColor_t color) {
    grConstantColorValue(color);
    for (std::size_t i = 0; i + 2 < mesh.size(); i += 3) {
      guDrawTriangleWithClip(&mesh[i], &mesh[i + 1], &mesh[i + 2]);
    }
  }
};

TEST_F(DepthTest, SecondPassWithLequalPassesOnEveryVisiblePixel) {
  for (GrDepthBufferMode_t mode : {GR_DEPTHBUFFER_WBUFFER, GR_DEPTHBUFFER_ZBUFFER}) {
    const bool w_buffer = mode == GR_DEPTHBUFFER_WBUFFER;
    const std::vector<GrVertex> mesh = random_mesh(42, 200);
    grDepthBufferMode(mode);
    grDepthMask(FXTRUE);
    grDepthBufferFunction(w_buffer ? GR_CMP_LESS : GR_CMP_GREATER);  // nearer wins
    grBufferClear(0, 0, w_buffer ? GR_WDEPTHVALUE_FARTHEST : GR_ZDEPTHVALUE_FARTHEST);
    draw_mesh(mesh, 0x00FF0000u);  // pass 1: red

    grDepthMask(FXFALSE);
    grDepthBufferFunction(w_buffer ? GR_CMP_LEQUAL : GR_CMP_GEQUAL);
    glideShimResetPixelsWritten();
    draw_mesh(mesh, 0x0000FF00u);  // pass 2: green, same vertices
    const FxU32 passed = glideShimPixelsWritten();

    int red = 0, green = 0;
    for (FxU16 p : read_buffer()) {
      red += p == 0xF800;
      green += p == 0x07E0;
    }
    EXPECT_EQ(red, 0) << "pixels where the second pass failed the depth test, mode " << mode;
    EXPECT_GT(green, kWidth * kHeight / 2);
    // Every covered pixel passes at least once (overdraw can pass more often).
    EXPECT_GE(passed, static_cast<FxU32>(green)) << "mode " << mode;
  }
  expect_no_error();
}

TEST_F(DepthTest, BiasedSecondPassFailsSoTheInvarianceCheckCanFail) {
  const std::vector<GrVertex> mesh = random_mesh(42, 200);
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthMask(FXTRUE);
  grDepthBufferFunction(GR_CMP_LESS);
  grBufferClear(0, 0, GR_WDEPTHVALUE_FARTHEST);
  draw_mesh(mesh, 0x00FF0000u);
  grDepthMask(FXFALSE);
  grDepthBufferFunction(GR_CMP_LEQUAL);
  grDepthBiasLevel(64);  // pushes the second pass 64 codes farther
  draw_mesh(mesh, 0x0000FF00u);
  int red = 0;
  for (FxU16 p : read_buffer()) red += p == 0xF800;
  EXPECT_GT(red, kWidth * kHeight / 2);
  expect_no_error();
}

TEST_F(DepthTest, WBufferNearerSmallerWWinsWithLess) {
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, GR_WDEPTHVALUE_FARTHEST);
  GrVertex near = vertex(), far = vertex();
  near.oow = 1.0f / 2.0f;
  far.oow = 1.0f / 4.0f;
  for (GrCmpFnc_t function : {GR_CMP_LESS, GR_CMP_GREATER}) {
    grDepthBufferFunction(GR_CMP_ALWAYS);
    grBufferClear(0, 0, function == GR_CMP_LESS ? GR_WDEPTHVALUE_FARTHEST : GR_WDEPTHVALUE_NEAREST);
    grDepthBufferFunction(function);
    grConstantColorValue(0x00FF0000u);
    draw_rect(0, 0, 48, 48, far);
    grConstantColorValue(0x000000FFu);
    draw_rect(16, 16, 64, 64, near);
    // Overlap: LESS keeps the nearer (blue, drawn second); GREATER keeps the farther (red).
    EXPECT_EQ(pixel(30, 30), function == GR_CMP_LESS ? 0x001F : 0xF800) << "function " << function;
  }
  expect_no_error();
}

TEST_F(DepthTest, ZBufferComparesOozAsStored) {
  // In Z mode the stored value is ooz itself: GREATER keeps the larger ooz (the nearer).
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthMask(FXTRUE);
  grDepthBufferFunction(GR_CMP_GREATER);
  grBufferClear(0, 0, GR_ZDEPTHVALUE_FARTHEST);
  GrVertex near = vertex(), far = vertex();
  near.ooz = 40000.0f;
  far.ooz = 20000.0f;
  grConstantColorValue(0x000000FFu);
  draw_rect(16, 16, 64, 64, near);
  grConstantColorValue(0x00FF0000u);
  draw_rect(0, 0, 48, 48, far);
  EXPECT_EQ(pixel(30, 30), 0x001F);
  EXPECT_EQ(pixel(5, 5), 0xF800);
  expect_no_error();
}

TEST_F(DepthTest, DepthMaskOffLeavesTheDepthBufferAlone) {
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthMask(FXTRUE);
  grDepthBufferFunction(GR_CMP_LESS);
  grBufferClear(0, 0, GR_WDEPTHVALUE_FARTHEST);
  grDepthMask(FXFALSE);
  GrVertex near = vertex();
  near.oow = 0.5f;
  draw_rect(0, 0, kWidth, kHeight, near);
  FxU16 code = 0;
  ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_AUXBUFFER, 10, 10, 1, 1, 2, &code));
  EXPECT_EQ(code, GR_WDEPTHVALUE_FARTHEST);
  grDepthMask(FXTRUE);
  draw_rect(0, 0, kWidth, kHeight, near);
  ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_AUXBUFFER, 10, 10, 1, 1, 2, &code));
  EXPECT_EQ(code, 0x1000);  // 1/w = 0.5: no leading zeros, mantissa 0 -> 0xFFF + 1
  expect_no_error();
}

}  // namespace
