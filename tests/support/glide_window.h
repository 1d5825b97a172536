// Test fixture: a small headless Glide window opened per test (grGlideInit .. grGlideShutdown),
// and helpers to draw screen-aligned rectangles and read the colour buffer back.
#pragma once

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

// sow, tow and oow affine in screen x, y, as a plane in perspective is: both triangles of the
// full-window quad share one gradient (256-texel units per pixel of sow and tow), and 1/w runs
// linearly from the top row to the bottom of the 64-pixel window.
struct TexturePlane {
  double s_dx, t_dy;
  double oow_top, oow_bottom;
  double oow(double y) const { return oow_top + (oow_bottom - oow_top) * y / 64.0; }
};

class GlideWindowTest : public ::testing::Test {
 protected:
  static constexpr int kWidth = 64;
  static constexpr int kHeight = 64;

  void SetUp() override;
  void TearDown() override;

  // The whole colour buffer as 565 words, rows from the top.
  std::vector<FxU16> read_buffer(GrBuffer_t buffer = GR_BUFFER_BACKBUFFER);
  FxU16 pixel(int x, int y, GrBuffer_t buffer = GR_BUFFER_BACKBUFFER);

  // Two triangles covering pixels [x0,x1) x [y0,y1); the vertex template supplies colour, depth
  // and texture fields.
  static void draw_rect(float x0, float y0, float x1, float y1, const GrVertex &style);
  static GrVertex vertex();  // all fields zero but oow = 1
  // The whole window textured by `plane` (TMU 0's s/w, t/w and 1/w).
  static void draw_plane(const TexturePlane &plane);

  // Expects no error reported since the last glideShimClearError.
  static void expect_no_error();
};

// The window with texels shown as they are: dithering off, TMU 0 decal, colour = texture, so a
// pixel's 565 word is the texel as the TMU filtered it.
class DecalTextureTest : public GlideWindowTest {
 protected:
  void SetUp() override;
};

// Channel helpers for 565 words.
inline int red5(FxU16 p) { return p >> 11; }
inline int green6(FxU16 p) { return (p >> 5) & 0x3F; }
inline int blue5(FxU16 p) { return p & 0x1F; }
