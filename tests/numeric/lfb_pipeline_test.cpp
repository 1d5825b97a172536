// LFB writes through the pixel pipeline (grLfbLock with pixelPipeline FXTRUE), as MAME's
// voodoo_renderer::pixel_pipeline runs them: the written colour with no colour combine, alpha
// from the data or grLfbConstantAlpha, depth from the data or grLfbConstantDepth, then the depth
// test, chroma key, alpha test, fog by the depth code, blending and the masks, counted pixel by
// pixel. Also grLfbWriteColorFormat (RGBA lanes) and grLfbWriteColorSwizzle (byte swizzle, word
// swap) on locks and grLfbWriteRegion, their bad values, and their place in grGlideGetState.
// Expectations come from the formulas written here and from voodoo_reference.
#include "glide_window.h"

#include "context.h"
#include "voodoo_reference.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr int kPipelineWidth = 64, kPipelineHeight = 64;  // GlideWindowTest's window

std::size_t at(int x, int y) { return static_cast<std::size_t>(y * kPipelineWidth + x); }

FxU16 rgb565(int r, int g, int b) { return static_cast<FxU16>((r >> 3) << 11 | (g >> 2) << 5 | (b >> 3)); }

class LfbPipelineTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    grDitherMode(GR_DITHER_DISABLE);  // 8-bit colour truncates to 565, as voodoo_reference packs it
    grBufferClear(0, 0, 0);
  }

  // Locks the back buffer in `mode` through the pipeline (upper-left origin), lets `write` fill
  // pixels through the pointer and stride, and unlocks.
  static void pipeline_write(GrLfbWriteMode_t mode, const std::function<void(std::uint8_t *, FxU32)> &write,
                             GrOriginLocation_t origin = GR_ORIGIN_UPPER_LEFT) {
    GrLfbInfo_t info{};
    info.size = sizeof info;
    ASSERT_TRUE(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, mode, origin, FXTRUE, &info))
        << glideShimGetLastErrorMessage();
    write(static_cast<std::uint8_t *>(info.lfbPtr), info.strideInBytes);
    ASSERT_TRUE(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER)) << glideShimGetLastErrorMessage();
  }

  static void put16(std::uint8_t *base, FxU32 stride, int x, int y, FxU16 value) {
    std::memcpy(base + static_cast<std::size_t>(y) * stride + static_cast<std::size_t>(x) * 2, &value, 2);
  }
  static void put32(std::uint8_t *base, FxU32 stride, int x, int y, FxU32 value) {
    std::memcpy(base + static_cast<std::size_t>(y) * stride + static_cast<std::size_t>(x) * 4, &value, 4);
  }

  // A flat rectangle of one 565-exact colour at one ooz, through the triangle path.
  static void draw_depth_rect(int x0, int y0, int x1, int y1, float ooz, int r, int g, int b) {
    GrVertex style = vertex();
    style.ooz = ooz;
    style.r = static_cast<float>(r), style.g = static_cast<float>(g), style.b = static_cast<float>(b);
    draw_rect(static_cast<float>(x0), static_cast<float>(y0), static_cast<float>(x1), static_cast<float>(y1), style);
  }
};

// ---- depth ---------------------------------------------------------------------------------------

TEST_F(LfbPipelineTest, DepthTestKeepsPixelsInFrontOfATriangleAndRejectsThoseBehind) {
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, 0xFFFF);
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  draw_depth_rect(0, 0, 32, kPipelineHeight, 30000.0f, 0, 0, 255);  // blue, depth code 30000 on the left half
  const FxU16 red = 0xF800;
  // Rows 10..19: columns 0..15 at code 20000 (in front of the triangle), 16..47 at 40000
  // (behind it where it is drawn, in front of the cleared 0xFFFF beyond it).
  grSstResetPerfStats();
  pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [&](std::uint8_t *base, FxU32 stride) {
    for (int y = 10; y < 20; ++y)
      for (int x = 0; x < 48; ++x) put32(base, stride, x, y, FxU32{x < 16 ? 20000u : 40000u} << 16 | red);
  });
  GrSstPerfStats_t stats{};
  grSstPerfStats(&stats);
  const std::vector<FxU16> color = read_buffer(), depth = read_buffer(GR_BUFFER_AUXBUFFER);
  int front = 0, behind = 0, beyond = 0, wrong = 0;
  for (int y = 0; y < kPipelineHeight; ++y) {
    for (int x = 0; x < kPipelineWidth; ++x) {
      const bool written = y >= 10 && y < 20 && x < 48;
      FxU16 want_color = x < 32 ? 0x001F : 0, want_depth = x < 32 ? 30000 : 0xFFFF;
      if (written && x < 16) want_color = red, want_depth = 20000, ++front;
      if (written && x >= 16 && x < 32) ++behind;  // rejected: the triangle stays
      if (written && x >= 32) want_color = red, want_depth = 40000, ++beyond;
      wrong += color[at(x, y)] != want_color || depth[at(x, y)] != want_depth;
    }
  }
  EXPECT_EQ(wrong, 0) << "pixels whose colour or depth is not what the depth test leaves";
  EXPECT_EQ(front + behind + beyond, 480);
  EXPECT_EQ(stats.pixelsIn, 480u) << "every written pixel enters the pipeline";
  EXPECT_EQ(stats.zFuncFail, static_cast<FxU32>(behind));
  EXPECT_EQ(stats.pixelsOut, static_cast<FxU32>(front + beyond));
  expect_no_error();
}

TEST_F(LfbPipelineTest, ConstantDepthIsTestedAndWrittenForModesWithoutDepth) {
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, 0x8000);
  grLfbConstantDepth(0x4000);  // in front of the cleared 0x8000: written
  pipeline_write(GR_LFBWRITEMODE_565, [](std::uint8_t *base, FxU32 stride) {
    for (int x = 0; x < 8; ++x) put16(base, stride, x, 3, 0x07E0);
  });
  grLfbConstantDepth(0xC000);  // behind it: rejected
  pipeline_write(GR_LFBWRITEMODE_565, [](std::uint8_t *base, FxU32 stride) {
    for (int x = 0; x < 8; ++x) put16(base, stride, x, 5, 0x07E0);
  });
  for (int x = 0; x < 8; ++x) {
    EXPECT_EQ(pixel(x, 3), 0x07E0) << x;
    EXPECT_EQ(pixel(x, 3, GR_BUFFER_AUXBUFFER), 0x4000) << "the constant depth is written: " << x;
    EXPECT_EQ(pixel(x, 5), 0) << x;
    EXPECT_EQ(pixel(x, 5, GR_BUFFER_AUXBUFFER), 0x8000) << x;
  }
  expect_no_error();
}

TEST_F(LfbPipelineTest, DepthIsWrittenPerTheMaskAndIgnoresTheDepthBias) {
  // Depth buffering off: nothing is tested, but the aux buffer still takes the depth code while
  // the mask is on (MAME's write_pixel), and not while it is off.
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, 0x1111);
  pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [](std::uint8_t *base, FxU32 stride) {
    put32(base, stride, 1, 1, 0x23450000u | 0xFFFF);
  });
  EXPECT_EQ(pixel(1, 1), 0xFFFF);
  EXPECT_EQ(pixel(1, 1, GR_BUFFER_AUXBUFFER), 0x2345);
  grDepthMask(FXFALSE);
  pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [](std::uint8_t *base, FxU32 stride) {
    put32(base, stride, 2, 1, 0x23450000u | 0xFFFF);
  });
  EXPECT_EQ(pixel(2, 1), 0xFFFF);
  EXPECT_EQ(pixel(2, 1, GR_BUFFER_AUXBUFFER), 0x1111);
  // grLfbLock turns the depth bias off: a bias that would push 0x3000 behind 0x4000 changes nothing.
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, 0x4000);
  grDepthBiasLevel(0x2000);
  pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [](std::uint8_t *base, FxU32 stride) {
    put32(base, stride, 4, 4, 0x30000000u | 0x001F);
  });
  EXPECT_EQ(pixel(4, 4), 0x001F);
  EXPECT_EQ(pixel(4, 4, GR_BUFFER_AUXBUFFER), 0x3000);
  EXPECT_EQ(glide_shim::current().depth.bias_level, 0x2000) << "the bias is back after the unlock";
  expect_no_error();
}

TEST_F(LfbPipelineTest, WBufferCodesAreTestedAndWrittenAsCodes) {
  // In W-buffer mode the written code is a W code: LESS keeps codes below the stored one.
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, 0x9000);
  const FxU16 codes[4] = {0x1234, 0x8FFF, 0x9001, 0xF000};
  pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [&](std::uint8_t *base, FxU32 stride) {
    for (int x = 0; x < 4; ++x) put32(base, stride, x, 0, FxU32{codes[x]} << 16 | 0xFFFF);
  });
  for (int x = 0; x < 4; ++x) {
    const bool kept = codes[x] < 0x9000;
    EXPECT_EQ(pixel(x, 0), kept ? 0xFFFF : 0) << std::hex << codes[x];
    EXPECT_EQ(pixel(x, 0, GR_BUFFER_AUXBUFFER), kept ? codes[x] : 0x9000) << std::hex << codes[x];
  }
  expect_no_error();
}

TEST_F(LfbPipelineTest, CompareToBiasModesCompareTheLocksConstantDepth) {
  // zaColor holds the lock's constant depth, so that is what "bias OP stored" compares; each
  // pixel still writes its own depth code.
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS);
  ASSERT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, 0x8000);
  grDepthBiasLevel(static_cast<FxI16>(0xF000u));  // would fail LESS against 0x8000
  grLfbConstantDepth(0x4000);                       // passes
  pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [](std::uint8_t *base, FxU32 stride) {
    put32(base, stride, 0, 0, 0x90000000u | 0x001F);  // its own code would fail too
  });
  grLfbConstantDepth(0xC000);  // fails
  pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [](std::uint8_t *base, FxU32 stride) {
    put32(base, stride, 1, 0, 0x10000000u | 0x001F);  // its own code would pass
  });
  EXPECT_EQ(pixel(0, 0), 0x001F);
  EXPECT_EQ(pixel(0, 0, GR_BUFFER_AUXBUFFER), 0x9000) << "the pixel writes its own code";
  EXPECT_EQ(pixel(1, 0), 0);
  EXPECT_EQ(pixel(1, 0, GR_BUFFER_AUXBUFFER), 0x8000);
  EXPECT_EQ(glide_shim::current().depth.bias_level, static_cast<FxI16>(0xF000u)) << "restored after the unlock";
  expect_no_error();
}

TEST_F(LfbPipelineTest, Za16PipelineWritesDepthOnlyThroughTheDepthTest) {
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grBufferClear(0x00FFFFFFu, 0, 0x8000);
  GrLfbInfo_t info{};
  info.size = sizeof info;
  ASSERT_TRUE(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_AUXBUFFER, GR_LFBWRITEMODE_ANY, GR_ORIGIN_UPPER_LEFT, FXTRUE, &info))
      << glideShimGetLastErrorMessage();
  EXPECT_EQ(info.writeMode, GR_LFBWRITEMODE_ZA16);
  put16(static_cast<std::uint8_t *>(info.lfbPtr), info.strideInBytes, 0, 0, 0x7000);  // in front
  put16(static_cast<std::uint8_t *>(info.lfbPtr), info.strideInBytes, 1, 0, 0x9000);  // behind
  ASSERT_TRUE(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_AUXBUFFER)) << glideShimGetLastErrorMessage();
  EXPECT_EQ(pixel(0, 0, GR_BUFFER_AUXBUFFER), 0x7000);
  EXPECT_EQ(pixel(1, 0, GR_BUFFER_AUXBUFFER), 0x8000);
  EXPECT_EQ(pixel(0, 0), 0xFFFF) << "no colour is written";
  EXPECT_EQ(pixel(0, 0, GR_BUFFER_FRONTBUFFER), 0) << "no colour is written";
  expect_no_error();
}

// ---- alpha ---------------------------------------------------------------------------------------

TEST_F(LfbPipelineTest, ConstantAlphaBlendsModesWithoutAlphaAndTheDataAlphaOthers) {
  const FxU16 background = rgb565(40, 200, 96);
  std::vector<FxU16> fill(kPipelineWidth * kPipelineHeight, background);
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, kPipelineWidth, kPipelineHeight, kPipelineWidth * 2, fill.data()));
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE, GR_BLEND_ZERO);
  const voodoo_ref::Rgba source{248, 64, 16, 0};  // 565-exact: 888 data truncates to itself
  const FxU32 rgb = 248u << 16 | 64u << 8 | 16u;
  grLfbConstantAlpha(0x60);
  pipeline_write(GR_LFBWRITEMODE_888, [&](std::uint8_t *base, FxU32 stride) {
    grLfbConstantAlpha(0xFF);  // too late: the lock has loaded zaColor already
    for (int x = 0; x < 16; ++x) put32(base, stride, x, 2, rgb);
  });
  pipeline_write(GR_LFBWRITEMODE_8888, [&](std::uint8_t *base, FxU32 stride) {
    for (int x = 0; x < 16; ++x) put32(base, stride, x, 4, 0xC0000000u | rgb);  // its own alpha
  });
  for (const auto &[row, alpha] : {std::pair{2, 0x60}, std::pair{4, 0xC0}}) {
    voodoo_ref::Rgba src = source;
    src.a = alpha;
    const FxU16 want = voodoo_ref::blend_to_rgb565(src, background, GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA);
    for (int x = 0; x < 16; ++x) {
      const FxU16 got = pixel(x, row);
      // GL blends the unquantised colour: within one 565 step of the Voodoo's arithmetic.
      EXPECT_LE(std::abs(red5(got) - red5(want)), 1) << "alpha " << alpha << " x " << x;
      EXPECT_LE(std::abs(green6(got) - green6(want)), 1) << "alpha " << alpha << " x " << x;
      EXPECT_LE(std::abs(blue5(got) - blue5(want)), 1) << "alpha " << alpha << " x " << x;
    }
  }
  // The two alphas give clearly different blends, so the alpha really came from each source.
  EXPECT_GT(std::abs(red5(pixel(0, 2)) - red5(pixel(0, 4))), 4);
  EXPECT_EQ(pixel(0, 3), background) << "rows not written keep the background";
  expect_no_error();
}

TEST_F(LfbPipelineTest, ChromaKeyAndAlphaTestRejectWrittenPixels) {
  grChromakeyMode(GR_CHROMAKEY_ENABLE);
  grChromakeyValue(0x00FF00FFu);  // magenta: 565 0xF81F widens to exactly (255, 0, 255)
  grAlphaTestFunction(GR_CMP_GREATER);
  grAlphaTestReferenceValue(0x80);
  grSstResetPerfStats();
  pipeline_write(GR_LFBWRITEMODE_8888, [](std::uint8_t *base, FxU32 stride) {
    put32(base, stride, 0, 0, 0xFFFF00FFu);  // keyed out
    put32(base, stride, 1, 0, 0xFFFF00FEu);  // one off the key: kept
    put32(base, stride, 2, 0, 0x4000FF00u);  // alpha 0x40: fails GREATER 0x80
    put32(base, stride, 3, 0, 0xC000FF00u);  // alpha 0xC0: kept
  });
  GrSstPerfStats_t stats{};
  grSstPerfStats(&stats);
  EXPECT_EQ(pixel(0, 0), 0);
  EXPECT_EQ(pixel(1, 0), rgb565(0xFF, 0, 0xFE));
  EXPECT_EQ(pixel(2, 0), 0);
  EXPECT_EQ(pixel(3, 0), 0x07E0);
  EXPECT_EQ(stats.pixelsIn, 4u);
  EXPECT_EQ(stats.chromaFail, 1u);
  EXPECT_EQ(stats.aFuncFail, 1u);
  EXPECT_EQ(stats.pixelsOut, 2u);
  // A 565 pixel keyed by its widened colour, alpha tested with the constant alpha.
  grAlphaTestFunction(GR_CMP_ALWAYS);
  pipeline_write(GR_LFBWRITEMODE_565, [](std::uint8_t *base, FxU32 stride) {
    put16(base, stride, 0, 1, 0xF81F);
    put16(base, stride, 1, 1, 0xF81E);
  });
  EXPECT_EQ(pixel(0, 1), 0);
  EXPECT_EQ(pixel(1, 1), 0xF81E);
  grChromakeyMode(GR_CHROMAKEY_DISABLE);
  grAlphaTestFunction(GR_CMP_LESS);
  grLfbConstantAlpha(0x10);
  pipeline_write(GR_LFBWRITEMODE_565, [](std::uint8_t *base, FxU32 stride) { put16(base, stride, 0, 2, 0x1234); });
  grLfbConstantAlpha(0xF0);
  pipeline_write(GR_LFBWRITEMODE_565, [](std::uint8_t *base, FxU32 stride) { put16(base, stride, 1, 2, 0x1234); });
  EXPECT_EQ(pixel(0, 2), 0x1234) << "constant alpha 0x10 < 0x80 passes LESS";
  EXPECT_EQ(pixel(1, 2), 0) << "constant alpha 0xF0 fails LESS";
  expect_no_error();
}

// ---- fog -----------------------------------------------------------------------------------------

// The Voodoo 1 fog table lookup at a 16-bit code (entry code >> 10, its 8-bit delta times the
// next 8 bits, >> 10) and the fog unit (fog - c) * (blend + 1) >> 8 + c, per channel.
int table_blend(const std::vector<GrFog_t> &table, unsigned code) {
  const unsigned index = code >> 10;
  const int next = table[index < 63 ? index + 1 : index];
  const int delta = ((next - table[index]) * 4) & 0xFF;
  return table[index] + ((delta * static_cast<int>((code >> 2) & 0xFF)) >> 10);
}
int fog_channel(int c, int fog, int blend) {
  return std::clamp(c + static_cast<int>(std::floor((fog - c) * (blend + 1) / 256.0)), 0, 255);
}

TEST_F(LfbPipelineTest, FogTableIsIndexedByTheWrittenDepthCode) {
  std::vector<GrFog_t> table(GR_FOG_TABLE_SIZE);
  for (int i = 0; i < GR_FOG_TABLE_SIZE; ++i) table[static_cast<std::size_t>(i)] = static_cast<GrFog_t>(i * 4);
  grFogTable(table.data());
  grFogColorValue(0x00F0F0F0u);
  grFogMode(GR_FOG_WITH_TABLE);
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);  // with depth buffering on, triangles' fog is biased
  grDepthBufferFunction(GR_CMP_ALWAYS);
  grDepthBiasLevel(0x0800);  // ignored by the LFB's fog as by its depth test
  const int c_r = 33, c_g = 65, c_b = 99;  // 565 (4, 16, 12) widened by bit replication
  const FxU16 color = rgb565(c_r, c_g, c_b);
  std::vector<FxU16> codes;
  for (int x = 0; x < kPipelineWidth; ++x) codes.push_back(static_cast<FxU16>(x * 1031 + 7));
  codes.back() = 0xFFFF;
  pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [&](std::uint8_t *base, FxU32 stride) {
    for (int x = 0; x < kPipelineWidth; ++x) put32(base, stride, x, 7, FxU32{codes[static_cast<std::size_t>(x)]} << 16 | color);
  });
  const std::vector<FxU16> frame = read_buffer();
  int wrong = 0, fogged = 0;
  for (int x = 0; x < kPipelineWidth; ++x) {
    const int blend = table_blend(table, codes[static_cast<std::size_t>(x)]);
    const int r = fog_channel(c_r, 0xF0, blend), g = fog_channel(c_g, 0xF0, blend), b = fog_channel(c_b, 0xF0, blend);
    const FxU16 want = rgb565(r, g, b), got = frame[at(x, 7)];
    fogged += want != color;
    if (got != want && wrong++ < 4) {
      ADD_FAILURE() << "code " << codes[static_cast<std::size_t>(x)] << " blend " << blend << ": got 0x"
                    << std::hex << got << " want 0x" << want;
    }
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(fogged, kPipelineWidth / 2) << "the fog changed most written pixels";
  EXPECT_EQ(frame[at(0, 6)], 0) << "unwritten pixels are not fogged";
  // Iterated-Z fog takes the code's top 8 bits as the blend.
  grFogMode(GR_FOG_WITH_ITERATED_Z);
  pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [&](std::uint8_t *base, FxU32 stride) {
    put32(base, stride, 0, 9, 0x9A000000u | color);
  });
  EXPECT_EQ(pixel(0, 9), rgb565(fog_channel(c_r, 0xF0, 0x9A), fog_channel(c_g, 0xF0, 0x9A), fog_channel(c_b, 0xF0, 0x9A)));
  expect_no_error();
}

// ---- what is written -----------------------------------------------------------------------------

TEST_F(LfbPipelineTest, UntouchedPixelsAndTheOtherBufferAreUnchanged) {
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthBufferFunction(GR_CMP_ALWAYS);
  grDepthMask(FXTRUE);
  std::vector<FxU16> pattern(kPipelineWidth * kPipelineHeight), codes(kPipelineWidth * kPipelineHeight);
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    pattern[i] = static_cast<FxU16>(i * 2654435761u >> 7);
    codes[i] = static_cast<FxU16>(i * 40503u + 11);
  }
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, kPipelineWidth, kPipelineHeight, kPipelineWidth * 2, pattern.data()));
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_AUXBUFFER, 0, 0, GR_LFB_SRC_FMT_ZA16, kPipelineWidth, kPipelineHeight, kPipelineWidth * 2, codes.data()));
  const std::vector<FxU16> front = read_buffer(GR_BUFFER_FRONTBUFFER);
  for (GrOriginLocation_t origin : {GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT}) {
    pipeline_write(GR_LFBWRITEMODE_565_DEPTH, [](std::uint8_t *base, FxU32 stride) {
      put32(base, stride, 5, 6, 0x12340000u | 0xABCD);
      put32(base, stride, 60, 63, 0x56780000u | 0x0F0F);
    }, origin);
    const int top6 = origin == GR_ORIGIN_UPPER_LEFT ? 6 : kPipelineHeight - 1 - 6, top63 = origin == GR_ORIGIN_UPPER_LEFT ? 63 : 0;
    pattern[at(5, top6)] = 0xABCD, codes[at(5, top6)] = 0x1234;
    pattern[at(60, top63)] = 0x0F0F, codes[at(60, top63)] = 0x5678;
    EXPECT_EQ(read_buffer(), pattern) << "origin " << origin;
    EXPECT_EQ(read_buffer(GR_BUFFER_AUXBUFFER), codes) << "origin " << origin;
    EXPECT_EQ(read_buffer(GR_BUFFER_FRONTBUFFER), front) << "origin " << origin;
  }
  expect_no_error();
}

TEST_F(LfbPipelineTest, ClipWindowAndColourMaskApplyToPipelineWritesOnly) {
  grClipWindow(8, 8, 16, 16);
  grColorMask(FXTRUE, FXFALSE);
  pipeline_write(GR_LFBWRITEMODE_565, [](std::uint8_t *base, FxU32 stride) {
    for (int x = 0; x < 24; ++x) put16(base, stride, x, 10, 0xFFFF);
  });
  for (int x = 0; x < 24; ++x) EXPECT_EQ(pixel(x, 10), x >= 8 && x < 16 ? 0xFFFF : 0) << x;
  // A direct write ignores the clip window, as the hardware's raw LFB path does.
  GrLfbInfo_t info{};
  info.size = sizeof info;
  ASSERT_TRUE(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, &info));
  put16(static_cast<std::uint8_t *>(info.lfbPtr), info.strideInBytes, 2, 12, 0x1111);
  ASSERT_TRUE(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER));
  EXPECT_EQ(pixel(2, 12), 0x1111);
  grClipWindow(0, 0, kPipelineWidth, kPipelineHeight);
  grColorMask(FXFALSE, FXFALSE);
  pipeline_write(GR_LFBWRITEMODE_565, [](std::uint8_t *base, FxU32 stride) { put16(base, stride, 3, 12, 0x2222); });
  EXPECT_EQ(pixel(3, 12), 0) << "the colour mask off keeps the colour";
  expect_no_error();
}

TEST_F(LfbPipelineTest, DitherAppliesToPipelineWrites) {
  // 888 colour 132 lies between two 5-bit levels: the 4x4 dither spreads it over both.
  grDitherMode(GR_DITHER_4x4);
  pipeline_write(GR_LFBWRITEMODE_888, [](std::uint8_t *base, FxU32 stride) {
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) put32(base, stride, x, y, 132u << 16);
  });
  int low = 0, high = 0;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const int r = red5(pixel(x, y));
      low += r == 16, high += r == 17;
    }
  }
  EXPECT_EQ(low + high, 16);
  EXPECT_GT(low, 0);
  EXPECT_GT(high, 0);
  expect_no_error();
}

// ---- write colour format and swizzle ---------------------------------------------------------------

// A colour placed in a mode's word as MAME's expand_lfb_data reads it under each RGBA lane order.
struct Layout {
  int r, g, b, a, bits_rb, bits_g, bits_a;
};
Layout layout_of(GrLfbWriteMode_t mode, GrColorFormat_t lanes) {
  const bool blue_high = lanes == GR_COLORFORMAT_ABGR || lanes == GR_COLORFORMAT_BGRA;
  const bool alpha_low = lanes == GR_COLORFORMAT_RGBA || lanes == GR_COLORFORMAT_BGRA;
  switch (mode) {
    case GR_LFBWRITEMODE_565: return blue_high ? Layout{0, 5, 11, 0, 5, 6, 0} : Layout{11, 5, 0, 0, 5, 6, 0};
    case GR_LFBWRITEMODE_555:
    case GR_LFBWRITEMODE_1555: {  // 555's spare bit sits where 1555's alpha does
      const int o = alpha_low ? 1 : 0, bits_a = mode == GR_LFBWRITEMODE_1555 ? 1 : 0;
      return blue_high ? Layout{o, o + 5, o + 10, alpha_low ? 0 : 15, 5, 5, bits_a}
                       : Layout{o + 10, o + 5, o, alpha_low ? 0 : 15, 5, 5, bits_a};
    }
    default: {  // 888 and 8888
      const int o = alpha_low ? 8 : 0, bits_a = mode == GR_LFBWRITEMODE_8888 ? 8 : 0;
      return blue_high ? Layout{o, o + 8, o + 16, alpha_low ? 0 : 24, 8, 8, bits_a}
                       : Layout{o + 16, o + 8, o, alpha_low ? 0 : 24, 8, 8, bits_a};
    }
  }
}
FxU32 place(GrLfbWriteMode_t mode, GrColorFormat_t lanes, int r, int g, int b, int a) {
  const Layout l = layout_of(mode, lanes);
  return static_cast<FxU32>(r >> (8 - l.bits_rb)) << l.r | static_cast<FxU32>(g >> (8 - l.bits_g)) << l.g |
         static_cast<FxU32>(b >> (8 - l.bits_rb)) << l.b | static_cast<FxU32>(a >> (8 - l.bits_a)) << l.a;
}

TEST_F(LfbPipelineTest, EveryLaneOrderGivesTheSamePictureForItsOwnData) {
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);  // alpha shows
  for (GrLfbWriteMode_t mode : {GR_LFBWRITEMODE_565, GR_LFBWRITEMODE_555, GR_LFBWRITEMODE_1555,
                                 GR_LFBWRITEMODE_888, GR_LFBWRITEMODE_8888}) {
    const int bytes = mode == GR_LFBWRITEMODE_888 || mode == GR_LFBWRITEMODE_8888 ? 4 : 2;
    std::vector<FxU16> reference;
    for (GrColorFormat_t lanes : {GR_COLORFORMAT_ARGB, GR_COLORFORMAT_ABGR, GR_COLORFORMAT_RGBA, GR_COLORFORMAT_BGRA}) {
      grLfbWriteColorFormat(lanes);
      grBufferClear(0, 0, 0);
      std::vector<std::uint8_t> data(static_cast<std::size_t>(kPipelineWidth * 4 * bytes));
      for (int i = 0; i < kPipelineWidth * 4; ++i) {
        const FxU32 word = place(mode, lanes, i * 37 & 0xFF, i * 91 & 0xFF, i * 13 & 0xFF, i & 1 ? 0xFF : 0x00);
        std::memcpy(data.data() + static_cast<std::size_t>(i * bytes), &word, static_cast<std::size_t>(bytes));
      }
      // Direct (grLfbWriteRegion) into rows 0..3, through the pipeline into rows 8..11.
      ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, static_cast<GrLfbSrcFmt_t>(mode), kPipelineWidth, 4, kPipelineWidth * bytes, data.data()));
      pipeline_write(mode, [&](std::uint8_t *base, FxU32 stride) {
        for (int y = 0; y < 4; ++y)
          std::memcpy(base + (8 + y) * stride, data.data() + static_cast<std::size_t>(y * kPipelineWidth * bytes), static_cast<std::size_t>(kPipelineWidth * bytes));
      });
      const std::vector<FxU16> frame = read_buffer();
      if (lanes == GR_COLORFORMAT_ARGB) {
        reference = frame;
        int lit = 0;
        for (FxU16 p : frame) lit += p != 0;
        EXPECT_GT(lit, kPipelineWidth * 4) << "mode " << mode << ": both writes drew";
      } else {
        EXPECT_EQ(frame, reference) << "mode " << mode << " lanes " << lanes;
      }
    }
  }
  // ABGR data read as ARGB swaps red and blue.
  grLfbWriteColorFormat(GR_COLORFORMAT_ARGB);
  const FxU32 abgr_red = place(GR_LFBWRITEMODE_8888, GR_COLORFORMAT_ABGR, 0xFF, 0, 0, 0xFF);
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 20, GR_LFB_SRC_FMT_8888, 1, 1, 4, const_cast<FxU32 *>(&abgr_red)));
  EXPECT_EQ(pixel(0, 20), 0x001F);
  expect_no_error();
}

TEST_F(LfbPipelineTest, ByteSwizzleAndWordSwapReorderTheWrittenData) {
  // 32-bit data: the swizzle reverses the four bytes, the swap exchanges the 16-bit halves.
  const FxU32 argb = 0xFF20A0F8u;  // (0x20, 0xA0, 0xF8) -> 565 0x2D1F
  const FxU16 want32 = rgb565(0x20, 0xA0, 0xF8);
  struct Case {
    bool swizzle, swap;
    FxU32 data;
  };
  for (const Case c : {Case{false, false, argb}, Case{true, false, 0xF8A020FFu}, Case{false, true, 0xA0F8FF20u},
                       Case{true, true, 0x20FFF8A0u}}) {
    grLfbWriteColorSwizzle(c.swizzle, c.swap);
    grBufferClear(0, 0, 0);
    ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 3, 0, GR_LFB_SRC_FMT_8888, 1, 1, 4, const_cast<FxU32 *>(&c.data)));
    pipeline_write(GR_LFBWRITEMODE_8888, [&](std::uint8_t *base, FxU32 stride) { put32(base, stride, 3, 1, c.data); });
    EXPECT_EQ(pixel(3, 0), want32) << "direct, swizzle " << c.swizzle << " swap " << c.swap;
    EXPECT_EQ(pixel(3, 1), want32) << "pipeline, swizzle " << c.swizzle << " swap " << c.swap;
  }
  // 16-bit data: two pixels share a 32-bit word. Either transform alone moves each pixel to its
  // partner (x ^ 1), the swizzle also reversing its bytes; both together swap bytes in place.
  const FxU16 a = 0xF800, b = 0x07E0;
  auto bswap = [](FxU16 v) { return static_cast<FxU16>(v << 8 | v >> 8); };
  struct Case16 {
    bool swizzle, swap;
    FxU16 at4, at5;  // written to pixels 4 and 5
  };
  for (const Case16 c : {Case16{false, false, a, b}, Case16{true, false, bswap(b), bswap(a)},
                         Case16{false, true, b, a}, Case16{true, true, bswap(a), bswap(b)}}) {
    grLfbWriteColorSwizzle(c.swizzle, c.swap);
    grBufferClear(0, 0, 0);
    const FxU16 region[2] = {c.at4, c.at5};
    ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 4, 0, GR_LFB_SRC_FMT_565, 2, 1, 4, const_cast<FxU16 *>(region)));
    pipeline_write(GR_LFBWRITEMODE_565, [&](std::uint8_t *base, FxU32 stride) {
      put16(base, stride, 4, 1, c.at4);
      put16(base, stride, 5, 1, c.at5);
    });
    for (int row : {0, 1}) {
      EXPECT_EQ(pixel(4, row), a) << "row " << row << " swizzle " << c.swizzle << " swap " << c.swap;
      EXPECT_EQ(pixel(5, row), b) << "row " << row << " swizzle " << c.swizzle << " swap " << c.swap;
    }
  }
  // A single 16-bit pixel at an odd column with the swap alone lands on its even partner.
  grLfbWriteColorSwizzle(FXFALSE, FXTRUE);
  grBufferClear(0, 0, 0);
  const FxU16 one = 0x1234;
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 7, 2, GR_LFB_SRC_FMT_565, 1, 1, 2, const_cast<FxU16 *>(&one)));
  EXPECT_EQ(pixel(6, 2), one);
  EXPECT_EQ(pixel(7, 2), 0);
  expect_no_error();
}

TEST_F(LfbPipelineTest, WindowOpensWithArgbLanesAndNoSwizzle) {
  // grSstWinOpen zeroes lfbMode (gsst.c), whatever the window's colour format.
  const glide_shim::LfbWriteLayout &layout = glide_shim::current().lfb.layout;
  EXPECT_EQ(layout.color_format, GR_COLORFORMAT_ARGB);
  EXPECT_FALSE(layout.swizzle_bytes);
  EXPECT_FALSE(layout.swap_words);
  grLfbWriteColorFormat(GR_COLORFORMAT_BGRA);
  grSstWinClose();
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ABGR, GR_ORIGIN_UPPER_LEFT, 2, 1));
  EXPECT_EQ(glide_shim::current().lfb.layout.color_format, GR_COLORFORMAT_ARGB);
  expect_no_error();
}

TEST_F(LfbPipelineTest, BadColourFormatsAreRefusedAndChangeNothing) {
  grLfbWriteColorFormat(GR_COLORFORMAT_BGRA);
  grLfbWriteColorSwizzle(FXTRUE, FXFALSE);
  expect_no_error();
  for (GrColorFormat_t bad : {-1, 4, 0x100}) {
    glideShimClearError();
    grLfbWriteColorFormat(bad);
    EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM) << bad;
    EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find("grLfbWriteColorFormat"), std::string::npos);
    const glide_shim::LfbWriteLayout &layout = glide_shim::current().lfb.layout;
    EXPECT_EQ(layout.color_format, GR_COLORFORMAT_BGRA) << bad;
    EXPECT_TRUE(layout.swizzle_bytes);
    EXPECT_FALSE(layout.swap_words);
  }
  glideShimClearError();
}

TEST_F(LfbPipelineTest, GlideStateSavesTheWriteLayoutAndConstants) {
  grLfbWriteColorFormat(GR_COLORFORMAT_RGBA);
  grLfbWriteColorSwizzle(FXFALSE, FXTRUE);
  grLfbConstantAlpha(0x33);
  grLfbConstantDepth(0x4455);
  GrState saved;
  grGlideGetState(&saved);
  grLfbWriteColorFormat(GR_COLORFORMAT_ARGB);
  grLfbWriteColorSwizzle(FXTRUE, FXFALSE);
  grLfbConstantAlpha(0xFF);
  grLfbConstantDepth(0);
  grGlideSetState(&saved);
  const glide_shim::LfbLockState &lfb = glide_shim::current().lfb;
  EXPECT_EQ(lfb.layout.color_format, GR_COLORFORMAT_RGBA);
  EXPECT_FALSE(lfb.layout.swizzle_bytes);
  EXPECT_TRUE(lfb.layout.swap_words);
  EXPECT_EQ(lfb.constant_alpha, 0x33);
  EXPECT_EQ(lfb.constant_depth, 0x4455);
  expect_no_error();
}

}  // namespace
