// Alpha blending with every Glide factor against the CPU Voodoo model. GL's blender rounds
// where the Voodoo computes (src*(a+1) + dst*(256-a)) >> 8, so a channel may differ by one 565
// step (measured on this Mesa: 3.4% of pixels); more than one step is a real error.
#include "glide_window.h"
#include "voodoo_reference.h"

#include <cstdlib>
#include <random>

namespace {

class BlendTest : public GlideWindowTest {};

TEST_F(BlendTest, EveryFactorPairIsWithinOne565StepOfTheVoodoo) {
  grDitherMode(GR_DITHER_DISABLE);
  std::mt19937 random(17);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<FxU16> background(kWidth * kHeight);
  for (FxU16 &p : background) p = static_cast<FxU16>(random());
  std::vector<voodoo_ref::Rgba> source(kWidth * kHeight);
  for (auto &c : source) c = {byte(random), byte(random), byte(random), byte(random)};
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);

  const GrAlphaBlendFnc_t sources[] = {GR_BLEND_ZERO, GR_BLEND_SRC_ALPHA, GR_BLEND_DST_COLOR,
                                       GR_BLEND_DST_ALPHA, GR_BLEND_ONE,
                                       GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE_MINUS_DST_COLOR,
                                       GR_BLEND_ONE_MINUS_DST_ALPHA, GR_BLEND_ALPHA_SATURATE};
  const GrAlphaBlendFnc_t destinations[] = {GR_BLEND_ZERO, GR_BLEND_SRC_ALPHA, GR_BLEND_SRC_COLOR,
                                            GR_BLEND_DST_ALPHA, GR_BLEND_ONE,
                                            GR_BLEND_ONE_MINUS_SRC_ALPHA,
                                            GR_BLEND_ONE_MINUS_SRC_COLOR,
                                            GR_BLEND_ONE_MINUS_DST_ALPHA, GR_BLEND_PREFOG_COLOR};
  long exact = 0, total = 0;
  for (GrAlphaBlendFnc_t sf : sources) {
    for (GrAlphaBlendFnc_t df : destinations) {
      grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
      ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, kWidth, kHeight,
                                   kWidth * 2, background.data()));
      grAlphaBlendFunction(sf, df, GR_BLEND_ONE, GR_BLEND_ZERO);
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          const voodoo_ref::Rgba &c = source[static_cast<std::size_t>(y * kWidth + x)];
          GrVertex style = vertex();
          style.r = static_cast<float>(c.r), style.g = static_cast<float>(c.g);
          style.b = static_cast<float>(c.b), style.a = static_cast<float>(c.a);
          draw_rect(static_cast<float>(x), static_cast<float>(y), static_cast<float>(x + 1),
                    static_cast<float>(y + 1), style);
        }
      }
      const std::vector<FxU16> frame = read_buffer();
      int worst = 0;
      for (std::size_t i = 0; i < frame.size(); ++i) {
        const FxU16 want = voodoo_ref::blend_to_rgb565(source[i], background[i], sf, df);
        const FxU16 got = frame[i];
        const int diff = std::max({std::abs(red5(got) - red5(want)),
                                   std::abs(green6(got) - green6(want)),
                                   std::abs(blue5(got) - blue5(want))});
        worst = std::max(worst, diff);
        exact += diff == 0;
        ++total;
      }
      EXPECT_LE(worst, 1) << "blend factors src " << sf << " dst " << df;
    }
  }
  // Report, not assert, how often GL's rounding agrees exactly with the Voodoo's.
  std::printf("blend: %.1f%% of pixels exact over %ld\n", 100.0 * static_cast<double>(exact) / static_cast<double>(total), total);
  expect_no_error();
}

}  // namespace
