// The gu texture manager and ConvertAndDownloadRle, rendered and read back. A mip map
// allocated, downloaded and selected through guTexAllocateMemory / guTexDownloadMipMap /
// guTexSource must draw exactly what the same texels draw through grTexDownloadMipMap,
// grTexSource and the gr mode calls with the same settings (NCC tables included); and
// ConvertAndDownloadRle must leave each texel of its rectangle equal to the look-up table entry
// of the bitmap's colour index, decoded here from an encoder written to the format's
// description, and every other texel as it was.
#include "glide_window.h"

#include <algorithm>
#include <cstring>
#include <ostream>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

// Far-away TMU memory for the gr-path copies: the manager allocates from 0 upwards.
constexpr FxU32 kGrAddress = 1u << 20;

struct MipMapCase {
  const char *name;
  GrTextureFormat_t format;
  GrAspectRatio_t aspect;
  GrLOD_t small_lod, large_lod;
  FxU8 mask;
  GrMipMapMode_t mipmap;
  GrTextureClampMode_t clamp_s, clamp_t;
  GrTextureFilterMode_t min_filter, mag_filter;
  float bias;
};

// Test failures name the case, not its bytes.
void PrintTo(const MipMapCase &c, std::ostream *out) { *out << c.name; }

std::size_t chain_texels(const MipMapCase &c) {
  std::size_t texels = 0;
  for (GrLOD_t lod = c.large_lod; lod <= c.small_lod; ++lod) {
    const int longer = 256 >> lod;
    const int ratio = 1 << std::abs(c.aspect - GR_ASPECT_1x1);
    texels += static_cast<std::size_t>(longer * std::max(1, longer / ratio));
  }
  return texels;
}

bool is_ncc(GrTextureFormat_t format) {
  return format == GR_TEXFMT_YIQ_422 || format == GR_TEXFMT_AYIQ_8422;
}

GuNccTable random_ncc(std::mt19937 &random) {
  GuNccTable table{};
  for (auto &word : table.packed_data) word = static_cast<FxU32>(random());
  return table;
}

class GuTextureTest : public DecalTextureTest {
 protected:
  // A floor receding from w = 1 (bottom) to w = 12 (top) over columns [x0, x1), the texture
  // repeated twice across and six times along, so several LODs are sampled.
  static void draw_floor(float x0, float x1) {
    GrVertex v[4];
    const float xs[4] = {x0, x1, x1, x0}, ys[4] = {0, 0, kHeight, kHeight};
    const float ws[4] = {12, 12, 1, 1}, ss[4] = {0, 512, 512, 0}, ts[4] = {0, 0, 1536, 1536};
    for (int k = 0; k < 4; ++k) {
      v[k] = vertex();
      v[k].x = xs[k], v[k].y = ys[k], v[k].oow = 1.0f / ws[k];
      v[k].tmuvtx[0].sow = ss[k] * v[k].oow;
      v[k].tmuvtx[0].tow = ts[k] * v[k].oow;
      v[k].tmuvtx[0].oow = v[k].oow;
    }
    grDrawTriangle(&v[0], &v[1], &v[2]);
    grDrawTriangle(&v[0], &v[2], &v[3]);
  }

  // The same texture the gr way at kGrAddress: download, source and every mode guTexSource sets.
  static void source_through_gr(const MipMapCase &c, void *texels, GuNccTable *ncc,
                                GrNCCTable_t ncc_table = GR_NCCTABLE_NCC1) {
    GrTexInfo info{c.small_lod, c.large_lod, c.aspect, c.format, texels};
    grTexDownloadMipMap(GR_TMU0, kGrAddress, c.mask, &info);
    grTexSource(GR_TMU0, kGrAddress, c.mask, &info);
    grTexClampMode(GR_TMU0, c.clamp_s, c.clamp_t);
    grTexFilterMode(GR_TMU0, c.min_filter, c.mag_filter);
    grTexMipMapMode(GR_TMU0, c.mipmap, FXFALSE);
    grTexLodBiasValue(GR_TMU0, c.bias);
    if (ncc != nullptr) {
      grTexDownloadTable(GR_TMU0, ncc_table, ncc);
      grTexNCCTable(GR_TMU0, ncc_table);
    }
  }

  static GrMipMapId_t allocate(const MipMapCase &c) {
    return guTexAllocateMemory(GR_TMU0, c.mask, 0, 0, c.format, c.mipmap, c.small_lod,
                               c.large_lod, c.aspect, c.clamp_s, c.clamp_t, c.min_filter,
                               c.mag_filter, c.bias, FXFALSE);
  }

  // Expects two frames to be equal and not flat (so the texture really was sampled).
  static void expect_same_textured_frame(const std::vector<FxU16> &got,
                                         const std::vector<FxU16> &want) {
    int wrong = 0;
    for (std::size_t i = 0; i < want.size(); ++i) {
      if (got[i] != want[i] && ++wrong <= 3) {
        ADD_FAILURE() << "pixel (" << i % kWidth << ", " << i / kWidth << "): gu path "
                      << got[i] << ", gr path " << want[i];
      }
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(std::set<FxU16>(want.begin(), want.end()).size(), 8u) << "the frame is too plain";
  }
};

class GuMipMapPaths : public GuTextureTest, public ::testing::WithParamInterface<MipMapCase> {};

TEST_P(GuMipMapPaths, GuPathDrawsWhatTheGrPathDraws) {
  const MipMapCase &c = GetParam();
  std::mt19937 random(23);
  std::vector<FxU8> texels(chain_texels(c) * (c.format >= GR_TEXFMT_16BIT ? 2 : 1));
  for (auto &byte : texels) byte = static_cast<FxU8>(random());
  GuNccTable ncc = random_ncc(random);
  GuTexPalette palette{};
  for (auto &entry : palette.data) entry = static_cast<FxU32>(random());
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &palette);
  // Both NCC tables hold other tables first: guTexSource must load the mip map's own.
  GuNccTable stale = random_ncc(random);
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_NCC0, &stale);
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_NCC1, &stale);

  // A first mip map, so the one under test does not start at address 0.
  const MipMapCase filler{"filler", GR_TEXFMT_RGB_565, GR_ASPECT_1x1, GR_LOD_1, GR_LOD_32,
                          GR_MIPMAPLEVELMASK_BOTH, GR_MIPMAP_DISABLE, 0, 0, 0, 0, 0.0f};
  ASSERT_EQ(allocate(filler), 0u);
  const GrMipMapId_t id = allocate(c);
  ASSERT_EQ(id, 1u) << glideShimGetLastErrorMessage();
  guTexDownloadMipMap(id, texels.data(), &ncc);
  guTexSource(id);
  expect_no_error();
  EXPECT_EQ(guTexGetCurrentMipMap(GR_TMU0), id);
  EXPECT_EQ(guTexGetMipMapInfo(id)->data, static_cast<void *>(texels.data()));
  grBufferClear(0, 0, 0);
  draw_floor(0, kWidth);
  const std::vector<FxU16> gu_frame = read_buffer();

  source_through_gr(c, texels.data(), is_ncc(c.format) ? &ncc : nullptr);
  grBufferClear(0, 0, 0);
  draw_floor(0, kWidth);
  expect_no_error();
  expect_same_textured_frame(gu_frame, read_buffer());
}

INSTANTIATE_TEST_SUITE_P(
    Formats, GuMipMapPaths,
    ::testing::Values(
        MipMapCase{"Rgb565MipMappedBilinear", GR_TEXFMT_RGB_565, GR_ASPECT_1x1, GR_LOD_1,
                   GR_LOD_64, GR_MIPMAPLEVELMASK_BOTH, GR_MIPMAP_NEAREST, GR_TEXTURECLAMP_WRAP,
                   GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR,
                   0.5f},
        MipMapCase{"Argb4444WideClampedNegativeBias", GR_TEXFMT_ARGB_4444, GR_ASPECT_2x1,
                   GR_LOD_1, GR_LOD_32, GR_MIPMAPLEVELMASK_BOTH, GR_MIPMAP_NEAREST_DITHER,
                   GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_POINT_SAMPLED,
                   GR_TEXTUREFILTER_POINT_SAMPLED, -0.75f},
        MipMapCase{"Yiq422WithItsNccTable", GR_TEXFMT_YIQ_422, GR_ASPECT_1x1, GR_LOD_16,
                   GR_LOD_64, GR_MIPMAPLEVELMASK_BOTH, GR_MIPMAP_NEAREST, GR_TEXTURECLAMP_WRAP,
                   GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_POINT_SAMPLED,
                   GR_TEXTUREFILTER_POINT_SAMPLED, 0.0f},
        MipMapCase{"Ayiq8422TallWithItsNccTable", GR_TEXFMT_AYIQ_8422, GR_ASPECT_1x2, GR_LOD_8,
                   GR_LOD_32, GR_MIPMAPLEVELMASK_BOTH, GR_MIPMAP_NEAREST, GR_TEXTURECLAMP_WRAP,
                   GR_TEXTURECLAMP_CLAMP, GR_TEXTUREFILTER_BILINEAR,
                   GR_TEXTUREFILTER_POINT_SAMPLED, 1.0f},
        MipMapCase{"Palette8NarrowMipMapped", GR_TEXFMT_P_8, GR_ASPECT_1x4, GR_LOD_1, GR_LOD_64,
                   GR_MIPMAPLEVELMASK_BOTH, GR_MIPMAP_NEAREST, GR_TEXTURECLAMP_WRAP,
                   GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_POINT_SAMPLED,
                   GR_TEXTUREFILTER_BILINEAR, 0.0f},
        // One TMU holding only a chain's odd levels: here just the 128 level, unmip-mapped.
        MipMapCase{"Intensity8OddLevelOnly", GR_TEXFMT_INTENSITY_8, GR_ASPECT_1x1, GR_LOD_128,
                   GR_LOD_128, GR_MIPMAPLEVELMASK_ODD, GR_MIPMAP_DISABLE, GR_TEXTURECLAMP_WRAP,
                   GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR,
                   0.0f}),
    [](const ::testing::TestParamInfo<MipMapCase> &param) { return std::string(param.param.name); });

TEST_F(GuTextureTest, LevelByLevelDownloadsEqualTheWholeChain) {
  const MipMapCase c{"", GR_TEXFMT_RGB_565, GR_ASPECT_1x1, GR_LOD_1, GR_LOD_64,
                     GR_MIPMAPLEVELMASK_BOTH, GR_MIPMAP_NEAREST, GR_TEXTURECLAMP_WRAP,
                     GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_POINT_SAMPLED,
                     GR_TEXTUREFILTER_POINT_SAMPLED, 0.0f};
  std::mt19937 random(3);
  std::vector<FxU16> texels(chain_texels(c));
  for (auto &texel : texels) texel = static_cast<FxU16>(random());
  const GrMipMapId_t whole = allocate(c);
  const GrMipMapId_t by_level = allocate(c);
  guTexDownloadMipMap(whole, texels.data(), nullptr);
  const void *source = texels.data();
  for (GrLOD_t lod = c.large_lod; lod <= c.small_lod; ++lod) {
    guTexDownloadMipMapLevel(by_level, lod, &source);
  }
  guTexSource(whole);
  draw_floor(0, kWidth);
  const std::vector<FxU16> whole_frame = read_buffer();
  grBufferClear(0, 0, 0);
  guTexSource(by_level);
  draw_floor(0, kWidth);
  expect_no_error();
  expect_same_textured_frame(read_buffer(), whole_frame);
}

TEST_F(GuTextureTest, TwoYiqMipMapsShareTheTwoNccTables) {
  // A and B, each with its own NCC table, drawn A, B, A in three bands: guTexSource puts A's
  // table in NCC0 and B's in NCC1 and selects the right one each time.
  const MipMapCase a{"", GR_TEXFMT_YIQ_422, GR_ASPECT_1x1, GR_LOD_64, GR_LOD_64,
                     GR_MIPMAPLEVELMASK_BOTH, GR_MIPMAP_DISABLE, GR_TEXTURECLAMP_WRAP,
                     GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_POINT_SAMPLED,
                     GR_TEXTUREFILTER_POINT_SAMPLED, 0.0f};
  MipMapCase b = a;
  b.format = GR_TEXFMT_AYIQ_8422;
  b.mag_filter = GR_TEXTUREFILTER_BILINEAR;
  std::mt19937 random(41);
  std::vector<FxU8> a_texels(64 * 64), b_texels(64 * 64 * 2);
  for (auto &byte : a_texels) byte = static_cast<FxU8>(random());
  for (auto &byte : b_texels) byte = static_cast<FxU8>(random());
  GuNccTable a_ncc = random_ncc(random), b_ncc = random_ncc(random);

  const GrMipMapId_t a_id = allocate(a), b_id = allocate(b);
  guTexDownloadMipMap(a_id, a_texels.data(), &a_ncc);
  guTexDownloadMipMap(b_id, b_texels.data(), &b_ncc);
  guTexSource(a_id);
  draw_floor(0, 20);
  guTexSource(b_id);
  draw_floor(20, 40);
  guTexSource(a_id);
  draw_floor(40, kWidth);
  expect_no_error();
  const std::vector<FxU16> gu_frame = read_buffer();

  grBufferClear(0, 0, 0);
  source_through_gr(a, a_texels.data(), &a_ncc, GR_NCCTABLE_NCC0);
  draw_floor(0, 20);
  source_through_gr(b, b_texels.data(), &b_ncc, GR_NCCTABLE_NCC1);
  draw_floor(20, 40);
  source_through_gr(a, a_texels.data(), &a_ncc, GR_NCCTABLE_NCC0);
  draw_floor(40, kWidth);
  expect_no_error();
  expect_same_textured_frame(gu_frame, read_buffer());
}

// ConvertAndDownloadRle's bitmaps: 4 bytes the driver skips, one length byte per row, then
// each row as codes: 0xE0 | n followed by a colour index is a run of n (1..31), 0xE0 alone
// ends the row, any byte below 0xE0 is one texel of that index.
std::vector<FxU8> encode_rle_bitmap(const std::vector<std::vector<FxU8>> &rows) {
  std::vector<FxU8> body;
  std::vector<FxU8> lengths;
  for (const auto &row : rows) {
    const std::size_t before = body.size();
    for (std::size_t at = 0; at < row.size();) {
      std::size_t run = 1;
      while (at + run < row.size() && run < 31 && row[at + run] == row[at]) ++run;
      if (run == 1 && row[at] < 0xE0) {
        body.push_back(row[at]);
      } else {
        body.push_back(static_cast<FxU8>(0xE0 | run));
        body.push_back(row[at]);
      }
      at += run;
    }
    body.push_back(0xE0);
    lengths.push_back(static_cast<FxU8>(body.size() - before));
  }
  std::vector<FxU8> bitmap(4, 0);
  bitmap.insert(bitmap.end(), lengths.begin(), lengths.end());
  bitmap.insert(bitmap.end(), body.begin(), body.end());
  return bitmap;
}

class RleDownloadTest : public GuTextureTest {
 protected:
  void SetUp() override {
    GuTextureTest::SetUp();
    std::mt19937 random(29);
    indices.assign(64, std::vector<FxU8>(64));
    for (auto &row : indices) {
      // Runs of 1..40 of one index; indices from 0xE0 up must be coded as runs.
      for (std::size_t x = 0; x < row.size();) {
        const std::size_t run = 1 + random() % 40;
        const auto index = static_cast<FxU8>(random());
        for (std::size_t k = 0; k < run && x < row.size(); ++k) row[x++] = index;
      }
    }
    bitmap = encode_rle_bitmap(indices);
    for (auto &entry : tlut) entry = static_cast<FxU16>(random());
    before.resize(64 * 64);
    for (auto &texel : before) texel = static_cast<FxU16>(random());
    GrTexInfo info{GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, before.data()};
    grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
    expect_no_error();
  }

  void convert(FxU32 u0, FxU32 v0, FxU32 width, FxU32 height, FxU32 dest_width,
               FxU32 dest_height) {
    ConvertAndDownloadRle(GR_TMU0, 0, GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565,
                          GR_MIPMAPLEVELMASK_BOTH, bitmap.data(), 64, u0, v0, width, height,
                          dest_width, dest_height, tlut);
  }

  // Draws texel (x, y) of the 64x64 level at pixel (x, y) and compares with want(x, y).
  template <typename Want>
  void expect_level(Want want) {
    grBufferClear(0, 0, 0);
    GrVertex v[4];
    const float xs[4] = {0, kWidth, kWidth, 0}, ys[4] = {0, 0, kHeight, kHeight};
    for (int k = 0; k < 4; ++k) {
      v[k] = vertex();
      v[k].x = xs[k], v[k].y = ys[k];
      v[k].tmuvtx[0].sow = xs[k] * 4.0f;  // 256 / 64: texel coordinates of the 256 range
      v[k].tmuvtx[0].tow = ys[k] * 4.0f;
    }
    grDrawTriangle(&v[0], &v[1], &v[2]);
    grDrawTriangle(&v[0], &v[2], &v[3]);
    const std::vector<FxU16> frame = read_buffer();
    int wrong = 0;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const FxU16 got = frame[static_cast<std::size_t>(y * kWidth + x)];
        if (got != want(x, y) && ++wrong <= 3) {
          ADD_FAILURE() << "texel (" << x << ", " << y << "): want " << want(x, y) << ", got "
                        << got;
        }
      }
    }
    EXPECT_EQ(wrong, 0);
  }

  FxU16 old_texel(int x, int y) const { return before[static_cast<std::size_t>(y * 64 + x)]; }
  FxU16 decoded(int x, int y) const {
    return tlut[indices[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)]];
  }

  std::vector<std::vector<FxU8>> indices;
  std::vector<FxU8> bitmap;
  FxU16 tlut[256];
  std::vector<FxU16> before;
};

TEST_F(RleDownloadTest, WholeLevelDecodesThroughTheTable) {
  convert(0, 0, 64, 64, 64, 64);
  expect_no_error();
  expect_level([&](int x, int y) { return decoded(x, y); });
}

TEST_F(RleDownloadTest, SubRectangleRepeatsItsLastRowOnceAndLeavesTheRest) {
  // Bitmap rows 5..14 from column 3 into level rows 0..9; dest_height 12 adds one copy of the
  // last row (row 10); dest_width 21 writes 20 texels (whole pairs) of each row.
  convert(3, 5, 40, 10, 21, 12);
  expect_no_error();
  expect_level([&](int x, int y) {
    if (x >= 20 || y > 10) return old_texel(x, y);
    return decoded(x + 3, std::min(y, 9) + 5);
  });
}

TEST_F(RleDownloadTest, BadCallsChangeNothing) {
  auto refused = [&](GlideShimError kind) {
    EXPECT_EQ(glideShimGetLastError(), kind) << glideShimGetLastErrorMessage();
    EXPECT_NE(std::strstr(glideShimGetLastErrorMessage(), "ConvertAndDownloadRle"), nullptr);
    glideShimClearError();
  };
  convert(0, 0, 64, 10, 64, 8);  // more rows than the destination
  refused(GLIDESHIM_ERR_OUT_OF_RANGE);
  convert(0, 60, 64, 8, 64, 8);  // rows 60..67 of a 64-row bitmap
  refused(GLIDESHIM_ERR_OUT_OF_RANGE);
  convert(0, 0, 64, 8, 65, 8);  // wider than the level
  refused(GLIDESHIM_ERR_OUT_OF_RANGE);
  convert(10, 0, 64, 8, 64, 8);  // rows decode to 64 texels, fewer than 10 + 64
  refused(GLIDESHIM_ERR_INVALID_VALUE);
  ConvertAndDownloadRle(GR_TMU0, 0, GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565,
                        GR_MIPMAPLEVELMASK_BOTH, bitmap.data(), 64, 0, 0, 64, 8, 64, 8, nullptr);
  refused(GLIDESHIM_ERR_NULL_POINTER);
  ConvertAndDownloadRle(GR_TMU0, 0, GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_P_8,
                        GR_MIPMAPLEVELMASK_BOTH, bitmap.data(), 64, 0, 0, 64, 8, 64, 8, tlut);
  refused(GLIDESHIM_ERR_INCONSISTENT);
  // Row 3 loses its end code: its length byte now ends inside the row's codes.
  std::vector<FxU8> broken = bitmap;
  broken[4 + 3] = static_cast<FxU8>(broken[4 + 3] - 1);
  ConvertAndDownloadRle(GR_TMU0, 0, GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565,
                        GR_MIPMAPLEVELMASK_BOTH, broken.data(), 64, 0, 0, 64, 8, 64, 8, tlut);
  refused(GLIDESHIM_ERR_INVALID_VALUE);
  expect_level([&](int x, int y) { return old_texel(x, y); });
}

}  // namespace
