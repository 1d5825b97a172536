// Unit tests of the Voodoo 1 CPU reference (tests/support/voodoo_reference.*) against values
// worked out by hand from the team's notes on MAME, 86Box and 3dfx's Glide sources (shared/docs), so that the reference
// can be trusted when it judges the shim. Each expected number is derived in a comment.
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
using voodoo_ref::Texture;

// grColorCombine / grAlphaCombine argument lists, as an application would write them.
CombineConfig combine(int function, int factor, int local, int other, bool invert = false) {
  return {function, factor, local, other, invert};
}

// A single-row INTENSITY_8 texture: texel value v decodes to {v, v, v, 255}.
Texture intensity_row(std::initializer_list<std::uint16_t> values) {
  return {static_cast<int>(values.size()), 1, GR_TEXFMT_INTENSITY_8, values};
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

// ---- texel expansion ---------------------------------------------------------------------------

TEST(VoodooRefTexel, Rgb565ExpandsByBitReplication) {
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_RGB_565, 31 << 11).r, 255);  // 11111 -> 0xFF
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_RGB_565, 1 << 11).r, 8);     // 00001 -> 0x08
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_RGB_565, 1 << 5).g, 4);      // 000001 -> 0x04
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_RGB_565, 63 << 5).g, 255);
  // 0x8410: r5 = 16 -> 0x84, g6 = 32 -> 0x82, b5 = 16 -> 0x84; shifting alone would give 0x80.
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_RGB_565, 0x8410), (Rgba{0x84, 0x82, 0x84, 255}));
}

TEST(VoodooRefTexel, Rgb565WordReinterpretedAsArgb4444) {
  // r5 = 11110b, g = b = 0: word 0xF000; as 4444, A = 0xF -> 255 and R = G = B = 0.
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_ARGB_4444, 0xF000), (Rgba{0, 0, 0, 255}));
  // r5 = 00001b (word 0x0800): A = 0, R = r5 bit 0 followed by g6[5:3] = 1000b -> 0x88.
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_ARGB_4444, 0x0800), (Rgba{0x88, 0, 0, 0}));
}

TEST(VoodooRefTexel, Argb4444NibblesTimes17) {
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_ARGB_4444, 0x1234),
            (Rgba{0x22, 0x33, 0x44, 0x11}));
}

TEST(VoodooRefTexel, Argb1555AlphaBitIsZeroOr255) {
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_ARGB_1555, 0x8000 | (1 << 10) | (2 << 5) | 31),
            (Rgba{8, 16, 255, 255}));  // 00010 -> 0x10
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_ARGB_1555, 0x7FFF), (Rgba{255, 255, 255, 0}));
}

TEST(VoodooRefTexel, Rgb332AndArgb8332ReplicateThreeAndTwoBits) {
  // 0xA5 = 101 001 01: R 101 -> 10110110 = 182, G 001 -> 00100100 = 36, B 01 -> 01010101 = 85.
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_RGB_332, 0xA5), (Rgba{182, 36, 85, 255}));
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_ARGB_8332, 0x7FA5), (Rgba{182, 36, 85, 0x7F}));
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_RGB_332, 0xFF), (Rgba{255, 255, 255, 255}));
}

TEST(VoodooRefTexel, AlphaIntensityFormats) {
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_ALPHA_8, 0x5A), (Rgba{0x5A, 0x5A, 0x5A, 0x5A}));
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_INTENSITY_8, 0x5A), (Rgba{0x5A, 0x5A, 0x5A, 255}));
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_ALPHA_INTENSITY_44, 0xA3),
            (Rgba{0x33, 0x33, 0x33, 0xAA}));
  EXPECT_EQ(voodoo_ref::decode_texel(GR_TEXFMT_ALPHA_INTENSITY_88, 0x1234),
            (Rgba{0x34, 0x34, 0x34, 0x12}));
}

TEST(VoodooRefTexel, PaletteAndNccFormatsThrow) {
  EXPECT_THROW(voodoo_ref::decode_texel(GR_TEXFMT_P_8, 1), std::invalid_argument);
  EXPECT_THROW(voodoo_ref::decode_texel(GR_TEXFMT_YIQ_422, 1), std::invalid_argument);
  EXPECT_THROW(voodoo_ref::decode_texel(GR_TEXFMT_AP_88, 1), std::invalid_argument);
}

// ---- texture sampling --------------------------------------------------------------------------

TEST(VoodooRefSampling, GlideStSpans256AcrossTheLongerSide) {
  // 64x16 (aspect 4x1): s 0..256 -> u 0..64, t 0..64 -> v 0..16.
  const auto wide = voodoo_ref::glide_st_to_texel(256.0, 64.0, 64, 16);
  EXPECT_DOUBLE_EQ(wide.u, 64.0);
  EXPECT_DOUBLE_EQ(wide.v, 16.0);
  // 8x32 (aspect 1x4): t 0..256 -> v 0..32, s 0..64 -> u 0..8.
  const auto tall = voodoo_ref::glide_st_to_texel(64.0, 128.0, 8, 32);
  EXPECT_DOUBLE_EQ(tall.u, 8.0);
  EXPECT_DOUBLE_EQ(tall.v, 16.0);
  // 256x256: s,t are texel coordinates already.
  const auto big = voodoo_ref::glide_st_to_texel(10.25, 3.5, 256, 256);
  EXPECT_DOUBLE_EQ(big.u, 10.25);
  EXPECT_DOUBLE_EQ(big.v, 3.5);
}

TEST(VoodooRefSampling, PointSamplingTakesTheTexelContainingTheCoordinate) {
  const Texture tex = intensity_row({0, 85, 170, 255});
  auto at = [&](double u) {
    return voodoo_ref::sample_texture(tex, {u, 0.5}, GR_TEXTUREFILTER_POINT_SAMPLED,
                                      GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP)
        .r;
  };
  EXPECT_EQ(at(0.0), 0);
  EXPECT_EQ(at(1.99), 85);  // no half-texel shift when point sampling
  EXPECT_EQ(at(2.0), 170);
  EXPECT_EQ(at(3.5), 255);
}

TEST(VoodooRefSampling, BilinearHalfwayBetween0And255) {
  const Texture tex = intensity_row({0, 255});
  // u = 1.0 is halfway between the texel centres 0.5 and 1.5: 16u - 8 = 8, f = 8,
  // weights 8*16 = 128 each: (0 * 128 + 255 * 128) >> 8 = 127 (GL_LINEAR would give 127.5).
  const Rgba out = voodoo_ref::sample_texture(tex, {1.0, 0.5}, GR_TEXTUREFILTER_BILINEAR,
                                              GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  EXPECT_EQ(out, (Rgba{127, 127, 127, 255}));
}

TEST(VoodooRefSampling, BilinearFractionIsQuantisedToSixteenths) {
  const Texture tex = intensity_row({0, 255});
  auto at = [&](double u) {
    return voodoo_ref::sample_texture(tex, {u, 0.5}, GR_TEXTUREFILTER_BILINEAR,
                                      GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP)
        .r;
  };
  EXPECT_EQ(at(0.5), 0);            // texel 0's centre: f = 0
  EXPECT_EQ(at(1.0 + 1.0 / 32), 127);  // 16.5 - 8 floors to f = 8, as at u = 1.0
  EXPECT_EQ(at(1.0 + 1.0 / 16), 143);  // f = 9: 255 * 144 = 36720, >> 8 = 143
  EXPECT_EQ(at(1.5 - 1.0 / 64), 239);  // f = 15: 255 * 240 = 61200, >> 8 = 239
  EXPECT_EQ(at(1.5), 255);
}

TEST(VoodooRefSampling, BilinearWeightsInTwoDimensions) {
  // Rows: (0, 64) and (128, 255). u = 0.75 -> f = 4, v = 1.25 -> g = 12.
  // Weights (16-f)(16-g) = 48, f(16-g) = 16, (16-f)g = 144, fg = 48 (sum 256):
  // 0*48 + 64*16 + 128*144 + 255*48 = 1024 + 18432 + 12240 = 31696, >> 8 = 123.
  const Texture tex{2, 2, GR_TEXFMT_INTENSITY_8, {0, 64, 128, 255}};
  const Rgba out = voodoo_ref::sample_texture(tex, {0.75, 1.25}, GR_TEXTUREFILTER_BILINEAR,
                                              GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  EXPECT_EQ(out, (Rgba{123, 123, 123, 255}));
}

TEST(VoodooRefSampling, ClampRepeatsTheEdgeTexel) {
  const Texture tex = intensity_row({10, 85, 170, 250});
  auto at = [&](double u, int filter) {
    return voodoo_ref::sample_texture(tex, {u, 0.5}, filter, GR_TEXTURECLAMP_CLAMP,
                                      GR_TEXTURECLAMP_CLAMP)
        .r;
  };
  for (int filter : {GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_BILINEAR}) {
    EXPECT_EQ(at(-3.0, filter), 10) << "filter " << filter;
    EXPECT_EQ(at(0.25, filter), 10) << "filter " << filter;  // bilinear taps -1 and 0 -> 0, 0
    EXPECT_EQ(at(3.75, filter), 250) << "filter " << filter;  // taps 3 and 4 -> 3, 3
    EXPECT_EQ(at(40.0, filter), 250) << "filter " << filter;
  }
}

TEST(VoodooRefSampling, WrapHasPeriodEqualToTheSize) {
  const Texture tex = intensity_row({10, 85, 170, 250});
  auto at = [&](double u, int filter) {
    return voodoo_ref::sample_texture(tex, {u, 0.5}, filter, GR_TEXTURECLAMP_WRAP,
                                      GR_TEXTURECLAMP_WRAP)
        .r;
  };
  for (int filter : {GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_BILINEAR}) {
    for (double u = -8.0; u < 8.0; u += 0.1875) {
      EXPECT_EQ(at(u, filter), at(u + 4.0, filter)) << "u=" << u << " filter " << filter;
    }
  }
  EXPECT_EQ(at(-0.5, GR_TEXTUREFILTER_POINT_SAMPLED), 250);  // index -1 wraps to 3
  // u = 0: taps -1 (-> 3) and 0 at f = 8: (250 * 128 + 10 * 128) >> 8 = 130.
  EXPECT_EQ(at(0.0, GR_TEXTUREFILTER_BILINEAR), 130);
}

TEST(VoodooRefSampling, ClampModesApplyPerAxis) {
  // 2x2: rows (0, 64) and (128, 255). s wraps, t clamps: u = -0.5 -> column 1, v = 5 -> row 1.
  const Texture tex{2, 2, GR_TEXFMT_INTENSITY_8, {0, 64, 128, 255}};
  const Rgba out = voodoo_ref::sample_texture(tex, {-0.5, 5.0}, GR_TEXTUREFILTER_POINT_SAMPLED,
                                              GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_CLAMP);
  EXPECT_EQ(out.r, 255);
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

// ---- alpha blend and 565 ----------------------------------------------------------------------

TEST(VoodooRefBlend, BlackOverDestinationWithSrcAlpha) {
  for (int d = 0; d < 256; ++d) {
    for (int a = 0; a < 256; ++a) {
      const Rgba out = voodoo_ref::alpha_blend(Rgba{0, 0, 0, a}, Rgba{d, d, d, 255},
                                               GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA);
      ASSERT_EQ(out.r, (d * (256 - a)) >> 8) << "d=" << d << " a=" << a;
    }
  }
  // Spot values: 200 * 128 >> 8 = 100; 255 * 255 >> 8 = 254 (a = 1 already darkens by one).
  EXPECT_EQ(voodoo_ref::alpha_blend(Rgba{0, 0, 0, 128}, Rgba{200, 200, 200, 255},
                                    GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA)
                .g,
            100);
  EXPECT_EQ(voodoo_ref::alpha_blend(Rgba{0, 0, 0, 1}, Rgba{255, 255, 255, 255},
                                    GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA)
                .b,
            254);
}

TEST(VoodooRefBlend, OneZeroIsTheSourceAndAlphaIsSourceAlpha) {
  for (int v = 0; v < 256; ++v) {
    const Rgba src{v, 255 - v, v / 3, 255 - v};
    EXPECT_EQ(voodoo_ref::alpha_blend(src, Rgba{9, 99, 199, 255}, GR_BLEND_ONE, GR_BLEND_ZERO),
              src);
  }
}

TEST(VoodooRefBlend, SourceFactorsScaleTheSource) {
  // src (100, 50, 200) a 64, dst (80, 160, 40) with no alpha planes (a 255); dst factor ZERO.
  const Rgba src{100, 50, 200, 64};
  const Rgba dst{80, 160, 40, 255};
  struct Case {
    int factor;
    Rgba expected;
  };
  const Case cases[] = {
      {GR_BLEND_ZERO, {0, 0, 0, 64}},
      {GR_BLEND_SRC_ALPHA, {25, 12, 50, 64}},            // x * 65 >> 8
      {GR_BLEND_DST_COLOR, {31, 31, 32, 64}},            // 100*81, 50*161, 200*41, >> 8
      {GR_BLEND_DST_ALPHA, {100, 50, 200, 64}},          // 255 + 1 = 256
      {GR_BLEND_ONE, {100, 50, 200, 64}},
      {GR_BLEND_ONE_MINUS_SRC_ALPHA, {75, 37, 150, 64}},  // x * 192 >> 8
      {GR_BLEND_ONE_MINUS_DST_COLOR, {68, 18, 168, 64}},  // 100*176, 50*96, 200*216, >> 8
      {GR_BLEND_ONE_MINUS_DST_ALPHA, {0, 0, 0, 64}},     // x * 1 >> 8
      {GR_BLEND_ALPHA_SATURATE, {0, 0, 1, 64}},          // min(64, 256 - 255) + 1 = 2
  };
  for (const Case& c : cases) {
    EXPECT_EQ(voodoo_ref::alpha_blend(src, dst, c.factor, GR_BLEND_ZERO), c.expected)
        << "factor " << c.factor;
  }
  // With alpha planes (dst alpha 100): ALPHA_SATURATE = min(64, 156) + 1 = 65, as SRC_ALPHA.
  EXPECT_EQ(voodoo_ref::alpha_blend(src, Rgba{80, 160, 40, 100}, GR_BLEND_ALPHA_SATURATE,
                                    GR_BLEND_ZERO),
            (Rgba{25, 12, 50, 64}));
}

TEST(VoodooRefBlend, DestinationFactorsScaleTheDestination) {
  // Same pixels, source factor ZERO: out = dst * fd >> 8.
  const Rgba src{100, 50, 200, 64};
  const Rgba dst{80, 160, 40, 255};
  struct Case {
    int factor;
    Rgba expected;
  };
  const Case cases[] = {
      {GR_BLEND_ZERO, {0, 0, 0, 64}},
      {GR_BLEND_SRC_ALPHA, {20, 40, 10, 64}},            // x * 65 >> 8
      {GR_BLEND_SRC_COLOR, {31, 31, 31, 64}},            // 80*101, 160*51, 40*201, >> 8
      {GR_BLEND_DST_ALPHA, {80, 160, 40, 64}},
      {GR_BLEND_ONE, {80, 160, 40, 64}},
      {GR_BLEND_ONE_MINUS_SRC_ALPHA, {60, 120, 30, 64}},  // x * 192 >> 8
      {GR_BLEND_ONE_MINUS_SRC_COLOR, {48, 128, 8, 64}},  // 80*156, 160*206, 40*56, >> 8
      {GR_BLEND_ONE_MINUS_DST_ALPHA, {0, 0, 0, 64}},
      {GR_BLEND_PREFOG_COLOR, {31, 31, 31, 64}},         // no fog: pre-fog colour = source
  };
  for (const Case& c : cases) {
    EXPECT_EQ(voodoo_ref::alpha_blend(src, dst, GR_BLEND_ZERO, c.factor), c.expected)
        << "factor " << c.factor;
  }
}

TEST(VoodooRefBlend, SumIsShiftedOnceThenClamped) {
  // SRC_ALPHA / ONE_MINUS_SRC_ALPHA, a = 127: (101 * 128 + 101 * 129) >> 8 = 25957 >> 8 = 101,
  // where shifting each term first would give 50 + 50 = 100.
  EXPECT_EQ(voodoo_ref::alpha_blend(Rgba{101, 0, 0, 127}, Rgba{101, 0, 0, 255},
                                    GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA)
                .r,
            101);
  // ONE / ONE: 200 + 200 clamps to 255; 100 + 40 = 140.
  EXPECT_EQ(voodoo_ref::alpha_blend(Rgba{200, 100, 0, 0}, Rgba{200, 40, 0, 255}, GR_BLEND_ONE,
                                    GR_BLEND_ONE),
            (Rgba{255, 140, 0, 0}));
}

TEST(VoodooRefFrameBuffer, PackTruncatesAndUnpackReplicates) {
  EXPECT_EQ(voodoo_ref::pack_rgb565(Rgba{255, 255, 255, 0}), 0xFFFF);
  EXPECT_EQ(voodoo_ref::pack_rgb565(Rgba{7, 3, 7, 255}), 0x0000);  // below one step: dropped
  EXPECT_EQ(voodoo_ref::pack_rgb565(Rgba{8, 4, 8, 0}), 0x0821);
  EXPECT_EQ(voodoo_ref::unpack_rgb565(0x0821), (Rgba{8, 4, 8, 255}));
  EXPECT_EQ(voodoo_ref::unpack_rgb565(0xFFFF), (Rgba{255, 255, 255, 255}));
  for (int word = 0; word < 0x10000; ++word) {
    const auto w = static_cast<std::uint16_t>(word);
    ASSERT_EQ(voodoo_ref::pack_rgb565(voodoo_ref::unpack_rgb565(w)), w) << word;
  }
}

TEST(VoodooRefFrameBuffer, BlendToRgb565TruncatesTheBlendedColour) {
  // Black, alpha 128, over white: 255 * 128 >> 8 = 127 -> r 15, g 31, b 15 -> 0x7BEF.
  EXPECT_EQ(voodoo_ref::blend_to_rgb565(Rgba{0, 0, 0, 128}, 0xFFFF, GR_BLEND_SRC_ALPHA,
                                        GR_BLEND_ONE_MINUS_SRC_ALPHA),
            0x7BEF);
  // Destination 0x0821 expands to (8, 4, 8); halving gives (4, 2, 4), which truncates to 0.
  EXPECT_EQ(voodoo_ref::blend_to_rgb565(Rgba{0, 0, 0, 127}, 0x0821, GR_BLEND_SRC_ALPHA,
                                        GR_BLEND_ONE_MINUS_SRC_ALPHA),
            0x0000);
}

// ---- depth -------------------------------------------------------------------------------------

TEST(VoodooRefDepth, WCodeIsZeroAtAndBeyondOowOne) {
  EXPECT_EQ(voodoo_ref::w_buffer_code(1.0), 0);
  EXPECT_EQ(voodoo_ref::w_buffer_code(3.0), 0);
  EXPECT_EQ(voodoo_ref::w_buffer_code(-0.5), 0);
  EXPECT_EQ(voodoo_ref::w_buffer_code(std::nextafter(1.0, 0.0)), 1);  // e 0, m 0xFFF: 0 + 1
}

TEST(VoodooRefDepth, WCodeHandComputedValues) {
  // oow 0.5 = 0x80000000: e = 0, m = 0 -> (0 << 12) + 0xFFF + 1 = 0x1000.
  EXPECT_EQ(voodoo_ref::w_buffer_code(0.5), 0x1000);
  // oow 0.75 = 0xC0000000: e = 0, m = 0x800 -> 0x7FF + 1 = 0x800.
  EXPECT_EQ(voodoo_ref::w_buffer_code(0.75), 0x800);
  // oow 2^-k: e = k - 1, m = 0 -> k * 0x1000 (4096 codes per octave of w).
  EXPECT_EQ(voodoo_ref::w_buffer_code(0.25), 0x2000);
  EXPECT_EQ(voodoo_ref::w_buffer_code(1.0 / 1024), 0xA000);
  // oow 0.3 = 0x4CCCCCCC.CD: e = 1, m = bits 29..18 = 0x333 -> 0x1000 + 0xCCC + 1 = 0x1CCD.
  EXPECT_EQ(voodoo_ref::w_buffer_code(0.3), 0x1CCD);
}

TEST(VoodooRefDepth, WCodeSaturatesFarAway) {
  EXPECT_EQ(voodoo_ref::w_buffer_code(0.0), 0xFFFF);
  EXPECT_EQ(voodoo_ref::w_buffer_code(std::ldexp(1.0, -17)), 0xFFFF);  // top 16 bits zero
  EXPECT_EQ(voodoo_ref::w_buffer_code(std::ldexp(1.0, -16)), 0xFFFF);  // 0x10000, clamped
  // e = 15, m = 2: 0xF000 + 0xFFD + 1 = 0xFFFE.
  EXPECT_EQ(voodoo_ref::w_buffer_code(std::ldexp(1.0 + 2.0 / 4096, -16)), 0xFFFE);
}

TEST(VoodooRefDepth, WCodeIsMonotonicInW) {
  int previous = voodoo_ref::w_buffer_code(1.0);
  int increases = 0;
  for (double w = 1.0; w < 70000.0; w *= 1.0003) {
    const int code = voodoo_ref::w_buffer_code(1.0 / w);
    ASSERT_GE(code, previous) << "w=" << w;
    increases += code > previous ? 1 : 0;
    previous = code;
  }
  EXPECT_EQ(previous, 0xFFFF);
  EXPECT_GT(increases, 30000);  // ~4096 distinct codes per octave over 16 octaves
}

TEST(VoodooRefDepth, WCodeInverseRoundTripsEveryCode) {
  for (int code = 0; code <= 0xFFFF; ++code) {
    ASSERT_EQ(voodoo_ref::w_buffer_code(voodoo_ref::w_buffer_code_to_oow(code)), code) << code;
  }
  // Code 0x1000 covers oow in [0.5, 0.5 + 2^-13): its centre is 0.5 + 2^-14.
  EXPECT_DOUBLE_EQ(voodoo_ref::w_buffer_code_to_oow(0x1000), 0.5 + std::ldexp(1.0, -14));
}

TEST(VoodooRefDepth, DepthBiasIsAddedThenClamped) {
  EXPECT_EQ(voodoo_ref::w_buffer_code(0.5, 10), 0x100A);
  EXPECT_EQ(voodoo_ref::w_buffer_code(0.5, -5000), 0);
  EXPECT_EQ(voodoo_ref::w_buffer_code(0.0, 1), 0xFFFF);
  // 2^-16 gives 0x10000 before the clamp, so a bias of -1 still reaches 0xFFFF.
  EXPECT_EQ(voodoo_ref::w_buffer_code(std::ldexp(1.0, -16), -1), 0xFFFF);
  EXPECT_EQ(voodoo_ref::z_buffer_code(1000.0, -8), 992);
  EXPECT_EQ(voodoo_ref::z_buffer_code(65535.0, 100), 0xFFFF);
}

TEST(VoodooRefDepth, ZCodeIsClampedTruncatedOoz) {
  EXPECT_EQ(voodoo_ref::z_buffer_code(1234.9), 1234);
  EXPECT_EQ(voodoo_ref::z_buffer_code(-3.0), 0);
  EXPECT_EQ(voodoo_ref::z_buffer_code(65535.0), 0xFFFF);
  EXPECT_EQ(voodoo_ref::z_buffer_code(70000.0), 0xFFFF);
}

// ---- gamma -------------------------------------------------------------------------------------

TEST(VoodooRefGamma, GammaOneTableIsIdentity) {
  const auto table = voodoo_ref::gamma_table(1.0);
  for (int x = 0; x < 256; ++x) EXPECT_EQ(table[x], x) << x;
}

TEST(VoodooRefGamma, TableHandComputedValues) {
  // 255 * (128/255)^(1/0.8) = 107.74 -> 108; 255 * (128/255)^(1/1.7) = 170.006 -> 170.
  EXPECT_EQ(voodoo_ref::gamma_table(0.8)[128], 108);
  EXPECT_EQ(voodoo_ref::gamma_table(1.7)[128], 170);
  EXPECT_EQ(voodoo_ref::gamma_table(1.7)[0], 0);
  EXPECT_EQ(voodoo_ref::gamma_table(1.7)[255], 255);
}

TEST(VoodooRefGamma, ClutTakesEveryEighthEntryAndAWhiteTop) {
  const auto table = voodoo_ref::gamma_table(1.7);
  const auto clut = voodoo_ref::gamma_clut(1.7);
  for (int i = 0; i < 32; ++i) EXPECT_EQ(clut[i], table[8 * i]) << i;
  EXPECT_EQ(clut[31], 251);  // table[248]
  EXPECT_EQ(clut[32], 255);
}

TEST(VoodooRefGamma, ScanOutWithGammaOneIsIdentityExceptTheTopEighth) {
  const auto clut = voodoo_ref::gamma_clut(1.0);
  for (int x = 0; x < 248; ++x) EXPECT_EQ(voodoo_ref::gamma_scan_out_channel(x, clut), x) << x;
  // x = 255: (248 * 1 + 255 * 7) >> 3 = 2033 >> 3 = 254; the top segment spans 248..255 only.
  EXPECT_EQ(voodoo_ref::gamma_scan_out_channel(255, clut), 254);
  EXPECT_EQ(voodoo_ref::gamma_scan_out(0xFFFF, clut), (Rgba{254, 254, 254, 255}));
}

TEST(VoodooRefGamma, ScanOutInterpolatesBetweenClutEntries) {
  const auto clut = voodoo_ref::gamma_clut(1.7);  // entries 12, 13, 16, 17 = 144, 150, 170, 176
  // x = 100: entry 12, 4/8 of the way: (144 * 4 + 150 * 4) >> 3 = 147.
  EXPECT_EQ(voodoo_ref::gamma_scan_out_channel(100, clut), 147);
  // 0x8410 expands to (132, 130, 132): 132 -> (170 * 4 + 176 * 4) >> 3 = 173,
  // 130 -> (170 * 6 + 176 * 2) >> 3 = 1372 >> 3 = 171.
  EXPECT_EQ(voodoo_ref::gamma_scan_out(0x8410, clut), (Rgba{173, 171, 173, 255}));
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

TEST(VoodooRefDepth, CompareToBiasComparesTheUnsignedBiasWithTheStoredCode) {
  EXPECT_EQ(voodoo_ref::compare_to_bias_source(-3), 65533);
  EXPECT_EQ(voodoo_ref::compare_to_bias_source(1000), 1000);
  EXPECT_TRUE(voodoo_ref::depth_test_passes(GR_CMP_LESS, 1000, 1001));
  EXPECT_FALSE(voodoo_ref::depth_test_passes(GR_CMP_LESS, 1000, 1000));
  EXPECT_TRUE(voodoo_ref::depth_test_passes(GR_CMP_GEQUAL, 1000, 1000));
  EXPECT_TRUE(voodoo_ref::depth_test_passes(GR_CMP_NOTEQUAL, 1000, 999));
  EXPECT_FALSE(voodoo_ref::depth_test_passes(GR_CMP_NEVER, 0, 0));
  EXPECT_TRUE(voodoo_ref::depth_test_passes(GR_CMP_ALWAYS, 0, 1));
  EXPECT_THROW(voodoo_ref::depth_test_passes(8, 0, 0), std::invalid_argument);
}

}  // namespace
