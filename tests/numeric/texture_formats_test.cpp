// The table formats and the rest of the texture download chapter: P_8 and AP_88 through the
// palette, YIQ_422 and AYIQ_8422 through the NCC tables (Y + I + Q per channel, clamped to
// 0..255, I and Q 9-bit signed), table changes between draws, partial table and level
// downloads, multibase addresses, and the errors for bad tables and rows. Expectations are
// computed here from the hardware's description (MAME's ncc_table and palette), per texel.
#include "glide_window.h"

#include <algorithm>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace {

FxU16 pack565(int r, int g, int b) {
  return static_cast<FxU16>(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
}

// An NCC table as a program (or gu3dfLoad) fills it: Y, I, Q, and the packed words the
// hardware receives.
GuNccTable make_ncc(std::mt19937 &random) {
  GuNccTable table{};
  for (auto &y : table.yRGB) y = static_cast<FxU8>(random());
  // I and Q span the whole 9-bit signed range, so sums clamp at both ends.
  auto nine_bits = [&]() { return static_cast<FxI16>(static_cast<int>(random() % 512) - 256); };
  for (auto &vector : table.iRGB) for (auto &c : vector) c = nine_bits();
  for (auto &vector : table.qRGB) for (auto &c : vector) c = nine_bits();
  for (int i = 0; i < 4; ++i) {
    table.packed_data[i] = FxU32{table.yRGB[4 * i]} | (FxU32{table.yRGB[4 * i + 1]} << 8) |
                           (FxU32{table.yRGB[4 * i + 2]} << 16) |
                           (FxU32{table.yRGB[4 * i + 3]} << 24);
    for (int k = 0; k < 2; ++k) {
      const FxI16 *v = k == 0 ? table.iRGB[i] : table.qRGB[i];
      table.packed_data[4 + 4 * k + i] = ((static_cast<FxU32>(v[0]) & 0x1FF) << 18) |
                                         ((static_cast<FxU32>(v[1]) & 0x1FF) << 9) |
                                         (static_cast<FxU32>(v[2]) & 0x1FF);
    }
  }
  return table;
}

// The 565 word the NCC decode of `texel` (YYYYIIQQ) writes with dither off.
FxU16 ncc_word(const GuNccTable &table, int texel) {
  const int y = table.yRGB[texel >> 4];
  const FxI16 *i = table.iRGB[(texel >> 2) & 3];
  const FxI16 *q = table.qRGB[texel & 3];
  auto channel = [&](int c) { return std::clamp(y + i[c] + q[c], 0, 255); };
  return pack565(channel(0), channel(1), channel(2));
}

FxU16 palette_word(const GuTexPalette &palette, int index) {
  const FxU32 entry = palette.data[index];
  return pack565((entry >> 16) & 0xFF, (entry >> 8) & 0xFF, entry & 0xFF);
}

class TextureFormatsTest : public DecalTextureTest {
 protected:
  void SetUp() override {
    DecalTextureTest::SetUp();
    guAlphaSource(GR_ALPHASOURCE_TEXTURE_ALPHA);
  }

  static void load64(GrTextureFormat_t format, void *data, FxU32 address = 0) {
    GrTexInfo info{GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, format, data};
    grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
    grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  }

  // Texel (x, y) of a 64x64 texture under pixel (x, y), over columns [x0, x1).
  static void draw_columns(float x0, float x1) {
    GrVertex v[4];
    const float xs[4] = {x0, x1, x1, x0}, ys[4] = {0, 0, kHeight, kHeight};
    for (int k = 0; k < 4; ++k) {
      v[k] = vertex();
      v[k].x = xs[k], v[k].y = ys[k];
      v[k].tmuvtx[0].sow = xs[k] * 4.0f;
      v[k].tmuvtx[0].tow = ys[k] * 4.0f;
    }
    grDrawTriangle(&v[0], &v[1], &v[2]);
    grDrawTriangle(&v[0], &v[2], &v[3]);
  }

  static GuTexPalette random_palette(std::mt19937 &random) {
    GuTexPalette palette{};
    for (auto &entry : palette.data) entry = static_cast<FxU32>(random());  // top byte ignored
    return palette;
  }

  // Expects pixel (x, y) == want(x, y) for every pixel with x0 <= x < x1; reports the first few.
  template <typename Want>
  void expect_frame(Want want, int x0 = 0, int x1 = kWidth) {
    const std::vector<FxU16> frame = read_buffer();
    int wrong = 0;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = x0; x < x1; ++x) {
        const FxU16 got = frame[static_cast<std::size_t>(y * kWidth + x)];
        if (got != want(x, y) && ++wrong <= 3) {
          ADD_FAILURE() << "pixel (" << x << ", " << y << "): want " << want(x, y) << ", got "
                        << got;
        }
      }
    }
    EXPECT_EQ(wrong, 0);
  }
};

TEST_F(TextureFormatsTest, P8ReadsThePalette) {
  std::mt19937 random(11);
  GuTexPalette palette = random_palette(random);
  std::vector<FxU8> indices(64 * 64);
  for (auto &index : indices) index = static_cast<FxU8>(random());
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &palette);
  load64(GR_TEXFMT_P_8, indices.data());
  draw_columns(0, kWidth);
  expect_frame([&](int x, int y) { return palette_word(palette, indices[y * 64 + x]); });
  expect_no_error();
}

TEST_F(TextureFormatsTest, Ap88TakesAlphaFromTheHighByteAndColourFromThePalette) {
  std::mt19937 random(12);
  GuTexPalette palette = random_palette(random);
  std::vector<FxU16> texels(64 * 64);
  for (auto &texel : texels) texel = static_cast<FxU16>(random());
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &palette);
  load64(GR_TEXFMT_AP_88, texels.data());
  draw_columns(0, kWidth);
  expect_frame([&](int x, int y) { return palette_word(palette, texels[y * 64 + x] & 0xFF); });
  // Alpha: white where the texel's alpha passes GREATER 127, the black clear colour elsewhere.
  grBufferClear(0, 0, 0);
  guColorCombineFunction(GR_COLORCOMBINE_CCRGB);
  grConstantColorValue(0xFFFFFFFF);
  grAlphaTestFunction(GR_CMP_GREATER);
  grAlphaTestReferenceValue(127);
  draw_columns(0, kWidth);
  expect_frame([&](int x, int y) -> FxU16 { return (texels[y * 64 + x] >> 8) > 127 ? 0xFFFF : 0; });
  expect_no_error();
}

TEST_F(TextureFormatsTest, YiqAndAyiqDecodeThroughTheSelectedNccTableWithClamping) {
  std::mt19937 random(13);
  const GuNccTable tables[2] = {make_ncc(random), make_ncc(random)};
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_NCC0, const_cast<GuNccTable *>(&tables[0]));
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_NCC1, const_cast<GuNccTable *>(&tables[1]));
  std::vector<FxU8> yiq(64 * 64);
  std::vector<FxU16> ayiq(64 * 64);
  for (int i = 0; i < 64 * 64; ++i) {
    yiq[static_cast<std::size_t>(i)] = static_cast<FxU8>(i);  // every texel value, 16 times
    ayiq[static_cast<std::size_t>(i)] = static_cast<FxU16>(random());
  }
  int clamped = 0;
  for (int t = 0; t < 256; ++t) {
    for (int c = 0; c < 3; ++c) {
      const int v = tables[0].yRGB[t >> 4] + tables[0].iRGB[(t >> 2) & 3][c] + tables[0].qRGB[t & 3][c];
      clamped += v < 0 || v > 255;
    }
  }
  ASSERT_GT(clamped, 0) << "the random tables should exercise the clamp";
  for (GrNCCTable_t select : {GR_NCCTABLE_NCC0, GR_NCCTABLE_NCC1}) {
    SCOPED_TRACE(select);
    grTexNCCTable(GR_TMU0, select);
    load64(GR_TEXFMT_YIQ_422, yiq.data());
    draw_columns(0, kWidth);
    expect_frame([&](int x, int y) { return ncc_word(tables[select], yiq[y * 64 + x]); });
    load64(GR_TEXFMT_AYIQ_8422, ayiq.data(), 8192);
    draw_columns(0, kWidth);
    expect_frame([&](int x, int y) { return ncc_word(tables[select], ayiq[y * 64 + x] & 0xFF); });
  }
  expect_no_error();
}

TEST_F(TextureFormatsTest, APaletteChangeReachesLaterDrawsOnly) {
  std::mt19937 random(14);
  const GuTexPalette first = random_palette(random), second = random_palette(random);
  std::vector<FxU8> indices(64 * 64);
  for (auto &index : indices) index = static_cast<FxU8>(random());
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, const_cast<GuTexPalette *>(&first));
  load64(GR_TEXFMT_P_8, indices.data());
  draw_columns(0, 32);  // queued, drawn with the first palette
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, const_cast<GuTexPalette *>(&second));
  draw_columns(32, 64);
  expect_frame([&](int x, int y) { return palette_word(first, indices[y * 64 + x]); }, 0, 32);
  expect_frame([&](int x, int y) { return palette_word(second, indices[y * 64 + x]); }, 32, 64);
  expect_no_error();
}

TEST_F(TextureFormatsTest, PartialTableDownloadsReplaceOnlyTheirEntries) {
  std::mt19937 random(15);
  GuTexPalette palette = random_palette(random);
  const GuTexPalette update = random_palette(random);
  std::vector<FxU8> indices(64 * 64);
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<FxU8>(i);
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &palette);
  grTexDownloadTablePartial(GR_TMU0, GR_TEXTABLE_PALETTE, const_cast<GuTexPalette *>(&update), 100,
                            131);
  std::copy(update.data + 100, update.data + 132, palette.data + 100);
  load64(GR_TEXFMT_P_8, indices.data());
  draw_columns(0, kWidth);
  expect_frame([&](int x, int y) { return palette_word(palette, indices[y * 64 + x]); });
  expect_no_error();
}

TEST_F(TextureFormatsTest, PartialLevelDownloadsWriteTheirRows) {
  std::mt19937 random(16);
  std::vector<FxU16> texels(64 * 64);
  for (auto &texel : texels) texel = static_cast<FxU16>(random());
  // Rows 0..40 then 41..63, each from the start of its own rows, as the driver reads them.
  grTexDownloadMipMapLevelPartial(GR_TMU0, 0, GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1,
                                  GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH, texels.data(), 0, 40);
  grTexDownloadMipMapLevelPartial(GR_TMU0, 0, GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1,
                                  GR_TEXFMT_RGB_565, GR_MIPMAPLEVELMASK_BOTH,
                                  texels.data() + 41 * 64, 41, 63);
  GrTexInfo info{GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, nullptr};
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  draw_columns(0, kWidth);
  expect_frame([&](int x, int y) { return texels[y * 64 + x]; });
  expect_no_error();
}

TEST_F(TextureFormatsTest, MultibaseReadsEachRangeFromItsOwnAddress) {
  // A 64..1 chain whose 64 level lives at 0 and whose 32..1 levels live at 65536; a wrong
  // base would read zeros (black) or the 64 level's red.
  std::vector<FxU16> level64(64 * 64, 0xF800);
  std::vector<FxU16> small_levels;
  for (GrLOD_t lod = GR_LOD_32; lod <= GR_LOD_1; ++lod) {
    const int side = 256 >> lod;
    small_levels.insert(small_levels.end(), static_cast<std::size_t>(side * side), 0x07E0);
  }
  grTexDownloadMipMapLevel(GR_TMU0, 0, GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565,
                           GR_MIPMAPLEVELMASK_BOTH, level64.data());
  std::size_t from = 0;
  for (GrLOD_t lod = GR_LOD_32; lod <= GR_LOD_1; ++lod) {
    grTexDownloadMipMapLevel(GR_TMU0, 65536, lod, GR_LOD_32, GR_ASPECT_1x1, GR_TEXFMT_RGB_565,
                             GR_MIPMAPLEVELMASK_BOTH, small_levels.data() + from);
    from += static_cast<std::size_t>((256 >> lod) * (256 >> lod));
  }
  GrTexInfo info{GR_LOD_1, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, nullptr};
  grTexSource(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexMultibase(GR_TMU0, FXTRUE);
  grTexMultibaseAddress(GR_TMU0, GR_TEXBASE_64, 0, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexMultibaseAddress(GR_TMU0, GR_TEXBASE_32_TO_1, 65536, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
  // Left half: one texel of the 64 level per pixel (LOD 2); right half: 4 per pixel (LOD 4).
  auto draw_scaled = [](float x0, float x1, float texels_per_pixel) {
    GrVertex v[4];
    const float xs[4] = {x0, x1, x1, x0}, ys[4] = {0, 0, kHeight, kHeight};
    for (int k = 0; k < 4; ++k) {
      v[k] = vertex();
      v[k].x = xs[k], v[k].y = ys[k];
      v[k].tmuvtx[0].sow = xs[k] * 4.0f * texels_per_pixel;
      v[k].tmuvtx[0].tow = ys[k] * 4.0f * texels_per_pixel;
    }
    grDrawTriangle(&v[0], &v[1], &v[2]);
    grDrawTriangle(&v[0], &v[2], &v[3]);
  };
  draw_scaled(0, 32, 1.0f);
  draw_scaled(32, 64, 4.0f);
  expect_frame([](int, int) -> FxU16 { return 0xF800; }, 0, 32);
  expect_frame([](int, int) -> FxU16 { return 0x07E0; }, 32, 64);
  // Multibase off: every level is read from grTexSource's chain at 0, where the 32 level is not.
  grTexMultibase(GR_TMU0, FXFALSE);
  draw_scaled(32, 64, 4.0f);
  const std::vector<FxU16> frame = read_buffer();
  EXPECT_NE(frame[40], 0x07E0);
  expect_no_error();
}

TEST_F(TextureFormatsTest, BadTablesAndRowsAreRefusedWithTheProblemNamed) {
  std::mt19937 random(17);
  GuTexPalette palette = random_palette(random);
  std::vector<FxU8> indices(64 * 64);
  for (auto &index : indices) index = static_cast<FxU8>(random());
  grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &palette);
  load64(GR_TEXFMT_P_8, indices.data());
  draw_columns(0, kWidth);
  const std::vector<FxU16> before = read_buffer();
  const GuTexPalette other = random_palette(random);
  struct Case {
    std::function<void()> call;
    GlideShimError error;
    const char *text;
  };
  const Case cases[] = {
      {[&] { grTexDownloadTable(GR_TMU0, 3, const_cast<GuTexPalette *>(&other)); },
       GLIDESHIM_ERR_INVALID_ENUM, "unknown table type 3"},
      {[&] { grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, nullptr); },
       GLIDESHIM_ERR_NULL_POINTER, "data is NULL"},
      {[&] { grTexDownloadTable(GR_TMU1, GR_TEXTABLE_PALETTE, const_cast<GuTexPalette *>(&other)); },
       GLIDESHIM_ERR_OUT_OF_RANGE, "does not exist"},
      {[&] {
         grTexDownloadTablePartial(GR_TMU0, GR_TEXTABLE_PALETTE,
                                   const_cast<GuTexPalette *>(&other), 200, 256);
       },
       GLIDESHIM_ERR_OUT_OF_RANGE, "entries 200..256 are outside the table's 0..255"},
      {[&] {
         grTexDownloadTablePartial(GR_TMU0, GR_TEXTABLE_NCC0,
                                   const_cast<GuTexPalette *>(&other), 0, 12);
       },
       GLIDESHIM_ERR_OUT_OF_RANGE, "outside the table's 0..11"},
      {[&] {
         grTexDownloadTablePartial(GR_TMU0, GR_TEXTABLE_PALETTE,
                                   const_cast<GuTexPalette *>(&other), 9, 3);
       },
       GLIDESHIM_ERR_OUT_OF_RANGE, "entries 9..3"},
      {[&] { grTexNCCTable(GR_TMU0, 2); }, GLIDESHIM_ERR_INVALID_ENUM, "not NCC0 or NCC1"},
      {[&] {
         grTexDownloadMipMapLevelPartial(GR_TMU0, 0, GR_LOD_64, GR_LOD_64, GR_ASPECT_1x1,
                                         GR_TEXFMT_P_8, GR_MIPMAPLEVELMASK_BOTH,
                                         indices.data(), 60, 64);
       },
       GLIDESHIM_ERR_OUT_OF_RANGE, "rows 60..64 are not inside the level's 0..63"},
      {[&] {
         grTexMultibaseAddress(GR_TMU0, 4, 0, GR_MIPMAPLEVELMASK_BOTH, nullptr);
       },
       GLIDESHIM_ERR_INVALID_ENUM, "unknown range 4"},
      {[&] {
         GrTexInfo info{GR_LOD_1, GR_LOD_64, GR_ASPECT_1x1, GR_TEXFMT_P_8, nullptr};
         grTexMultibaseAddress(GR_TMU0, GR_TEXBASE_64, 2 * 1024 * 1024 - 8,
                               GR_MIPMAPLEVELMASK_BOTH, &info);
       },
       GLIDESHIM_ERR_OUT_OF_RANGE, "beyond TMU memory"},
  };
  for (const Case &c : cases) {
    glideShimClearError();
    c.call();
    EXPECT_EQ(glideShimGetLastError(), c.error) << c.text;
    EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find(c.text), std::string::npos)
        << glideShimGetLastErrorMessage();
  }
  // Nothing changed: the same texture, palette and NCC selection draw the same picture.
  draw_columns(0, kWidth);
  EXPECT_EQ(read_buffer(), before);
}

}  // namespace
