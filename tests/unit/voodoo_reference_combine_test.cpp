// Unit tests of the Voodoo 1 CPU reference (tests/support/voodoo_reference.*), its combine units
// (the FBI's colour and alpha units, the TMU's) and per-pixel tests, against values worked out by
// hand from the team's notes on MAME, 86Box and 3dfx's Glide sources (shared/docs), so that the
// reference can be trusted when it judges the shim. Each expected number is derived in a comment.
// Texels, sampling, blending, depth and gamma: voodoo_reference_pixel_test.cpp.
#include "voodoo_reference.h"

#include <glide.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace {

using voodoo_ref::CombineConfig;
using voodoo_ref::CombineInputs;
using voodoo_ref::Rgba;
using voodoo_ref::TexCombineConfig;

// grColorCombine / grAlphaCombine argument lists, as an application would write them.
CombineConfig combine(int function, int factor, int local, int other, bool invert = false) {
  return {function, factor, local, other, invert};
}

// ---- combine units ---------------------------------------------------------------------------

TEST(VoodooRefCombine, ScaleOtherWithFactorOneIsIdentityForAllInputs) {
  const CombineConfig color = combine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE);
  const CombineConfig alpha = color;
  for (int v = 0; v < 256; ++v) {
    CombineInputs in;
    in.texture = {v, 255 - v, v / 2, v};
    in.iterated = {7, 7, 7, 7};
    // f = 255, so (v * 256) >> 8 = v exactly: the +1 is what makes ONE an identity.
    EXPECT_EQ(voodoo_ref::combine_fbi(color, alpha, in), in.texture) << "v=" << v;
  }
}

TEST(VoodooRefCombine, TextureAlphaTimesIteratedAlpha) {
  // grAlphaCombine(SCALE_OTHER, LOCAL, ITERATED, TEXTURE): (t * (i + 1)) >> 8.
  const CombineConfig color = combine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ZERO,
                                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED);
  const CombineConfig alpha = combine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE);
  CombineInputs in;
  in.texture = {0, 0, 0, 255};
  in.iterated = {0, 0, 0, 170};
  EXPECT_EQ(voodoo_ref::combine_fbi(color, alpha, in).a, 170);  // (255 * 171) >> 8 = 170
  in.texture.a = 200;
  in.iterated.a = 100;
  EXPECT_EQ(voodoo_ref::combine_fbi(color, alpha, in).a, 78);  // 20200 / 256 = 78.9
  in.texture.a = 128;
  in.iterated.a = 128;
  EXPECT_EQ(voodoo_ref::combine_fbi(color, alpha, in).a, 64);  // 16512 / 256 = 64.5
}

TEST(VoodooRefCombine, EveryCombineFunctionMatchesItsEquation) {
  // other = 200 (texture), local = 100 (iterated), a_local = 127 (iterated alpha), factor
  // LOCAL_ALPHA: f + 1 = 128, so each product is (x * 128) >> 8 = floor(x / 2).
  CombineInputs in;
  in.texture = {200, 200, 200, 0};
  in.iterated = {100, 100, 100, 127};
  const CombineConfig alpha = combine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ZERO,
                                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE);
  struct Case {
    int function;
    int expected;
  };
  const Case cases[] = {
      {GR_COMBINE_FUNCTION_ZERO, 0},
      {GR_COMBINE_FUNCTION_LOCAL, 100},
      {GR_COMBINE_FUNCTION_LOCAL_ALPHA, 127},
      {GR_COMBINE_FUNCTION_SCALE_OTHER, 100},                             // 200/2
      {GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL, 200},                   // 100 + 100
      {GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL_ALPHA, 227},             // 100 + 127
      {GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL, 50},                  // (200-100)/2
      {GR_COMBINE_FUNCTION_BLEND, 150},                                   // 50 + 100
      {GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL_ALPHA, 177}, // 50 + 127
      {GR_COMBINE_FUNCTION_BLEND_LOCAL, 50},                              // -50 + 100
      {GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL_ALPHA, 77},        // -50 + 127
  };
  for (const Case& c : cases) {
    const CombineConfig color = combine(c.function, GR_COMBINE_FACTOR_LOCAL_ALPHA,
                                        GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE);
    const Rgba out = voodoo_ref::combine_fbi(color, alpha, in);
    EXPECT_EQ(out, (Rgba{c.expected, c.expected, c.expected, 127})) << "function " << c.function;
  }
}

TEST(VoodooRefCombine, AlphaUnitFunctionsUseAlphaInputs) {
  // Alpha unit: other = texture alpha 200, local = iterated alpha 100, factor ONE_MINUS_LOCAL
  // gives f = 155, f + 1 = 156.
  CombineInputs in;
  in.texture = {1, 2, 3, 200};
  in.iterated = {4, 5, 6, 100};
  const CombineConfig color = combine(GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_ZERO,
                                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED);
  struct Case {
    int function;
    int expected;
  };
  const Case cases[] = {
      {GR_COMBINE_FUNCTION_ZERO, 0},
      {GR_COMBINE_FUNCTION_LOCAL, 100},
      {GR_COMBINE_FUNCTION_LOCAL_ALPHA, 100},
      {GR_COMBINE_FUNCTION_SCALE_OTHER, 121},         // 200 * 156 = 31200, / 256 = 121.9
      {GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL, 221},
      {GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL, 60},  // 100 * 156 = 15600, / 256 = 60.9
      {GR_COMBINE_FUNCTION_BLEND, 160},
      {GR_COMBINE_FUNCTION_BLEND_LOCAL, 39},          // -15600 / 256 = -60.9 -> -61, + 100
  };
  for (const Case& c : cases) {
    const CombineConfig alpha = combine(c.function, GR_COMBINE_FACTOR_ONE_MINUS_LOCAL,
                                        GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE);
    EXPECT_EQ(voodoo_ref::combine_fbi(color, alpha, in).a, c.expected) << "function "
                                                                        << c.function;
  }
}

TEST(VoodooRefCombine, ColourFactorsSelectTheirSourceWithAlphaUnitSelections) {
  // SCALE_OTHER with other = 255 outputs exactly f: (255 * (f + 1)) >> 8 = f.
  // Colour local = iterated RGB (10, 20, 30). a_other comes from grAlphaCombine's other
  // (ITERATED: 40) and a_local from its local (CONSTANT: 90), not from the colour unit's own
  // selections (which would swap the two). Texture alpha is 150.
  CombineInputs in;
  in.iterated = {10, 20, 30, 40};
  in.constant = {255, 255, 255, 90};
  in.texture = {0, 0, 0, 150};
  const CombineConfig alpha = combine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ZERO,
                                      GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_ITERATED);
  struct Case {
    int factor;
    Rgba expected;
  };
  const Case cases[] = {
      {GR_COMBINE_FACTOR_ZERO, {0, 0, 0, 90}},
      {GR_COMBINE_FACTOR_LOCAL, {10, 20, 30, 90}},
      {GR_COMBINE_FACTOR_OTHER_ALPHA, {40, 40, 40, 90}},
      {GR_COMBINE_FACTOR_LOCAL_ALPHA, {90, 90, 90, 90}},
      {GR_COMBINE_FACTOR_TEXTURE_ALPHA, {150, 150, 150, 90}},
      {GR_COMBINE_FACTOR_ONE, {255, 255, 255, 90}},
      {GR_COMBINE_FACTOR_ONE_MINUS_LOCAL, {245, 235, 225, 90}},
      {GR_COMBINE_FACTOR_ONE_MINUS_OTHER_ALPHA, {215, 215, 215, 90}},
      {GR_COMBINE_FACTOR_ONE_MINUS_LOCAL_ALPHA, {165, 165, 165, 90}},
      {GR_COMBINE_FACTOR_ONE_MINUS_TEXTURE_ALPHA, {105, 105, 105, 90}},
  };
  for (const Case& c : cases) {
    const CombineConfig color = combine(GR_COMBINE_FUNCTION_SCALE_OTHER, c.factor,
                                        GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_CONSTANT);
    EXPECT_EQ(voodoo_ref::combine_fbi(color, alpha, in), c.expected) << "factor " << c.factor;
  }
}

TEST(VoodooRefCombine, AlphaFactorsSelectTheirSource) {
  // Alpha SCALE_OTHER with a_other = constant alpha 255 outputs f. a_local = iterated 40,
  // texture alpha 150; in the alpha unit LOCAL and LOCAL_ALPHA are both a_local.
  CombineInputs in;
  in.iterated = {0, 0, 0, 40};
  in.constant = {0, 0, 0, 255};
  in.texture = {0, 0, 0, 150};
  const CombineConfig color = combine(GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_ZERO,
                                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED);
  struct Case {
    int factor;
    int expected;
  };
  const Case cases[] = {
      {GR_COMBINE_FACTOR_ZERO, 0},
      {GR_COMBINE_FACTOR_LOCAL, 40},
      {GR_COMBINE_FACTOR_OTHER_ALPHA, 255},
      {GR_COMBINE_FACTOR_LOCAL_ALPHA, 40},
      {GR_COMBINE_FACTOR_TEXTURE_ALPHA, 150},
      {GR_COMBINE_FACTOR_ONE, 255},
      {GR_COMBINE_FACTOR_ONE_MINUS_LOCAL, 215},
      {GR_COMBINE_FACTOR_ONE_MINUS_OTHER_ALPHA, 0},
      {GR_COMBINE_FACTOR_ONE_MINUS_LOCAL_ALPHA, 215},
      {GR_COMBINE_FACTOR_ONE_MINUS_TEXTURE_ALPHA, 105},
  };
  for (const Case& c : cases) {
    const CombineConfig alpha = combine(GR_COMBINE_FUNCTION_SCALE_OTHER, c.factor,
                                        GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_CONSTANT);
    EXPECT_EQ(voodoo_ref::combine_fbi(color, alpha, in).a, c.expected) << "factor " << c.factor;
  }
}

TEST(VoodooRefCombine, LocalAndOtherSourcesSelectTheirInputs) {
  CombineInputs in;
  in.iterated = {11, 12, 13, 14};
  in.texture = {21, 22, 23, 24};
  in.constant = {31, 32, 33, 34};
  in.depth_alpha = 44;
  auto other = [&](int color_other, int alpha_other) {
    return voodoo_ref::combine_other(
        combine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_ITERATED,
                color_other),
        combine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_ITERATED,
                alpha_other),
        in);
  };
  EXPECT_EQ(other(GR_COMBINE_OTHER_ITERATED, GR_COMBINE_OTHER_TEXTURE), (Rgba{11, 12, 13, 24}));
  EXPECT_EQ(other(GR_COMBINE_OTHER_TEXTURE, GR_COMBINE_OTHER_CONSTANT), (Rgba{21, 22, 23, 34}));
  EXPECT_EQ(other(GR_COMBINE_OTHER_CONSTANT, GR_COMBINE_OTHER_ITERATED), (Rgba{31, 32, 33, 14}));

  // Function LOCAL outputs the local selection: colour from grColorCombine's local, alpha from
  // grAlphaCombine's local (DEPTH = depth_alpha).
  auto local = [&](int color_local, int alpha_local) {
    return voodoo_ref::combine_fbi(
        combine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ZERO, color_local,
                GR_COMBINE_OTHER_TEXTURE),
        combine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ZERO, alpha_local,
                GR_COMBINE_OTHER_TEXTURE),
        in);
  };
  EXPECT_EQ(local(GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_LOCAL_CONSTANT), (Rgba{11, 12, 13, 34}));
  EXPECT_EQ(local(GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_LOCAL_ITERATED), (Rgba{31, 32, 33, 14}));
  EXPECT_EQ(local(GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_LOCAL_DEPTH), (Rgba{31, 32, 33, 44}));
  EXPECT_THROW(local(GR_COMBINE_LOCAL_DEPTH, GR_COMBINE_LOCAL_ITERATED), std::invalid_argument);
}

TEST(VoodooRefCombine, GlideDefaultCombinePassesVertexColourAndConstantAlpha) {
  // grSstWinOpen defaults: colour SCALE_OTHER, ONE, ITERATED, ITERATED; alpha SCALE_OTHER, ONE,
  // NONE, CONSTANT.
  const CombineConfig color = combine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED);
  const CombineConfig alpha = combine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                                      GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_CONSTANT);
  CombineInputs in;
  in.iterated = {12, 34, 56, 78};
  in.texture = {90, 91, 92, 93};
  in.constant = {255, 255, 255, 201};
  EXPECT_EQ(voodoo_ref::combine_fbi(color, alpha, in), (Rgba{12, 34, 56, 201}));
}

TEST(VoodooRefCombine, InvertGivesComplementOfClampedResult) {
  CombineInputs in;
  in.texture = {200, 30, 0, 0};
  in.iterated = {100, 100, 100, 0};
  const CombineConfig alpha = combine(GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_ZERO,
                                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED, true);
  // SCALE_OTHER_ADD_LOCAL, ONE: 300 -> 255 -> 0; 130 -> 125; 100 -> 155. ZERO alpha -> 255.
  const CombineConfig color =
      combine(GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL, GR_COMBINE_FACTOR_ONE,
              GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, true);
  EXPECT_EQ(voodoo_ref::combine_fbi(color, alpha, in), (Rgba{0, 125, 155, 255}));
}

TEST(VoodooRefCombine, NegativeProductsShiftTowardsMinusInfinity) {
  // BLEND with factor ZERO: ((0 - 100) * 1) >> 8 = -1 (floor), + 100 = 99, not 100.
  EXPECT_EQ(voodoo_ref::combine_channel(GR_COMBINE_FUNCTION_BLEND, 0, false, 0, 100, 0), 99);
  // BLEND_LOCAL with f = 127: (-101 * 128) >> 8 = floor(-50.5) = -51, + 101 = 50 (truncation
  // towards zero would give 51).
  EXPECT_EQ(voodoo_ref::combine_channel(GR_COMBINE_FUNCTION_BLEND_LOCAL, 127, false, 0, 101, 0),
            50);
  // Equal other and local: product 0, so BLEND returns local unchanged.
  EXPECT_EQ(voodoo_ref::combine_channel(GR_COMBINE_FUNCTION_BLEND, 0, false, 100, 100, 0), 100);
  // A negative sum clamps to 0 before the invert.
  EXPECT_EQ(voodoo_ref::combine_channel(GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL, 255, true, 0,
                                        100, 0),
            255);
}

TEST(VoodooRefCombine, UnknownEnumsThrow) {
  CombineInputs in;
  const CombineConfig ok = combine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                                   GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED);
  CombineConfig bad = ok;
  bad.function = 0xA;
  EXPECT_THROW(voodoo_ref::combine_fbi(bad, ok, in), std::invalid_argument);
  bad = ok;
  bad.factor = GR_COMBINE_FACTOR_TEXTURE_RGB;  // Voodoo 2 only
  EXPECT_THROW(voodoo_ref::combine_fbi(bad, ok, in), std::invalid_argument);
  bad = ok;
  bad.other = 3;
  EXPECT_THROW(voodoo_ref::combine_fbi(ok, bad, in), std::invalid_argument);
}

TEST(VoodooRefTmuCombine, DecalReturnsTheTexel) {
  // guTexCombineFunction(DECAL) = grTexCombine(LOCAL, NONE, LOCAL, NONE).
  const TexCombineConfig decal{GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE,
                               GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, false, false};
  const Rgba texel{10, 20, 30, 40};
  EXPECT_EQ(voodoo_ref::combine_tmu(decal, texel, voodoo_ref::kNoUpstreamTmu), texel);
  EXPECT_EQ(voodoo_ref::combine_tmu(decal, texel, Rgba{99, 99, 99, 99}), texel);
}

TEST(VoodooRefTmuCombine, ZeroFunctionOutputsZero) {
  // The grSstWinOpen default grTexCombine(ZERO, ...) makes the texture output 0.
  const TexCombineConfig zero{GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE,
                              GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, false, false};
  EXPECT_EQ(voodoo_ref::combine_tmu(zero, Rgba{10, 20, 30, 40}, Rgba{50, 60, 70, 80}),
            (Rgba{0, 0, 0, 0}));
}

TEST(VoodooRefTmuCombine, OtherIsTheUpstreamTmu) {
  const TexCombineConfig pass{GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                              GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, false,
                              false};
  const Rgba texel{10, 20, 30, 40};
  EXPECT_EQ(voodoo_ref::combine_tmu(pass, texel, Rgba{50, 60, 70, 80}), (Rgba{50, 60, 70, 80}));
  EXPECT_EQ(voodoo_ref::combine_tmu(pass, texel, voodoo_ref::kNoUpstreamTmu), (Rgba{0, 0, 0, 0}));

  // BLEND, ONE_MINUS_LOCAL_ALPHA: texel alpha 64 gives f = 191, f + 1 = 192.
  // r: (200 - 100) * 192 >> 8 = 75, + 100 = 175; alpha: (0 - 64) * 192 >> 8 = -48, + 64 = 16.
  const TexCombineConfig blend{GR_COMBINE_FUNCTION_BLEND, GR_COMBINE_FACTOR_ONE_MINUS_LOCAL_ALPHA,
                               GR_COMBINE_FUNCTION_BLEND, GR_COMBINE_FACTOR_ONE_MINUS_LOCAL_ALPHA,
                               false, false};
  EXPECT_EQ(voodoo_ref::combine_tmu(blend, Rgba{100, 100, 100, 64}, Rgba{200, 100, 0, 0}),
            (Rgba{175, 100, 25, 16}));
}

TEST(VoodooRefTmuCombine, DetailAndLodFractionFactorsAreZero) {
  const Rgba upstream{200, 100, 50, 250};
  // DETAIL_FACTOR -> f = 0: (x * 1) >> 8 = 0 for x < 256.
  const TexCombineConfig detail{GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_DETAIL_FACTOR,
                                GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOD_FRACTION,
                                false, false};
  EXPECT_EQ(voodoo_ref::combine_tmu(detail, Rgba{1, 2, 3, 4}, upstream), (Rgba{0, 0, 0, 0}));
  // Their ONE_MINUS forms are 255, an identity.
  const TexCombineConfig one_minus{
      GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE_MINUS_DETAIL_FACTOR,
      GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE_MINUS_LOD_FRACTION, false, false};
  EXPECT_EQ(voodoo_ref::combine_tmu(one_minus, Rgba{1, 2, 3, 4}, upstream), upstream);
}

// ---- per-pixel tests ---------------------------------------------------------------------------

TEST(VoodooRefPixelTests, AlphaTestComparesAlphaAgainstReference) {
  struct Case {
    int function;
    bool below, equal, above;  // alpha 99, 100, 101 against reference 100
  };
  const Case cases[] = {
      {GR_CMP_NEVER, false, false, false},  {GR_CMP_LESS, true, false, false},
      {GR_CMP_EQUAL, false, true, false},   {GR_CMP_LEQUAL, true, true, false},
      {GR_CMP_GREATER, false, false, true}, {GR_CMP_NOTEQUAL, true, false, true},
      {GR_CMP_GEQUAL, false, true, true},   {GR_CMP_ALWAYS, true, true, true},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(voodoo_ref::alpha_test_passes(c.function, 99, 100), c.below) << c.function;
    EXPECT_EQ(voodoo_ref::alpha_test_passes(c.function, 100, 100), c.equal) << c.function;
    EXPECT_EQ(voodoo_ref::alpha_test_passes(c.function, 101, 100), c.above) << c.function;
  }
}

TEST(VoodooRefPixelTests, ChromaKeyDiscardsExactRgbMatchOfOtherColour) {
  const Rgba key{10, 20, 30, 0};
  EXPECT_TRUE(voodoo_ref::chroma_key_discards(Rgba{10, 20, 30, 255}, key));  // alpha ignored
  EXPECT_FALSE(voodoo_ref::chroma_key_discards(Rgba{11, 20, 30, 0}, key));
  EXPECT_FALSE(voodoo_ref::chroma_key_discards(Rgba{10, 19, 30, 0}, key));
  EXPECT_FALSE(voodoo_ref::chroma_key_discards(Rgba{10, 20, 31, 0}, key));

  // The compared colour is the colour unit's 'other' (texture here), not the combined result.
  CombineInputs in;
  in.texture = {10, 20, 30, 0};
  in.iterated = {200, 200, 200, 0};
  const CombineConfig color = combine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_ZERO,
                                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE);
  const CombineConfig alpha = color;
  EXPECT_TRUE(voodoo_ref::chroma_key_discards(voodoo_ref::combine_other(color, alpha, in), key));
  EXPECT_FALSE(voodoo_ref::chroma_key_discards(voodoo_ref::combine_fbi(color, alpha, in), key));
}

TEST(VoodooRefTmuCombine, DetailFactorIsTheShiftedDistanceBelowTheBiasLimitedToMax) {
  // Bias 4 whole LODs = 1024 in 8.8; LOD 2.5 = 640: (384 << 2) >> 8 = 6.
  EXPECT_EQ(voodoo_ref::detail_factor(640, 4, 2, 255), 6);
  EXPECT_EQ(voodoo_ref::detail_factor(640, 4, 7, 255), 192);   // (384 << 7) >> 8
  EXPECT_EQ(voodoo_ref::detail_factor(640, 4, 7, 100), 100);   // limited to max
  EXPECT_EQ(voodoo_ref::detail_factor(0, 31, 7, 255), 255);    // saturates, no 8-bit wrap
  EXPECT_EQ(voodoo_ref::detail_factor(1024, 4, 7, 255), 0);    // LOD at the bias: zero
  EXPECT_EQ(voodoo_ref::detail_factor(1100, 4, 7, 255), 0);    // beyond it: zero
  EXPECT_EQ(voodoo_ref::detail_factor(0, -1, 3, 255), 0);      // a negative bias is below LOD 0
  EXPECT_EQ(voodoo_ref::detail_max_field(0.5f), 127);
  EXPECT_EQ(voodoo_ref::detail_max_field(1.0f), 255);
  EXPECT_THROW(voodoo_ref::detail_factor(0, 32, 0, 0), std::invalid_argument);
  EXPECT_THROW(voodoo_ref::detail_factor(0, 0, 8, 0), std::invalid_argument);
}

TEST(VoodooRefTmuCombine, DetailAndLodFractionFactorsFeedTheTmuCombine) {
  // BLEND_LOCAL on a white texel: ((0 - 255) * (f + 1) >> 8) + 255.
  const TexCombineConfig detail{GR_COMBINE_FUNCTION_BLEND_LOCAL, GR_COMBINE_FACTOR_DETAIL_FACTOR,
                                GR_COMBINE_FUNCTION_BLEND_LOCAL, GR_COMBINE_FACTOR_LOD_FRACTION,
                                false, false};
  const Rgba out = voodoo_ref::combine_tmu(detail, Rgba{255, 255, 255, 255},
                                           voodoo_ref::kNoUpstreamTmu, 99, 149);
  EXPECT_EQ(out.r, ((-255 * 100) >> 8) + 255);  // detail 99
  EXPECT_EQ(out.a, ((-255 * 150) >> 8) + 255);  // LOD fraction 149: 105
}

TEST(VoodooRefCombine, AlphaControlsItrgbPicksTheLocalByTextureAlphaBitSeven) {
  const CombineConfig local{GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE,
                            GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_NONE, false};
  CombineInputs in;
  in.iterated = {10, 20, 30, 40};
  in.constant = {200, 210, 220, 230};
  in.alpha_controls_itrgb = true;
  in.texture = {0, 0, 0, 0x80};
  EXPECT_EQ(voodoo_ref::combine_fbi(local, local, in), (Rgba{200, 210, 220, 40}));
  in.texture.a = 0x7F;
  EXPECT_EQ(voodoo_ref::combine_fbi(local, local, in), (Rgba{10, 20, 30, 40}));
}

}  // namespace
