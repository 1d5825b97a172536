// grLfbWriteRegion's depth-carrying formats, exactly: ZA16 into the aux buffer, and the 32-bit
// 565/555/1555 + depth formats (colour word low, depth code high) writing both buffers; read back
// raw through grLfbReadRegion. Write locks in every write mode and origin. Also
// grLfbConstantAlpha / grLfbConstantDepth and format errors.
#include "glide_window.h"

#include "context.h"

#include <cstring>
#include <random>
#include <vector>

namespace {

constexpr int kFormatsWidth = 64, kFormatsHeight = 64;

class LfbFormatsTest : public GlideWindowTest {
 protected:
  void SetUp() override {
    GlideWindowTest::SetUp();
    grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);  // depth codes map to GL depth exactly
    grDepthMask(FXTRUE);
    grBufferClear(0, 0, 0);
  }

  static std::vector<FxU16> random_words(unsigned seed, std::size_t count) {
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> word(0, 0xFFFF);
    std::vector<FxU16> words(count);
    for (FxU16 &w : words) w = static_cast<FxU16>(word(random));
    return words;
  }
};

TEST_F(LfbFormatsTest, Za16WritesDepthCodesAndLeavesColour) {
  const std::vector<FxU16> codes = random_words(7, 20 * 12);
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_AUXBUFFER, 30, 40, GR_LFB_SRC_FMT_ZA16, 20, 12, 40, const_cast<FxU16 *>(codes.data())))
      << glideShimGetLastErrorMessage();
  std::vector<FxU16> back(20 * 12);
  ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_AUXBUFFER, 30, 40, 20, 12, 40, back.data()));
  EXPECT_EQ(back, codes);
  const std::vector<FxU16> color = read_buffer();
  for (FxU16 p : color) ASSERT_EQ(p, 0) << "a ZA16 write changed colour";
  // A ZA16 word carries only depth: naming a colour buffer writes the same aux buffer.
  const std::vector<FxU16> more = random_words(8, 4);
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_ZA16, 4, 1, 8, const_cast<FxU16 *>(more.data())));
  std::vector<FxU16> row(4);
  ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_AUXBUFFER, 0, 0, 4, 1, 8, row.data()));
  EXPECT_EQ(row, more);
  expect_no_error();
}

TEST_F(LfbFormatsTest, ColourAndDepthFormatsWriteBothBuffers) {
  const int w = 16, h = 8;
  const std::vector<FxU16> colours = random_words(11, w * h), codes = random_words(12, w * h);
  for (GrLfbSrcFmt_t format : {GR_LFB_SRC_FMT_565_DEPTH, GR_LFB_SRC_FMT_555_DEPTH, GR_LFB_SRC_FMT_1555_DEPTH}) {
    std::vector<FxU32> pixels(w * h);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = (FxU32{codes[i]} << 16) | colours[i];
    ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 5, 9, format, w, h, w * 4, pixels.data()))
        << glideShimGetLastErrorMessage();
    std::vector<FxU16> depth(w * h), colour(w * h), want(w * h);
    ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_AUXBUFFER, 5, 9, w, h, w * 2, depth.data()));
    ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 5, 9, w, h, w * 2, colour.data()));
    EXPECT_EQ(depth, codes) << "format " << format;
    // The colour half converts as the colour-only format does.
    const GrLfbSrcFmt_t colour_only = format - GR_LFB_SRC_FMT_565_DEPTH + GR_LFB_SRC_FMT_565;
    ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_FRONTBUFFER, 5, 9, colour_only, w, h, w * 2, const_cast<FxU16 *>(colours.data())));
    ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_FRONTBUFFER, 5, 9, w, h, w * 2, want.data()));
    EXPECT_EQ(colour, want) << "format " << format;
    if (format == GR_LFB_SRC_FMT_565_DEPTH) {
      EXPECT_EQ(colour, colours);
    }
  }
  expect_no_error();
}

// Write locks in every mode: the program writes a few pixels in the lock's format; only those
// change, converted as grLfbWriteRegion converts the same source format.
TEST_F(LfbFormatsTest, WriteLocksInEveryModeChangeOnlyThePixelsWritten) {
  const std::vector<FxU16> background = random_words(21, kFormatsWidth * kFormatsHeight), depth = random_words(22, kFormatsWidth * kFormatsHeight);
  struct Case {
    GrLfbWriteMode_t mode;
    int bytes;
  };
  for (const Case c : {Case{GR_LFBWRITEMODE_565, 2}, Case{GR_LFBWRITEMODE_555, 2}, Case{GR_LFBWRITEMODE_1555, 2},
                       Case{GR_LFBWRITEMODE_888, 4}, Case{GR_LFBWRITEMODE_8888, 4},
                       Case{GR_LFBWRITEMODE_565_DEPTH, 4}, Case{GR_LFBWRITEMODE_555_DEPTH, 4},
                       Case{GR_LFBWRITEMODE_1555_DEPTH, 4}, Case{GR_LFBWRITEMODE_ZA16, 2}}) {
    for (GrOriginLocation_t origin : {GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT}) {
      const std::string what = "mode " + std::to_string(c.mode) + " origin " + std::to_string(origin);
      ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, kFormatsWidth, kFormatsHeight, kFormatsWidth * 2, const_cast<FxU16 *>(background.data())));
      ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_AUXBUFFER, 0, 0, GR_LFB_SRC_FMT_ZA16, kFormatsWidth, kFormatsHeight, kFormatsWidth * 2, const_cast<FxU16 *>(depth.data())));
      GrLfbInfo_t info{};
      info.size = sizeof info;
      ASSERT_TRUE(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, c.mode, origin, FXFALSE, &info))
          << what << ": " << glideShimGetLastErrorMessage();
      EXPECT_EQ(info.writeMode, c.mode) << what;
      EXPECT_EQ(info.strideInBytes, static_cast<FxU32>(kFormatsWidth * c.bytes)) << what;
      // Three pixels along row 5 (from the lock's origin) at x 10..12, as a source region would give them.
      std::vector<std::uint8_t> source(static_cast<std::size_t>(3 * c.bytes));
      for (std::size_t i = 0; i < source.size(); ++i) source[i] = static_cast<std::uint8_t>(0x35 + 29 * i);
      std::memcpy(static_cast<std::uint8_t *>(info.lfbPtr) + 5 * info.strideInBytes + 10 * c.bytes, source.data(), source.size());
      ASSERT_TRUE(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER)) << what;

      // The same three pixels through grLfbWriteRegion into a copy, for the expected words.
      const int row = origin == GR_ORIGIN_UPPER_LEFT ? 5 : kFormatsHeight - 1 - 5;
      const std::vector<FxU16> got_color = read_buffer(GR_BUFFER_BACKBUFFER), got_depth = read_buffer(GR_BUFFER_AUXBUFFER);
      ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, kFormatsWidth, kFormatsHeight, kFormatsWidth * 2, const_cast<FxU16 *>(background.data())));
      ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_AUXBUFFER, 0, 0, GR_LFB_SRC_FMT_ZA16, kFormatsWidth, kFormatsHeight, kFormatsWidth * 2, const_cast<FxU16 *>(depth.data())));
      ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 10, static_cast<FxU32>(row), c.mode, 3, 1, 3 * c.bytes, source.data()));
      EXPECT_EQ(got_color, read_buffer(GR_BUFFER_BACKBUFFER)) << what;
      EXPECT_EQ(got_depth, read_buffer(GR_BUFFER_AUXBUFFER)) << what;
      int changed = 0;
      for (std::size_t i = 0; i < got_color.size(); ++i) changed += got_color[i] != background[i] || got_depth[i] != depth[i];
      EXPECT_GE(changed, 1) << what;
      EXPECT_LE(changed, 3) << what << ": only the written pixels change";
    }
  }
  expect_no_error();
}

TEST_F(LfbFormatsTest, ConstantAlphaAndDepthAreKept) {
  grLfbConstantAlpha(0x40);
  grLfbConstantDepth(0x1234);
  EXPECT_EQ(glide_shim::current().lfb.constant_alpha, 0x40);
  EXPECT_EQ(glide_shim::current().lfb.constant_depth, 0x1234);
  expect_no_error();
}

TEST_F(LfbFormatsTest, FormatsAndBuffersThatDoNotMatchAreRefused) {
  FxU16 word = 0x1234;
  std::vector<FxU16> before = read_buffer(GR_BUFFER_AUXBUFFER);
  EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_AUXBUFFER, 0, 0, GR_LFB_SRC_FMT_565, 1, 1, 2, &word), FXFALSE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INVALID_ENUM);
  // RLE16 is not implemented by the SST-1 driver either; it fails, as there.
  EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_RLE16, 1, 1, 4, &word), FXFALSE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_UNSUPPORTED);
  FxU32 pixel = 0xABCD1234u;
  EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565_DEPTH, 1, 1, 2, &pixel), FXFALSE);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_OUT_OF_RANGE) << "a 4-byte pixel needs a 4-byte stride";
  EXPECT_EQ(read_buffer(GR_BUFFER_AUXBUFFER), before);
  glideShimClearError();
}

}  // namespace
