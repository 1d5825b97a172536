// GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS and WBUFFER_COMPARE_TO_BIAS: the depth test compares
// grDepthBiasLevel (as an unsigned 16-bit value) with the stored code, not the pixel's depth,
// and a passing pixel writes its own depth, without bias (gglide.c sets fbzMode bit 20 and no
// depth-bias enable; MAME's depth_test replaces the pixel's side). Stored codes are written
// through the LFB, so every pixel's test is known exactly, including codes next to the bias.
#include "glide_window.h"
#include "voodoo_reference.h"

#include <GL/gl.h>

#include <random>
#include <string>
#include <vector>

namespace {

class DepthCompareToBiasTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    grDitherMode(GR_DITHER_DISABLE);
    guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  }

  // Stored codes: the top half runs through bias - 32 .. bias + 31 along each row (so codes
  // next to the bias and the pixel's own code sit side by side), the bottom half is random.
  static std::vector<FxU16> stored_codes(int bias_source, int pixel_code) {
    std::mt19937 random(static_cast<unsigned>(bias_source * 31 + pixel_code));
    std::uniform_int_distribution<int> any(0, 0xFFFF);
    std::vector<FxU16> codes(kWidth * kHeight);
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        int code = any(random);
        if (y < kHeight / 4) code = bias_source - 32 + x;
        else if (y < kHeight / 2) code = pixel_code - 32 + x;
        codes[static_cast<std::size_t>(y * kWidth + x)] =
            static_cast<FxU16>(std::clamp(code, 0, 0xFFFF));
      }
    }
    return codes;
  }

  // Black colour, the given depth codes, then one full-window quad of `style`. Returns the
  // codes the aux buffer held before the quad, read back: in W mode the 24-bit buffer cannot
  // hold every far code (above about 0xC000 neighbouring codes share a level), so the test
  // compares against what is stored.
  std::vector<FxU16> draw_over(std::vector<FxU16> codes, const GrVertex &style) {
    grDepthMask(FXFALSE);
    grBufferClear(0x00000000u, 0, 0);
    EXPECT_TRUE(grLfbWriteRegion(GR_BUFFER_AUXBUFFER, 0, 0, GR_LFB_SRC_FMT_ZA16, kWidth, kHeight,
                                 kWidth * 2, codes.data()));
    const std::vector<FxU16> stored = read_codes();
    grDepthMask(FXTRUE);
    draw_rect(0, 0, kWidth, kHeight, style);
    return stored;
  }

  std::vector<FxU16> read_codes() {
    std::vector<FxU16> codes(kWidth * kHeight);
    EXPECT_TRUE(grLfbReadRegion(GR_BUFFER_AUXBUFFER, 0, 0, kWidth, kHeight, kWidth * 2,
                                codes.data()));
    return codes;
  }

  // Every function and several biases in `mode`, with a flat quad whose own code is
  // `pixel_code` (style carries its ooz or oow): colour and depth per pixel against the model.
  void check_mode(GrDepthBufferMode_t mode, const GrVertex &style, int pixel_code) {
    grDepthBufferMode(mode);
    ASSERT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
    const FxU16 white = 0xFFFF;
    int passed = 0, failed = 0;
    for (FxI16 bias : {FxI16{1000}, static_cast<FxI16>(pixel_code - 1),
                       static_cast<FxI16>(pixel_code), FxI16{-3}, FxI16{0}}) {
      const int source = voodoo_ref::compare_to_bias_source(bias);
      for (GrCmpFnc_t function = GR_CMP_NEVER; function <= GR_CMP_ALWAYS; ++function) {
        SCOPED_TRACE("mode " + std::to_string(mode) + " bias " + std::to_string(bias) +
                     " function " + std::to_string(function));
        grDepthBiasLevel(bias);
        grDepthBufferFunction(function);
        const std::vector<FxU16> before = draw_over(stored_codes(source, pixel_code), style);
        const std::vector<FxU16> frame = read_buffer(), after = read_codes();
        int wrong = 0;
        for (std::size_t i = 0; i < before.size(); ++i) {
          const bool pass = voodoo_ref::depth_test_passes(function, source, before[i]);
          passed += pass;
          failed += !pass;
          const FxU16 want_colour = pass ? white : 0;
          const FxU16 want_code = pass ? static_cast<FxU16>(pixel_code) : before[i];
          if ((frame[i] != want_colour || after[i] != want_code) && ++wrong <= 3) {
            ADD_FAILURE() << "pixel " << i << " stored " << before[i] << ": want colour "
                          << want_colour << " code " << want_code << ", got " << frame[i]
                          << " code " << after[i];
          }
        }
        EXPECT_EQ(wrong, 0);
      }
    }
    EXPECT_GT(passed, 10000);
    EXPECT_GT(failed, 10000);
    expect_no_error();
  }

  static GrVertex white_vertex() {
    GrVertex v = vertex();
    v.r = v.g = v.b = 255.0f;
    return v;
  }
};

TEST_F(DepthCompareToBiasTest, ZBufferComparesTheBiasLevelWithTheStoredCode) {
  GrVertex style = white_vertex();
  style.ooz = 30000.0f;  // the pixel's Z code; no bias is added to it in this mode
  check_mode(GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS, style, 30000);
}

TEST_F(DepthCompareToBiasTest, WBufferComparesTheBiasLevelWithTheStoredCode) {
  GrVertex style = white_vertex();
  style.oow = 0.0123f;
  const int code = voodoo_ref::w_buffer_code(0.0123f);
  check_mode(GR_DEPTHBUFFER_WBUFFER_COMPARE_TO_BIAS, style, code);
}

TEST_F(DepthCompareToBiasTest, EveryBufferLevelAroundTheBiasCodeGoesTheWayItsCodeDoes) {
  // 4096 consecutive 24-bit levels around the levels of code 1000 (about 256 a code in Z mode),
  // written through plain GL: the levels next to each code boundary, which LFB-written codes
  // never reach. The stored code of a pixel is what an aux-buffer read returns.
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS);
  grDepthBiasLevel(1000);
  constexpr double kTop = 16777215.0;
  const double first_level = std::floor(1000.0 / 65535.0 * kTop) - 2048.0;
  std::vector<float> levels(kWidth * kHeight);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    levels[i] = static_cast<float>((first_level + static_cast<double>(i)) / kTop);
  }
  using DrawPixels = void (*)(GLsizei, GLsizei, GLenum, GLenum, const void *);
  using WindowPos = void (*)(GLint, GLint);
  using Enable = void (*)(GLenum);
  using DepthFunc = void (*)(GLenum);
  for (GrCmpFnc_t function = GR_CMP_LESS; function <= GR_CMP_GEQUAL; ++function) {
    SCOPED_TRACE("function " + std::to_string(function));
    grDepthBufferFunction(function);
    ASSERT_TRUE(glideShimBeginGL());
    reinterpret_cast<Enable>(glideShimGetProcAddress("glEnable"))(GL_DEPTH_TEST);
    reinterpret_cast<DepthFunc>(glideShimGetProcAddress("glDepthFunc"))(GL_ALWAYS);
    reinterpret_cast<WindowPos>(glideShimGetProcAddress("glWindowPos2i"))(0, 0);
    reinterpret_cast<DrawPixels>(glideShimGetProcAddress("glDrawPixels"))(
        kWidth, kHeight, GL_DEPTH_COMPONENT, GL_FLOAT, levels.data());
    glideShimEndGL();
    grDepthMask(FXFALSE);  // the depth pixels drew the raster colour too: black, depth kept
    grBufferClear(0x00000000u, 0, 0);
    const std::vector<FxU16> stored = read_codes();
    draw_rect(0, 0, kWidth, kHeight, white_vertex());
    const std::vector<FxU16> frame = read_buffer();
    int passed = 0, failed = 0, wrong = 0;
    for (std::size_t i = 0; i < stored.size(); ++i) {
      const bool pass = voodoo_ref::depth_test_passes(function, 1000, stored[i]);
      passed += pass, failed += !pass;
      if (frame[i] != (pass ? 0xFFFF : 0) && ++wrong <= 3) {
        ADD_FAILURE() << "pixel " << i << " stored code " << stored[i] << ": want "
                      << (pass ? "drawn" : "not drawn");
      }
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(passed, 0);
    EXPECT_GT(failed, 0);
  }
  expect_no_error();
}

TEST_F(DepthCompareToBiasTest, NotEqualDrawsEachPixelOnceAcrossBothSides) {
  // A sloped quad whose Z codes run from 800 to 1200 across x, NOTEQUAL against bias 1000,
  // additive blending: a pixel drawn twice would read 2 x 100. Stored codes on both sides.
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS);
  grDepthBufferFunction(GR_CMP_NOTEQUAL);
  grDepthBiasLevel(1000);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ZERO);
  std::vector<FxU16> codes(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      codes[static_cast<std::size_t>(y * kWidth + x)] = static_cast<FxU16>(968 + x + (y % 3) * 16);
    }
  }
  grDepthMask(FXFALSE);
  grBufferClear(0x00000000u, 0, 0);
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_AUXBUFFER, 0, 0, GR_LFB_SRC_FMT_ZA16, kWidth, kHeight,
                               kWidth * 2, codes.data()));
  grDepthMask(FXTRUE);
  GrVertex v[4];
  const float xs[4] = {0, kWidth, kWidth, 0}, ys[4] = {0, 0, kHeight, kHeight};
  for (int k = 0; k < 4; ++k) {
    v[k] = vertex();
    v[k].x = xs[k], v[k].y = ys[k];
    v[k].r = v[k].g = v[k].b = 100.0f;
    v[k].ooz = 800.0f + 400.0f * xs[k] / kWidth;
  }
  grDrawTriangle(&v[0], &v[1], &v[2]);
  grDrawTriangle(&v[0], &v[2], &v[3]);
  const std::vector<FxU16> frame = read_buffer();
  const FxU16 once = voodoo_ref::pack_rgb565({100, 100, 100, 255});
  int passed = 0;
  for (std::size_t i = 0; i < codes.size(); ++i) {
    const bool pass = codes[i] != 1000;
    passed += pass;
    ASSERT_EQ(frame[i], pass ? once : 0) << "pixel " << i << " stored " << codes[i];
  }
  EXPECT_GT(passed, kWidth * kHeight / 2);
  EXPECT_LT(passed, kWidth * kHeight);
  // Redrawing the same quad: its own depths are stored now, and NOTEQUAL passes wherever their
  // code is not 1000 (the hardware compares the bias, not the pixel's depth).
  const std::vector<FxU16> stored = read_codes();
  grDepthMask(FXFALSE);  // clear the colour only
  grBufferClear(0x00000000u, 0, 0);
  grDepthMask(FXTRUE);
  grDrawTriangle(&v[0], &v[1], &v[2]);
  grDrawTriangle(&v[0], &v[2], &v[3]);
  const std::vector<FxU16> again = read_buffer();
  for (std::size_t i = 0; i < stored.size(); ++i) {
    ASSERT_EQ(again[i], stored[i] != 1000 ? once : 0) << "pixel " << i << " stored " << stored[i];
  }
  expect_no_error();
}

TEST_F(DepthCompareToBiasTest, PerfStatsCountTheBiasComparisonAsTheDepthTest) {
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS);
  grDepthBufferFunction(GR_CMP_GREATER);
  grDepthBiasLevel(500);
  std::vector<FxU16> codes(kWidth * kHeight);
  int expected_fail = 0;
  for (std::size_t i = 0; i < codes.size(); ++i) {
    codes[i] = static_cast<FxU16>(i % 1000);  // 500 > code for codes 0..499
    expected_fail += !(500 > codes[i]);
  }
  GrVertex style = white_vertex();
  style.ooz = 100.0f;
  grSstResetPerfStats();
  const std::vector<FxU16> stored = draw_over(codes, style);
  ASSERT_EQ(stored, codes);
  GrSstPerfStats_t stats;
  grSstPerfStats(&stats);
  EXPECT_EQ(stats.pixelsIn, static_cast<FxU32>(kWidth * kHeight));
  EXPECT_EQ(stats.zFuncFail, static_cast<FxU32>(expected_fail));
  EXPECT_EQ(stats.pixelsOut, static_cast<FxU32>(kWidth * kHeight - expected_fail));
  expect_no_error();
}

}  // namespace
