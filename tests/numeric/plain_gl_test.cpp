// Plain GL between Glide calls: what GL draws lands in Glide's frame buffer, Glide's depth is
// there in the documented mapping, and Glide draws after glideShimEndGL exactly as before.
#include "glide_window.h"

#include <GL/gl.h>

namespace {

using PlainGlTest = GlideWindowTest;

template <typename F>
F gl(const char *name) {
  return reinterpret_cast<F>(glideShimGetProcAddress(name));
}

TEST_F(PlainGlTest, GlDrawsIntoGlidesBackBufferAndSeesItsDepth) {
  grDitherMode(GR_DITHER_DISABLE);
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, GR_WDEPTHVALUE_FARTHEST);
  GrVertex near = vertex();
  near.oow = 0.5f;  // w = 2
  near.r = 255;
  draw_rect(0, 0, 32, 64, near);  // left half, red

  ASSERT_TRUE(glideShimBeginGL());
  auto clear_color = gl<void (*)(float, float, float, float)>("glClearColor");
  auto enable = gl<void (*)(GLenum)>("glEnable");
  auto scissor = gl<void (*)(int, int, int, int)>("glScissor");
  auto clear = gl<void (*)(GLbitfield)>("glClear");
  auto read_pixels = gl<void (*)(int, int, int, int, GLenum, GLenum, void *)>("glReadPixels");
  ASSERT_TRUE(clear_color && enable && scissor && clear && read_pixels);
  float depth = -1.0f;
  read_pixels(10, 10, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);  // GL rows from the bottom
  EXPECT_NEAR(depth, 0.5f, 1e-6f) << "W-buffer depth is 1/w in GL";
  enable(GL_SCISSOR_TEST);
  scissor(32, 0, 32, 64);  // right half
  clear_color(0.0f, 0.0f, 1.0f, 1.0f);
  clear(GL_COLOR_BUFFER_BIT);
  glideShimEndGL();
  expect_no_error();

  EXPECT_EQ(pixel(10, 10), 0xF800);
  EXPECT_EQ(pixel(50, 10), 0x001F);
  // Glide works as before: clip window, depth test and colour path restored.
  GrVertex nearer = vertex();
  nearer.oow = 0.75f;
  nearer.g = 255;
  draw_rect(0, 0, 64, 64, nearer);
  EXPECT_EQ(pixel(10, 10), 0x07E0);
  EXPECT_EQ(pixel(50, 10), 0x07E0);
  expect_no_error();
}

TEST_F(PlainGlTest, PlainGlStartsWithGlsDefaultClearValues) {
  // A W-buffer clear to the farthest code sets GL's clear depth to 0 (1/w); a GL technique that
  // clears its own depth map must not inherit that.
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthMask(FXTRUE);
  grBufferClear(0x00FF00FFu, 0, GR_WDEPTHVALUE_FARTHEST);
  ASSERT_TRUE(glideShimBeginGL());
  auto get_floats = gl<void (*)(GLenum, float *)>("glGetFloatv");
  float depth = -1.0f, color[4] = {-1, -1, -1, -1};
  get_floats(GL_DEPTH_CLEAR_VALUE, &depth);
  get_floats(GL_COLOR_CLEAR_VALUE, color);
  glideShimEndGL();
  EXPECT_EQ(depth, 1.0f);
  EXPECT_EQ(color[0] + color[1] + color[2] + color[3], 0.0f);
  expect_no_error();
}

TEST_F(PlainGlTest, BeginTwiceOrEndWithoutBeginIsRefused) {
  ASSERT_TRUE(glideShimBeginGL());
  EXPECT_FALSE(glideShimBeginGL());
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INCONSISTENT);
  glideShimEndGL();
  glideShimClearError();
  glideShimEndGL();
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INCONSISTENT);
  EXPECT_EQ(glideShimGetProcAddress(nullptr), nullptr);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
}

}  // namespace
