// The LFB write layout: grLfbWriteColorFormat (RGBA lanes) and grLfbWriteColorSwizzle (byte
// swizzle, word swap) on locks and grLfbWriteRegion, their bad values, and their place in
// grGlideGetState. Expectations come from MAME's expand_lfb_data, written out here.
#include "lfb_pipeline_fixture.h"

namespace {

using namespace lfb_pipeline;

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
