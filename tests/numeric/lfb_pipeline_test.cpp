// LFB writes through the pixel pipeline (grLfbLock with pixelPipeline FXTRUE), as MAME's
// voodoo_renderer::pixel_pipeline runs them: the written colour with no colour combine, alpha
// from the data or grLfbConstantAlpha, depth from the data or grLfbConstantDepth, then the depth
// test, chroma key, alpha test, fog by the depth code, blending and the masks, counted pixel by
// pixel. Expectations come from the formulas written here and from voodoo_reference.
#include "lfb_pipeline_fixture.h"

namespace {

using namespace lfb_pipeline;

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

}  // namespace
