// The TMU: texel formats widened by bit replication, clamp and wrap, point and Voodoo-1
// bilinear sampling, TMU memory (a re-download is seen by the next draw), the projective
// divisor hint, and the article's 565-to-ARGB_4444 reinterpretation.
#include "glide_window.h"
#include "voodoo_reference.h"

#include <cstdlib>
#include <random>

namespace {

class TextureTest : public DecalTextureTest {
 protected:
  void SetUp() override {
    DecalTextureTest::SetUp();
    guAlphaSource(GR_ALPHASOURCE_TEXTURE_ALPHA);
  }

  static void load(GrLOD_t lod, GrAspectRatio_t aspect, GrTextureFormat_t format, void *data,
                   FxU32 address = 0) {
    GrTexInfo info{lod, lod, aspect, format, data};
    grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  }

  // A quad over the whole window whose s,t run from (s0,t0) at the top-left corner to (s1,t1)
  // at the bottom-right, with oow = 1 so s,t are screen-linear.
  static void draw_st(float s0, float t0, float s1, float t1) {
    GrVertex style = vertex();
    GrVertex v[4] = {style, style, style, style};
    const float xs[4] = {0, kWidth, kWidth, 0}, ys[4] = {0, 0, kHeight, kHeight};
    for (int k = 0; k < 4; ++k) {
      v[k].x = xs[k], v[k].y = ys[k];
      v[k].tmuvtx[0].sow = s0 + (s1 - s0) * xs[k] / kWidth;
      v[k].tmuvtx[0].tow = t0 + (t1 - t0) * ys[k] / kHeight;
    }
    grDrawTriangle(&v[0], &v[1], &v[2]);
    grDrawTriangle(&v[0], &v[2], &v[3]);
  }

  // Glide s,t at the centre of pixel (x, y) for draw_st.
  static double s_at(int x, float s0, float s1) { return s0 + (s1 - s0) * (x + 0.5) / kWidth; }
};

TEST_F(TextureTest, EveryFormatWidensTexelsByBitReplication) {
  const GrTextureFormat_t formats[] = {
      GR_TEXFMT_RGB_565,   GR_TEXFMT_ARGB_4444,        GR_TEXFMT_ARGB_1555,
      GR_TEXFMT_ARGB_8332, GR_TEXFMT_RGB_332,          GR_TEXFMT_ALPHA_8,
      GR_TEXFMT_INTENSITY_8, GR_TEXFMT_ALPHA_INTENSITY_44, GR_TEXFMT_ALPHA_INTENSITY_88};
  std::mt19937 random(3);
  for (GrTextureFormat_t format : formats) {
    const bool wide = format >= GR_TEXFMT_16BIT;
    std::vector<FxU16> words(kWidth * kHeight);
    std::vector<FxU8> bytes(kWidth * kHeight);
    for (int i = 0; i < kWidth * kHeight; ++i) {
      words[static_cast<std::size_t>(i)] = static_cast<FxU16>(random());
      bytes[static_cast<std::size_t>(i)] = static_cast<FxU8>(random());
    }
    load(GR_LOD_64, GR_ASPECT_1x1, format, wide ? static_cast<void *>(words.data()) : bytes.data());
    draw_st(0, 0, 256, 256);  // texel (x, y) under pixel (x, y)
    const std::vector<FxU16> frame = read_buffer();
    int wrong = 0;
    for (int i = 0; i < kWidth * kHeight && wrong < 3; ++i) {
      const voodoo_ref::Rgba texel = voodoo_ref::decode_texel(
          format, wide ? words[static_cast<std::size_t>(i)] : bytes[static_cast<std::size_t>(i)]);
      if (frame[static_cast<std::size_t>(i)] != voodoo_ref::pack_rgb565(texel)) {
        ++wrong;
        ADD_FAILURE() << "format " << format << " texel " << i << ": want " << texel
                      << ", got 565 word " << frame[static_cast<std::size_t>(i)];
      }
    }
  }
  expect_no_error();
}

TEST_F(TextureTest, FrameBufferWordsReadAsArgb4444GiveTheShadowMask) {
  // Step 1 and 2 of the article: red 11110b on black, read back, download as ARGB_4444.
  grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                 GR_COMBINE_OTHER_NONE, FXFALSE);
  grConstantColorValue(0x00F00000u);  // ARGB: red 240 = 11110000b
  grBufferClear(0, 0, 0);
  GrVertex a = vertex(), b = vertex(), c = vertex();
  a.x = 8, a.y = 4, b.x = 60, b.y = 30, c.x = 20, c.y = 58;
  grDrawTriangle(&a, &b, &c);
  std::vector<FxU16> shadow(kWidth * kHeight);
  ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, kWidth, kHeight, kWidth * 2, shadow.data()));
  int drawn = 0;
  for (FxU16 word : shadow) {
    ASSERT_TRUE(word == 0xF000 || word == 0) << "frame-buffer word " << word;
    drawn += word == 0xF000;
  }
  EXPECT_GT(drawn, 500);

  // Step 5's combine: colour = texture (black), alpha = texture alpha, shown by blending.
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  guAlphaSource(GR_ALPHASOURCE_TEXTURE_ALPHA);
  grAlphaBlendFunction(GR_BLEND_ZERO, GR_BLEND_SRC_ALPHA, GR_BLEND_ZERO, GR_BLEND_ZERO);
  grBufferClear(0xFFFFFFFFu, 0, 0);
  load(GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_ARGB_4444, shadow.data());
  draw_st(0, 0, 256, 256);
  const std::vector<FxU16> frame = read_buffer();
  for (std::size_t i = 0; i < frame.size(); ++i) {
    // Alpha 0xF widens to 255 (white stays white); alpha 0 gives black.
    ASSERT_EQ(frame[i], shadow[i] == 0xF000 ? 0xFFFF : 0x0000) << "pixel " << i;
  }
  // And the texture's RGB is black where drawn: colour = texture with blending off.
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  grBufferClear(0xFFFFFFFFu, 0, 0);
  draw_st(0, 0, 256, 256);
  for (FxU16 word : read_buffer()) ASSERT_EQ(word, 0);
  expect_no_error();
}

TEST_F(TextureTest, ClampRepeatsEdgeTexelsAndWrapRepeatsWithPeriodOne) {
  std::mt19937 random(8);
  std::vector<FxU16> texels(8 * 8);
  for (FxU16 &t : texels) t = static_cast<FxU16>(random());
  voodoo_ref::Texture reference{8, 8, GR_TEXFMT_RGB_565, texels};
  load(GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data());
  const float s0 = -600, s1 = 800;  // far outside 0..256 on both sides
  for (GrTextureClampMode_t mode : {GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_WRAP}) {
    for (GrTextureFilterMode_t filter : {GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_BILINEAR}) {
      grTexClampMode(GR_TMU0, mode, mode);
      grTexFilterMode(GR_TMU0, filter, filter);
      draw_st(s0, s0, s1, s1);
      const std::vector<FxU16> frame = read_buffer();
      int wrong = 0;
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          const voodoo_ref::TexelCoord uv =
              voodoo_ref::glide_st_to_texel(s_at(x, s0, s1), s_at(y, s0, s1), 8, 8);
          const voodoo_ref::Rgba want = voodoo_ref::sample_texture(reference, uv, filter, mode, mode);
          wrong += frame[static_cast<std::size_t>(y * kWidth + x)] != voodoo_ref::pack_rgb565(want);
        }
      }
      EXPECT_EQ(wrong, 0) << "clamp mode " << mode << ", filter " << filter;
    }
  }
  expect_no_error();
}

TEST_F(TextureTest, BilinearUsesFourBitWeightsLikeVoodooOne) {
  // A magnified 4x4 texture: each texel covers 16 pixels, so every weight 0..15 occurs.
  std::vector<FxU16> texels = {0x0000, 0xFFFF, 0x0000, 0xFFFF, 0xF800, 0x07E0, 0x001F, 0x0000,
                               0xFFFF, 0x0000, 0xFFFF, 0x0000, 0x07E0, 0xF800, 0x0000, 0x001F};
  voodoo_ref::Texture reference{4, 4, GR_TEXFMT_RGB_565, texels};
  load(GR_LOD_4, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data());
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  draw_st(0, 0, 256, 256);
  const std::vector<FxU16> frame = read_buffer();
  int wrong = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const voodoo_ref::TexelCoord uv =
          voodoo_ref::glide_st_to_texel(s_at(x, 0, 256), s_at(y, 0, 256), 4, 4);
      const voodoo_ref::Rgba want = voodoo_ref::sample_texture(reference, uv, GR_TEXTUREFILTER_BILINEAR,
                                                               GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
      wrong += frame[static_cast<std::size_t>(y * kWidth + x)] != voodoo_ref::pack_rgb565(want);
    }
  }
  EXPECT_EQ(wrong, 0);
  expect_no_error();
}

TEST_F(TextureTest, RedownloadToTheSameAddressIsSeenByTheNextDraw) {
  std::vector<FxU16> first(8 * 8, 0xF800), second(8 * 8, 0x001F);
  load(GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, first.data(), 4096);
  draw_st(0, 0, 256, 256);
  EXPECT_EQ(pixel(10, 10), 0xF800);
  load(GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, second.data(), 4096);
  draw_st(0, 0, 256, 256);
  EXPECT_EQ(pixel(10, 10), 0x001F);
  // A download elsewhere leaves the source alone.
  load(GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, first.data(), 8192);
  GrTexInfo info{GR_LOD_8, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, nullptr};
  grTexSource(GR_TMU0, 4096, GR_MIPMAPLEVELMASK_BOTH, &info);
  draw_st(0, 0, 256, 256);
  EXPECT_EQ(pixel(10, 10), 0x001F);
  expect_no_error();
}

TEST_F(TextureTest, WDiffTmu0HintDividesByTheTmuW) {
  // s varies across the texture only if the divisor is tmuvtx[0].oow (2), not the vertex oow.
  std::vector<FxU16> texels(8 * 8);
  for (int i = 0; i < 64; ++i) texels[static_cast<std::size_t>(i)] = i % 8 < 4 ? 0xF800 : 0x001F;
  load(GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data());
  GrVertex style = vertex();
  style.oow = 1.0f;
  style.tmuvtx[0].oow = 2.0f;
  style.tmuvtx[0].sow = 2.0f * 200.0f;  // s = 200 under the hint (texel 6: blue), 400 without
  grHints(GR_HINT_STWHINT, GR_STWHINT_W_DIFF_TMU0);
  draw_rect(0, 0, kWidth, kHeight, style);
  EXPECT_EQ(pixel(5, 5), 0x001F);
  style.tmuvtx[0].sow = 2.0f * 100.0f;  // s = 100: texel 3, red
  draw_rect(0, 0, kWidth, kHeight, style);
  EXPECT_EQ(pixel(5, 5), 0xF800);
  grHints(GR_HINT_STWHINT, 0);
  draw_rect(0, 0, kWidth, kHeight, style);  // s = 200 / 1: texel 6 (clamped sample), blue
  EXPECT_EQ(pixel(5, 5), 0x001F);
  expect_no_error();
}

TEST_F(TextureTest, NoTexturingUntilTheProgramSetsTheTextureCombine) {
  // grSstWinOpen leaves grTexCombine at ZERO: a textured draw shows black.
  std::vector<FxU16> texels(8 * 8, 0xFFFF);
  load(GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data());
  grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, GR_COMBINE_FUNCTION_ZERO,
               GR_COMBINE_FACTOR_NONE, FXFALSE, FXFALSE);
  grBufferClear(0x00808080u, 0, 0);
  draw_st(0, 0, 256, 256);
  EXPECT_EQ(pixel(30, 30), 0);
  expect_no_error();
}

}  // namespace
