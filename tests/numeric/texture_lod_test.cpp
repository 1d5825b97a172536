// Mip-mapping: the level each pixel samples against a CPU model of the TMU's LOD (MAME's and
// the 3dfx register description: log2 of the larger screen gradient of the iterated s/w, t/w,
// minus log2 of the iterated 1/w, in 8.8 fixed point; the bias in quarters as the driver rounds
// it; the 4x4 LOD dither; the clamp to [largeLod, smallLod] and the evenOdd rule), written here
// from those descriptions and not from the shim's shader.
#include "glide_window.h"

#include <cmath>
#include <set>
#include <vector>

namespace {

// One solid 565 colour per GR_LOD value, all different in every channel's top bits.
constexpr FxU16 kLevelColor[9] = {0xF800, 0x07E0, 0x001F, 0xFFE0, 0xF81F,
                                  0x07FF, 0x8410, 0xFC00, 0x041F};

int level_of_color(FxU16 word) {
  for (int lod = 0; lod < 9; ++lod) {
    if (kLevelColor[lod] == word) return lod;
  }
  return -1;
}

using Plane = TexturePlane;  // see glide_window.h

class TextureLodTest : public DecalTextureTest {
 protected:
  void SetUp() override {
    DecalTextureTest::SetUp();
    grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP);
  }

  // Downloads a square chain large..small at address 0, every level filled with its colour.
  static void load_chain(GrLOD_t large, GrLOD_t small, FxU32 even_odd = GR_MIPMAPLEVELMASK_BOTH) {
    std::vector<FxU16> texels;
    for (GrLOD_t lod = large; lod <= small; ++lod) {
      const int side = 256 >> lod;
      texels.insert(texels.end(), static_cast<std::size_t>(side * side), kLevelColor[lod]);
    }
    GrTexInfo info{small, large, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
    grTexDownloadMipMap(GR_TMU0, 0, even_odd, &info);
    grTexSource(GR_TMU0, 0, even_odd, &info);
  }

  // The hardware's LOD at the centre of row y before dither and clamp, in LOD units.
  static double model_lod(const Plane &plane, int y, double bias_quarters) {
    const double gradient = std::max(plane.s_dx * plane.s_dx, plane.t_dy * plane.t_dy);
    const double lod = 0.5 * std::log2(gradient) - std::log2(plane.oow(y + 0.5));
    return std::floor(lod * 256.0) / 256.0 + bias_quarters / 4.0;
  }

  // The driver's _grTexFloatLODToFixedLOD, as a signed count of quarters.
  static int bias_quarters(float bias) {
    const int field = static_cast<int>((bias + 0.125f) / 0.25f) & 0x3F;
    return field >= 32 ? field - 64 : field;
  }

  static int dither4(int x, int y) {
    static const int kMatrix[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
    return kMatrix[y & 3][x & 3];
  }

  // Compares every pixel with the model's level; pixels whose LOD is within 1/64 of a level
  // boundary (where float and the hardware's 8.8 rounding may land on either side) are skipped.
  // Returns the set of levels seen, so a test can check that it spans several.
  std::set<int> expect_levels(const Plane &plane, GrLOD_t large, GrLOD_t small,
                              double bias_q, bool dither, FxU32 even_odd) {
    const std::vector<FxU16> frame = read_buffer();
    std::set<int> seen;
    int wrong = 0, compared = 0;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        double lod = model_lod(plane, y, bias_q);
        if (dither) lod += dither4(x, y) / 16.0;
        const double distance = std::abs(lod - std::round(lod));
        lod = std::clamp(lod, static_cast<double>(large), static_cast<double>(small));
        int level = static_cast<int>(std::floor(lod));
        const bool held = even_odd == GR_MIPMAPLEVELMASK_BOTH ||
                          ((level % 2 == 0) == (even_odd == GR_MIPMAPLEVELMASK_EVEN));
        if (!held) ++level;
        const int got = level_of_color(frame[static_cast<std::size_t>(y * kWidth + x)]);
        seen.insert(got);
        if (distance < 1.0 / 64.0) continue;
        ++compared;
        if (got != level && ++wrong <= 5) {
          ADD_FAILURE() << "pixel (" << x << ", " << y << "): model LOD " << lod << " -> level "
                        << level << ", shim drew level " << got;
        }
      }
    }
    EXPECT_EQ(wrong, 0) << "of " << compared << " pixels compared";
    EXPECT_GT(compared, kWidth * kHeight * 3 / 4);
    return seen;
  }

  static constexpr Plane kFloor{1.5, 1.5, 1.0, 1.0 / 32.0};  // LOD 0.58 at the top to 5.6
};

TEST_F(TextureLodTest, NearestMipmappingPicksTheModelsLevelPerPixel) {
  load_chain(GR_LOD_256, GR_LOD_1);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
  draw_plane(kFloor);
  const std::set<int> seen = expect_levels(kFloor, GR_LOD_256, GR_LOD_1, 0, false,
                                           GR_MIPMAPLEVELMASK_BOTH);
  EXPECT_GE(seen.size(), 6u);  // levels 0..5 across the floor
  expect_no_error();
}

TEST_F(TextureLodTest, BiasMovesTheLevelInDriverRoundedQuarters) {
  load_chain(GR_LOD_256, GR_LOD_1);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
  for (float bias : {1.0f, -0.75f, 0.3f, -0.5f, 2.6f}) {
    SCOPED_TRACE(bias);
    grTexLodBiasValue(GR_TMU0, bias);
    draw_plane(kFloor);
    expect_levels(kFloor, GR_LOD_256, GR_LOD_1, bias_quarters(bias), false,
                  GR_MIPMAPLEVELMASK_BOTH);
  }
  // The driver's rounding: -0.5 is one quarter down, not two.
  EXPECT_EQ(bias_quarters(-0.5f), -1);
  expect_no_error();
}

TEST_F(TextureLodTest, LodIsClampedToTheChainsLevels) {
  load_chain(GR_LOD_64, GR_LOD_8);  // levels 2..5
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
  const Plane steep{1.5, 1.5, 1.0, 1.0 / 128.0};  // LOD 0.58 .. 7.6
  draw_plane(steep);
  const std::set<int> seen =
      expect_levels(steep, GR_LOD_64, GR_LOD_8, 0, false, GR_MIPMAPLEVELMASK_BOTH);
  EXPECT_EQ(seen, (std::set<int>{GR_LOD_64, GR_LOD_32, GR_LOD_16, GR_LOD_8}));
  expect_no_error();
}

TEST_F(TextureLodTest, MipmapDisableSamplesOnlyTheLargestLevel) {
  load_chain(GR_LOD_256, GR_LOD_1);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_DISABLE, FXFALSE);
  draw_plane(kFloor);
  for (FxU16 word : read_buffer()) ASSERT_EQ(word, kLevelColor[GR_LOD_256]);
  expect_no_error();
}

TEST_F(TextureLodTest, DitheredMipmappingNeedsTheHintAndAddsTheMatrixOverSixteen) {
  load_chain(GR_LOD_256, GR_LOD_1);
  // Without GR_HINT_ALLOW_MIPMAP_DITHER the driver leaves LOD dither off.
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST_DITHER, FXFALSE);
  draw_plane(kFloor);
  expect_levels(kFloor, GR_LOD_256, GR_LOD_1, 0, false, GR_MIPMAPLEVELMASK_BOTH);
  grHints(GR_HINT_ALLOW_MIPMAP_DITHER, 1);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST_DITHER, FXFALSE);
  draw_plane(kFloor);
  expect_levels(kFloor, GR_LOD_256, GR_LOD_1, 0, true, GR_MIPMAPLEVELMASK_BOTH);
  expect_no_error();
}

TEST_F(TextureLodTest, ALevelTheEvenOddMaskLeftOutIsReplacedByTheNextSmaller) {
  load_chain(GR_LOD_256, GR_LOD_1, GR_MIPMAPLEVELMASK_ODD);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
  draw_plane(kFloor);
  const std::set<int> seen =
      expect_levels(kFloor, GR_LOD_256, GR_LOD_1, 0, false, GR_MIPMAPLEVELMASK_ODD);
  for (int level : seen) EXPECT_EQ(level % 2, 1) << level;
  expect_no_error();
}

TEST_F(TextureLodTest, MagnificationAndMinificationFiltersFollowTheLod) {
  // An 8x8 level of two columns of colours and a 4x4 level likewise: bilinear blends across the
  // column edge, point sampling never does. Magnified pixels (LOD at lodmin) use the mag filter.
  std::vector<FxU16> texels;
  for (int side : {8, 4}) {
    for (int i = 0; i < side * side; ++i) texels.push_back((i % side) < side / 2 ? 0xF800 : 0x001F);
  }
  GrTexInfo info{GR_LOD_4, GR_LOD_8, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
  auto blended_pixels = [&](const Plane &plane) {
    draw_plane(plane);
    int blended = 0;
    for (FxU16 word : read_buffer()) blended += word != 0xF800 && word != 0x001F;
    return blended;
  };
  // Magnified: 8 texels of the 8x8 level (s 0..256) over 64 pixels, LOD 2 < lodmin 5.
  const Plane magnified{4.0, 4.0, 1.0, 1.0};
  // Minified: 1.5 texels of the 8x8 level per pixel, LOD 5.58: still the 8x8 level, but the
  // LOD is above lodmin, so the min filter applies; the column edge falls at pixel 2.
  const Plane minified{48.0, 48.0, 1.0, 1.0};
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_BILINEAR);
  EXPECT_GT(blended_pixels(magnified), 0);
  EXPECT_EQ(blended_pixels(minified), 0);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_POINT_SAMPLED);
  EXPECT_EQ(blended_pixels(magnified), 0);
  EXPECT_GT(blended_pixels(minified), 0);
  expect_no_error();
}

TEST_F(TextureLodTest, LodFractionFactorIsTheFractionOfTheLod) {
  // Six 256-units per pixel: LOD log2(6) = 2.585, 661/256 in 8.8, fraction 149. The TMU's
  // BLEND_LOCAL with LOD_FRACTION on a white texel: ((0 - 255) * 150 >> 8) + 255 = 105.
  std::vector<FxU16> texels(256 * 256 * 2, 0xFFFF);
  GrTexInfo info{GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, texels.data()};
  grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
  grTexCombine(GR_TMU0, GR_COMBINE_FUNCTION_BLEND_LOCAL, GR_COMBINE_FACTOR_LOD_FRACTION,
               GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, FXFALSE, FXFALSE);
  draw_plane(Plane{6.0, 6.0, 1.0, 1.0});
  const FxU16 want = static_cast<FxU16>((105 >> 3) << 11 | (105 >> 2) << 5 | (105 >> 3));
  for (FxU16 word : read_buffer()) ASSERT_EQ(word, want);
  // Without mip-mapping the LOD is lodmin, a whole number: fraction 0, (0 - 255) * 1 >> 8 + 255.
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_DISABLE, FXFALSE);
  draw_plane(Plane{6.0, 6.0, 1.0, 1.0});
  const FxU16 almost_white = static_cast<FxU16>((254 >> 3) << 11 | (254 >> 2) << 5 | (254 >> 3));
  for (FxU16 word : read_buffer()) ASSERT_EQ(word, almost_white);
  expect_no_error();
}

TEST_F(TextureLodTest, OutOfRangeLodsAndBiasAreRefusedAndChangeNothing) {
  load_chain(GR_LOD_256, GR_LOD_1);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
  draw_plane(kFloor);
  const std::vector<FxU16> before = read_buffer();
  FxU16 texel = 0;
  grTexDownloadMipMapLevel(GR_TMU0, 0, 9, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565,
                           GR_MIPMAPLEVELMASK_BOTH, &texel);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM);
  EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find("grTexDownloadMipMapLevel"),
            std::string::npos);
  GrTexInfo bad{GR_LOD_256, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, &texel};  // reversed
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &bad);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INCONSISTENT);
  grTexLodBiasValue(GR_TMU0, 9.0f);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  grTexMipMapMode(GR_TMU0, 7, FXFALSE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM);
  draw_plane(kFloor);
  EXPECT_EQ(read_buffer(), before);
}

}  // namespace
