// Fog, exactly: table fog indexed by the W code of 1/w (entry = code >> 10, interpolated by the
// next 8 bits with the 8-bit delta grFogTable loads), iterated-alpha and iterated-Z fog, the
// MULT2 / ADD2 flags, the fog colour in the window's colour format, and the gu table
// generators against gu.c's arithmetic. Expectations are computed here from those formulas.
#include "glide_window.h"

#include "voodoo_reference.h"

#include <glideutl.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace {

struct Rgb {
  int r, g, b;
};

// The fog unit: (fog - c) * (f + 1) >> 8 + c, the shift flooring negative products.
int fog_channel(int c, int fog, int blend, bool mult, bool add) {
  const int fog_color = add ? 0 : fog;
  const int difference = mult ? fog_color : fog_color - c;
  const int scaled = static_cast<int>(std::floor(difference * (blend + 1) / 256.0));
  return std::clamp(mult ? scaled : scaled + c, 0, 255);
}

FxU16 fogged_565(Rgb c, Rgb fog, int blend, bool mult = false, bool add = false) {
  const int r = fog_channel(c.r, fog.r, blend, mult, add);
  const int g = fog_channel(c.g, fog.g, blend, mult, add);
  const int b = fog_channel(c.b, fog.b, blend, mult, add);
  return static_cast<FxU16>(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
}

// The table lookup as the Voodoo 1 does it (no fog dither or zones).
int table_blend(const GrFog_t *table, unsigned code) {
  const unsigned index = code >> 10;
  const int next = table[index < 63 ? index + 1 : index];
  const int delta = ((next - table[index]) * 4) & 0xFF;
  return table[index] + ((delta * static_cast<int>((code >> 2) & 0xFF)) >> 10);
}

class FogTest : public GlideWindowTest {
 protected:
  static constexpr Rgb kColor{200, 100, 52};
  static constexpr Rgb kFog{12, 224, 132};

  void SetUp() override {
    GlideWindowTest::SetUp();
    grDitherMode(GR_DITHER_DISABLE);
    grConstantColorValue(0xFF000000u | (kColor.r << 16) | (kColor.g << 8) | kColor.b);
    guColorCombineFunction(GR_COLORCOMBINE_CCRGB);
    grFogColorValue((kFog.r << 16) | (kFog.g << 8) | kFog.b);  // ARGB window
  }

  // A 16x16 square at (8, 8) with one w (and ooz, alpha) at every vertex.
  static void draw_square(float oow, float ooz = 0.0f, float alpha = 0.0f) {
    GrVertex style = vertex();
    style.oow = oow, style.ooz = ooz, style.a = alpha;
    draw_rect(8, 8, 24, 24, style);
  }

  // Every pixel of the square is `want`, and the pixel outside it is untouched (clear black).
  void expect_square(FxU16 want, const std::string &what) {
    const std::vector<FxU16> pixels = read_buffer();
    int wrong = 0;
    for (int y = 8; y < 24; ++y)
      for (int x = 8; x < 24; ++x) wrong += pixels[static_cast<std::size_t>(y * kWidth + x)] != want;
    EXPECT_EQ(wrong, 0) << what << ": got 0x" << std::hex << pixels[8 * kWidth + 8] << " want 0x" << want;
    EXPECT_EQ(pixels[30 * kWidth + 30], 0) << what;
  }

  static std::vector<GrFog_t> ramp_table() {
    std::vector<GrFog_t> table(GR_FOG_TABLE_SIZE);
    for (int i = 0; i < GR_FOG_TABLE_SIZE; ++i) table[static_cast<std::size_t>(i)] = static_cast<GrFog_t>(i * 4);
    return table;
  }
};

TEST_F(FogTest, DisabledFogLeavesTheColour) {
  grBufferClear(0, 0, 0);
  draw_square(0.3f);
  expect_square(fogged_565(kColor, kFog, -1), "no fog");  // blend + 1 = 0: colour unchanged
  expect_no_error();
}

TEST_F(FogTest, TableFogInterpolatesBetweenEntriesByTheWCode) {
  const std::vector<GrFog_t> table = ramp_table();
  grFogTable(table.data());
  grFogMode(GR_FOG_WITH_TABLE);
  // w from 1 to 30000: codes spread over many entries, with non-zero interpolation bits.
  for (float w : {1.0f, 1.37f, 3.3f, 17.9f, 250.0f, 4097.0f, 30000.0f}) {
    grBufferClear(0, 0, 0);
    const float oow = 1.0f / w;
    draw_square(oow);
    const auto code = static_cast<unsigned>(voodoo_ref::w_buffer_code(oow));
    expect_square(fogged_565(kColor, kFog, table_blend(table.data(), code)),
                  "w " + std::to_string(w) + " code " + std::to_string(code));
  }
  expect_no_error();
}

TEST_F(FogTest, TableDeltaKeepsOnlyEightBitsAsTheHardwareDoes) {
  // Entry 12 jumps to 200 at entry 13: (200 << 2) does not fit the delta byte, and the
  // hardware interpolates with 800 & 0xFF = 32, not with 800.
  std::vector<GrFog_t> table(GR_FOG_TABLE_SIZE, 0);
  for (int i = 13; i < GR_FOG_TABLE_SIZE; ++i) table[static_cast<std::size_t>(i)] = 200;
  grFogTable(table.data());
  grFogMode(GR_FOG_WITH_TABLE);
  const float oow = 1.0f / 8.8f;  // code 13033: entry 12, 186/256 of the way along
  const auto code = static_cast<unsigned>(voodoo_ref::w_buffer_code(oow));
  ASSERT_EQ(code >> 10, 12u);
  grBufferClear(0, 0, 0);
  draw_square(oow);
  const int blend = table_blend(table.data(), code);
  EXPECT_LT(blend, 40);  // a wide delta would have given about 150
  expect_square(fogged_565(kColor, kFog, blend), "wrapped delta");
}

TEST_F(FogTest, DepthBiasShiftsTheTableIndexWhenDepthBuffering) {
  const std::vector<GrFog_t> table = ramp_table();
  grFogTable(table.data());
  grFogMode(GR_FOG_WITH_TABLE);
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_ALWAYS);
  grDepthBiasLevel(3000);
  grBufferClear(0, 0, 0);
  const float oow = 1.0f / 3.3f;
  draw_square(oow);
  expect_square(fogged_565(kColor, kFog, table_blend(table.data(), static_cast<unsigned>(voodoo_ref::w_buffer_code(oow) + 3000))),
                "biased");
}

TEST_F(FogTest, IteratedAlphaAndIteratedZSelectTheBlend) {
  grFogMode(GR_FOG_WITH_ITERATED_ALPHA);
  grBufferClear(0, 0, 0);
  draw_square(1.0f, 0.0f, 100.0f);
  expect_square(fogged_565(kColor, kFog, 100), "iterated alpha 100");

  grFogMode(GR_FOG_WITH_ITERATED_Z);
  grBufferClear(0, 0, 0);
  draw_square(1.0f, 30000.0f);
  expect_square(fogged_565(kColor, kFog, 30000 >> 8), "iterated z 30000");
  expect_no_error();
}

TEST_F(FogTest, MultAndAddFlagsDropTheColourTerms) {
  for (GrFogMode_t flags : {GR_FOG_MULT2, GR_FOG_ADD2, GR_FOG_MULT2 | GR_FOG_ADD2}) {
    grFogMode(GR_FOG_WITH_ITERATED_ALPHA | flags);
    grBufferClear(0, 0, 0);
    draw_square(1.0f, 0.0f, 160.0f);
    expect_square(fogged_565(kColor, kFog, 160, (flags & GR_FOG_MULT2) != 0, (flags & GR_FOG_ADD2) != 0),
                  "flags " + std::to_string(flags));
  }
  expect_no_error();
}

TEST_F(FogTest, FogColourFollowsAnAbgrWindow) {
  grSstWinClose();
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ABGR,
                           GR_ORIGIN_UPPER_LEFT, 2, 1));
  grDitherMode(GR_DITHER_DISABLE);
  grConstantColorValue(0xFF000000u | (kColor.b << 16) | (kColor.g << 8) | kColor.r);
  guColorCombineFunction(GR_COLORCOMBINE_CCRGB);
  grFogColorValue((kFog.b << 16) | (kFog.g << 8) | kFog.r);  // ABGR: 0xAABBGGRR
  grFogMode(GR_FOG_WITH_ITERATED_ALPHA);
  grBufferClear(0, 0, 0);
  draw_square(1.0f, 0.0f, 90.0f);
  expect_square(fogged_565(kColor, kFog, 90), "ABGR");
  expect_no_error();
}

TEST_F(FogTest, BadModeAndNullTableAreRefusedAndChangeNothing) {
  grFogMode(GR_FOG_WITH_ITERATED_ALPHA);
  grFogMode(0x7);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM);
  grFogMode(GR_FOG_WITH_TABLE | 0x400);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM);
  glideShimClearError();
  grFogTable(nullptr);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  grBufferClear(0, 0, 0);
  draw_square(1.0f, 0.0f, 100.0f);
  expect_square(fogged_565(kColor, kFog, 100), "iterated alpha still set");
}

TEST(FogUtilities, IndexToWMatchesTheWCodeOfEachEntry) {
  // Entry i starts at code i << 10, which stands for w = 2^(3 + i/4) / (8 - i%4).
  EXPECT_FLOAT_EQ(guFogTableIndexToW(0), 1.0f);
  EXPECT_FLOAT_EQ(guFogTableIndexToW(4), 2.0f);
  EXPECT_FLOAT_EQ(guFogTableIndexToW(1), 8.0f / 7.0f);
  EXPECT_FLOAT_EQ(guFogTableIndexToW(63), 262144.0f / 5.0f);
  for (int i = 1; i < 60; ++i) {
    const double w = static_cast<double>(guFogTableIndexToW(i));
    EXPECT_EQ(voodoo_ref::w_buffer_code(1.0 / w) >> 10, i) << i;
  }
  glideShimClearError();
  EXPECT_EQ(guFogTableIndexToW(64), 0.0f);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  glideShimClearError();
}

TEST(FogUtilities, GeneratorsFollowGuC) {
  GrFog_t linear[GR_FOG_TABLE_SIZE], exp1[GR_FOG_TABLE_SIZE], exp2[GR_FOG_TABLE_SIZE];
  guFogGenerateLinear(linear, 2.0f, 300.0f);
  guFogGenerateExp(exp1, 0.01f);
  guFogGenerateExp2(exp2, 0.002f);
  for (int i = 0; i < GR_FOG_TABLE_SIZE; ++i) {
    const float w = std::min(guFogTableIndexToW(i), 65535.0f);
    const float f = std::clamp((w - 2.0f) / 298.0f, 0.0f, 1.0f);
    EXPECT_EQ(linear[i], static_cast<GrFog_t>(f * 255.0f)) << i;
    if (i > 0) {
      EXPECT_GE(exp1[i], exp1[i - 1]) << i;
      EXPECT_GE(exp2[i], exp2[i - 1]) << i;
    }
  }
  // Both exponential tables are normalised so the farthest entry is fully fogged.
  EXPECT_EQ(exp1[63], 255);
  EXPECT_EQ(exp2[63], 255);
  const float scale = 1.0f / (1.0f - std::exp(-0.01f * guFogTableIndexToW(63)));
  EXPECT_EQ(exp1[20], static_cast<GrFog_t>((1.0f - std::exp(-0.01f * guFogTableIndexToW(20))) * scale * 255.0f));
  glideShimClearError();
}

TEST(FogUtilities, BadGeneratorArgumentsLeaveTheTable) {
  GrFog_t table[GR_FOG_TABLE_SIZE];
  std::fill(std::begin(table), std::end(table), GrFog_t{7});
  guFogGenerateExp(table, 0.0f);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  guFogGenerateExp2(table, NAN);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  guFogGenerateLinear(table, 10.0f, 10.0f);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE);
  EXPECT_TRUE(std::all_of(std::begin(table), std::end(table), [](GrFog_t v) { return v == 7; }));
  guFogGenerateExp(nullptr, 0.5f);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_NULL_POINTER);
  glideShimClearError();
}

}  // namespace
