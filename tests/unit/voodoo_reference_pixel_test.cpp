// Unit tests of the Voodoo 1 CPU reference (tests/support/voodoo_reference.*) from the texel to
// the screen: texel expansion, texture sampling, alpha blending and the 565 write, depth codes and
// gamma, against values worked out by hand from the team's notes on MAME, 86Box and 3dfx's Glide
// sources (shared/docs). Each expected number is derived in a comment. The combine units:
// voodoo_reference_combine_test.cpp.
#include "voodoo_reference.h"

#include <glide.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace {

using voodoo_ref::Rgba;
using voodoo_ref::Texture;

// A single-row INTENSITY_8 texture: texel value v decodes to {v, v, v, 255}.
Texture intensity_row(std::initializer_list<std::uint16_t> values) {
  return {static_cast<int>(values.size()), 1, GR_TEXFMT_INTENSITY_8, values};
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
