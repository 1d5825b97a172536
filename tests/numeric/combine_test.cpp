// The colour, alpha and texture combine units against the CPU Voodoo reference, for every
// function, factor, local and other source and invert flag. Each configuration draws 4096
// pixels with random iterated colours, random texels and a random constant colour.
// Tolerance: the hardware result and ours may differ by 1 of 255 before 565 truncation (the
// issue's bound); in practice the shader reproduces the (f+1)>>8 arithmetic exactly.
#include "glide_window.h"
#include "voodoo_reference.h"

#include <functional>
#include <iterator>
#include <random>
#include <sstream>
#include <string>

namespace {

constexpr int kFunctions[] = {
    GR_COMBINE_FUNCTION_ZERO,
    GR_COMBINE_FUNCTION_LOCAL,
    GR_COMBINE_FUNCTION_LOCAL_ALPHA,
    GR_COMBINE_FUNCTION_SCALE_OTHER,
    GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL,
    GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL_ALPHA,
    GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL,
    GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL,
    GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL_ALPHA,
    GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL,
    GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL_ALPHA,
};
// Voodoo 1 FBI factors (TEXTURE_RGB is a Voodoo 2 addition).
constexpr int kFactors[] = {
    GR_COMBINE_FACTOR_ZERO,          GR_COMBINE_FACTOR_LOCAL,
    GR_COMBINE_FACTOR_OTHER_ALPHA,   GR_COMBINE_FACTOR_LOCAL_ALPHA,
    GR_COMBINE_FACTOR_TEXTURE_ALPHA, GR_COMBINE_FACTOR_ONE,
    GR_COMBINE_FACTOR_ONE_MINUS_LOCAL, GR_COMBINE_FACTOR_ONE_MINUS_OTHER_ALPHA,
    GR_COMBINE_FACTOR_ONE_MINUS_LOCAL_ALPHA, GR_COMBINE_FACTOR_ONE_MINUS_TEXTURE_ALPHA,
};
constexpr int kLocals[] = {GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_LOCAL_CONSTANT};
constexpr int kOthers[] = {GR_COMBINE_OTHER_ITERATED, GR_COMBINE_OTHER_TEXTURE,
                           GR_COMBINE_OTHER_CONSTANT};

std::string describe(const char *unit, const voodoo_ref::CombineConfig &c) {
  std::ostringstream s;
  s << unit << "(function " << c.function << ", factor " << c.factor << ", local " << c.local
    << ", other " << c.other << ", invert " << c.invert << ")";
  return s.str();
}

// True when an observed 565 channel is the truncation of a value within 1 of `expected`.
bool within_one_level(int observed, int expected, int bits) {
  const int shift = 8 - bits;
  for (int v = expected - 1; v <= expected + 1; ++v) {
    if (v >= 0 && v <= 255 && (v >> shift) == observed) return true;
  }
  return false;
}

class CombineTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    grDitherMode(GR_DITHER_DISABLE);  // the reference models the truncating write
    std::mt19937 random(1999);
    std::uniform_int_distribution<int> byte(0, 255);
    // AI_88 texels give full 8-bit texture alpha and intensity, one per pixel.
    texels_.resize(kWidth * kHeight);
    iterated_.resize(kWidth * kHeight);
    for (int i = 0; i < kWidth * kHeight; ++i) {
      texels_[static_cast<std::size_t>(i)] = static_cast<FxU16>(byte(random) << 8 | byte(random));
      iterated_[static_cast<std::size_t>(i)] = {byte(random), byte(random), byte(random), byte(random)};
    }
    GrTexInfo info{GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_ALPHA_INTENSITY_88, texels_.data()};
    grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
    expect_no_error();
  }

  // One small triangle per pixel, with that pixel's iterated colour; s,t put texel (x,y) under
  // it. In window coordinates the legs are 1.875 long (1.9 snapped to the 1/16 subpixel grid):
  // the triangle covers its own pixel's centre (x+0.5, y+0.5), where x+y is 1 from the corner,
  // and none of its neighbours' (x+y is 2 there), so every pixel is drawn exactly once, with
  // half the triangles of a quad.
  void draw_pixels() {
    constexpr float kLeg = 1.875f;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const voodoo_ref::Rgba &c = iterated_[static_cast<std::size_t>(y * kWidth + x)];
        GrVertex v[3];
        const float xs[3] = {0, kLeg, 0}, ys[3] = {0, 0, kLeg};
        for (int k = 0; k < 3; ++k) {
          v[k] = vertex();
          v[k].x = static_cast<float>(x) + xs[k];
          v[k].y = static_cast<float>(y) + ys[k];
          v[k].r = static_cast<float>(c.r), v[k].g = static_cast<float>(c.g);
          v[k].b = static_cast<float>(c.b), v[k].a = static_cast<float>(c.a);
          // 64 texels span s = 0..256: 4 units per texel.
          v[k].tmuvtx[0].sow = 4.0f * v[k].x;
          v[k].tmuvtx[0].tow = 4.0f * v[k].y;
        }
        grDrawTriangle(&v[0], &v[1], &v[2]);
      }
    }
  }

  voodoo_ref::CombineInputs inputs(int x, int y, const voodoo_ref::Rgba &constant) const {
    const FxU16 t = texels_[static_cast<std::size_t>(y * kWidth + x)];
    voodoo_ref::CombineInputs in;
    in.iterated = iterated_[static_cast<std::size_t>(y * kWidth + x)];
    in.texture = voodoo_ref::decode_texel(GR_TEXFMT_ALPHA_INTENSITY_88, t);
    in.constant = constant;
    return in;
  }

  // Makes the alpha of every later draw visible in the colour buffer: blending ZERO/SRC_ALPHA
  // over white leaves alpha/255 in each channel.
  static void show_alpha_as_colour() {
    grAlphaBlendFunction(GR_BLEND_ZERO, GR_BLEND_SRC_ALPHA, GR_BLEND_ZERO, GR_BLEND_ZERO);
    grBufferClear(0xFFFFFFFFu, 0, 0);
  }

  // Compares one channel (or all three) of the frame with `want` per pixel; returns mismatches.
  int compare(const std::string &what, const std::vector<FxU16> &frame,
              const std::function<voodoo_ref::Rgba(int, int)> &want, bool rgb) {
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const voodoo_ref::Rgba w = want(x, y);
        const FxU16 got = frame[static_cast<std::size_t>(y * kWidth + x)];
        const bool ok = rgb ? within_one_level(red5(got), w.r, 5) &&
                                  within_one_level(green6(got), w.g, 6) &&
                                  within_one_level(blue5(got), w.b, 5)
                            : within_one_level(green6(got), w.a, 6);
        if (!ok) {
          ADD_FAILURE() << what << " at (" << x << "," << y << "): want " << w << ", got 565 ("
                        << red5(got) << "," << green6(got) << "," << blue5(got) << ")";
          return 1;
        }
      }
    }
    return 0;
  }

  // A random grConstantColorValue (the window is ARGB), returned as the reference reads it.
  static voodoo_ref::Rgba set_random_constant(std::mt19937 &random) {
    const GrColor_t argb = std::uniform_int_distribution<unsigned>()(random);
    grConstantColorValue(argb);
    return {static_cast<int>(argb >> 16 & 0xFF), static_cast<int>(argb >> 8 & 0xFF),
            static_cast<int>(argb & 0xFF), static_cast<int>(argb >> 24)};
  }

  std::vector<FxU16> texels_;
  std::vector<voodoo_ref::Rgba> iterated_;
};

// The exhaustive tests, one instance per combine function, so that ctest can spread them over
// processes (and cores). Each instance draws the configurations of its function, with the same
// random constant colours as one run over every function would draw for them.
class CombineFunctionTest : public CombineTest,
                            public ::testing::WithParamInterface<std::size_t> {
 protected:
  int function() const { return kFunctions[GetParam()]; }

  // The colour and alpha tests draw one random constant per configuration: 120 per function.
  static constexpr int kConstantsPerFunction = 10 * 2 * 3 * 2;
  std::mt19937 constants(unsigned seed) const {
    std::mt19937 random(seed);
    random.discard(static_cast<unsigned long long>(kConstantsPerFunction) * GetParam());
    return random;
  }
};

TEST_P(CombineFunctionTest, ColorCombineMatchesReferenceForEveryConfiguration) {
  std::mt19937 random = constants(7);
  // a_local = iterated alpha, a_other = texture alpha, for the colour unit's alpha factors.
  const voodoo_ref::CombineConfig alpha{GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                                        GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, false};
  grAlphaCombine(alpha.function, alpha.factor, alpha.local, alpha.other, FXFALSE);
  int configurations = 0, mismatches = 0;
  for (int factor : kFactors)
    for (int local : kLocals)
      for (int other : kOthers)
        for (bool invert : {false, true}) {
          const voodoo_ref::CombineConfig color{function(), factor, local, other, invert};
          const voodoo_ref::Rgba constant = set_random_constant(random);
          grColorCombine(function(), factor, local, other, invert ? FXTRUE : FXFALSE);
          draw_pixels();
          ++configurations;
          mismatches += compare(describe("grColorCombine", color), read_buffer(),
                                [&](int x, int y) {
                                  return voodoo_ref::combine_fbi(color, alpha,
                                                                 inputs(x, y, constant));
                                },
                                true);
          if (mismatches > 5) return;
        }
  expect_no_error();
  EXPECT_EQ(configurations, kConstantsPerFunction);
}

TEST_P(CombineFunctionTest, AlphaCombineMatchesReferenceForEveryConfiguration) {
  show_alpha_as_colour();
  const voodoo_ref::CombineConfig color{GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_ZERO,
                                        GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED, false};
  grColorCombine(color.function, color.factor, color.local, color.other, FXFALSE);
  std::mt19937 random = constants(11);
  int configurations = 0, mismatches = 0;
  for (int factor : kFactors)
    for (int local : kLocals)
      for (int other : kOthers)
        for (bool invert : {false, true}) {
          const voodoo_ref::CombineConfig alpha{function(), factor, local, other, invert};
          const voodoo_ref::Rgba constant = set_random_constant(random);
          grAlphaCombine(function(), factor, local, other, invert ? FXTRUE : FXFALSE);
          grBufferClear(0xFFFFFFFFu, 0, 0);
          draw_pixels();
          ++configurations;
          mismatches += compare(describe("grAlphaCombine", alpha), read_buffer(),
                                [&](int x, int y) {
                                  return voodoo_ref::combine_fbi(color, alpha,
                                                                 inputs(x, y, constant));
                                },
                                false);
          if (mismatches > 5) return;
        }
  expect_no_error();
  EXPECT_EQ(configurations, kConstantsPerFunction);
}

TEST_P(CombineFunctionTest, TextureCombineMatchesReferenceForEveryConfiguration) {
  // ARGB_8332 texels: distinct R, G, B and a full 8-bit alpha.
  std::mt19937 random(5);
  std::uniform_int_distribution<int> texel(0, 0xFFFF);
  std::vector<FxU16> texels(kWidth * kHeight);
  for (FxU16 &t : texels) t = static_cast<FxU16>(texel(random));
  GrTexInfo info{GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_ARGB_8332, texels.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  // The colour unit passes the TMU's RGB through; its alpha is shown by blending.
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  guAlphaSource(GR_ALPHASOURCE_TEXTURE_ALPHA);
  const int tmu_factors[] = {GR_COMBINE_FACTOR_ZERO, GR_COMBINE_FACTOR_LOCAL,
                             GR_COMBINE_FACTOR_OTHER_ALPHA, GR_COMBINE_FACTOR_LOCAL_ALPHA,
                             GR_COMBINE_FACTOR_DETAIL_FACTOR, GR_COMBINE_FACTOR_LOD_FRACTION,
                             GR_COMBINE_FACTOR_ONE, GR_COMBINE_FACTOR_ONE_MINUS_LOCAL,
                             GR_COMBINE_FACTOR_ONE_MINUS_OTHER_ALPHA,
                             GR_COMBINE_FACTOR_ONE_MINUS_LOCAL_ALPHA,
                             GR_COMBINE_FACTOR_ONE_MINUS_DETAIL_FACTOR,
                             GR_COMBINE_FACTOR_ONE_MINUS_LOD_FRACTION};
  auto texel_at = [&](int x, int y) {
    return voodoo_ref::decode_texel(GR_TEXFMT_ARGB_8332,
                                    texels[static_cast<std::size_t>(y * kWidth + x)]);
  };
  const int combine_function = function();
  int mismatches = 0;
  for (int factor : tmu_factors)
    for (bool invert : {false, true}) {
      const voodoo_ref::TexCombineConfig tmu{combine_function, factor, combine_function, factor,
                                           invert, invert};
      grTexCombine(GR_TMU0, combine_function, factor, combine_function, factor, invert, invert);
      grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
      draw_pixels();
      const std::string what = "grTexCombine(function " + std::to_string(combine_function) +
                               ", factor " + std::to_string(factor) + ", invert " +
                               std::to_string(invert) + ")";
      auto want = [&](int x, int y) {
        return voodoo_ref::combine_tmu(tmu, texel_at(x, y), voodoo_ref::kNoUpstreamTmu);
      };
      mismatches += compare(what + " rgb", read_buffer(), want, true);
      show_alpha_as_colour();
      draw_pixels();
      mismatches += compare(what + " alpha", read_buffer(), want, false);
      if (mismatches > 5) return;
    }
  expect_no_error();
}

INSTANTIATE_TEST_SUITE_P(EveryFunction, CombineFunctionTest,
                         ::testing::Range<std::size_t>(0, std::size(kFunctions)),
                         [](const ::testing::TestParamInfo<std::size_t> &instance) {
                           return "function" + std::to_string(kFunctions[instance.param]);
                         });

TEST_F(CombineTest, ChromaKeyDiscardsExactlyTheMatchingOtherColour) {
  // Other = iterated colour; key one pixel's colour and a colour no pixel has.
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                 GR_COMBINE_OTHER_ITERATED, FXFALSE);
  const voodoo_ref::Rgba keyed = iterated_[100];
  grChromakeyValue(static_cast<GrColor_t>(keyed.r << 16 | keyed.g << 8 | keyed.b));
  grChromakeyMode(GR_CHROMAKEY_ENABLE);
  grBufferClear(0x00000000u, 0, 0);
  draw_pixels();
  const std::vector<FxU16> frame = read_buffer();
  int discarded = 0;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    const voodoo_ref::Rgba &c = iterated_[static_cast<std::size_t>(i)];
    const bool expect_discard = voodoo_ref::chroma_key_discards(c, keyed);
    const FxU16 drawn = voodoo_ref::pack_rgb565(c);
    if (expect_discard) {
      ++discarded;
      EXPECT_EQ(frame[static_cast<std::size_t>(i)], 0) << "pixel " << i << " matched the key";
    } else {
      EXPECT_EQ(frame[static_cast<std::size_t>(i)], drawn) << "pixel " << i;
    }
  }
  EXPECT_GE(discarded, 1);
  expect_no_error();
}

TEST_F(CombineTest, AlphaTestPassesExactlyWhereTheReferenceDoes) {
  // Colour = white, alpha = iterated; each function against reference 128 and the extremes.
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  guAlphaSource(GR_ALPHASOURCE_ITERATED_ALPHA);
  for (int function = GR_CMP_NEVER; function <= GR_CMP_ALWAYS; ++function) {
    for (int reference : {0, 128, 255}) {
      grAlphaTestFunction(function);
      grAlphaTestReferenceValue(static_cast<GrAlpha_t>(reference));
      grBufferClear(0x00000000u, 0, 0);
      draw_pixels();
      const std::vector<FxU16> frame = read_buffer();
      int wrong = 0;
      for (int i = 0; i < kWidth * kHeight; ++i) {
        const bool pass =
            voodoo_ref::alpha_test_passes(function, iterated_[static_cast<std::size_t>(i)].a, reference);
        wrong += (frame[static_cast<std::size_t>(i)] == 0xFFFF) != pass;
      }
      EXPECT_EQ(wrong, 0) << "alpha test function " << function << " reference " << reference;
    }
  }
  expect_no_error();
}

}  // namespace
