// The linear frame buffer, exactly: LFB region copies, the source-format conversions of
// grLfbWriteRegion, and the truncating 565 write of the pipeline (and the article's red-240
// trick). Every expectation is computed here, bit for bit. Locks and the buffers chapter:
// lfb_lock_buffer_test.cpp.
#include "lfb_checks.h"

namespace {

using namespace lfb_checks;

// ---------------------------------------------------------------------------------------------
// grLfbWriteRegion / grLfbReadRegion, 565

TEST_F(LfbTest, WriteThenReadRegionRoundTripsBothColourBuffers) {
  std::mt19937 random(2001);
  std::vector<FxU16> back = random_words(random, kPixels);
  std::vector<FxU16> front = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, back);
  fill(GR_BUFFER_FRONTBUFFER, front);
  EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_BACKBUFFER), back, "back buffer"), 0);
  EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_FRONTBUFFER), front, "front buffer"), 0);
  expect_no_error();
}

TEST_F(LfbTest, WritingOneColourBufferLeavesTheOtherUnchanged) {
  std::mt19937 random(2002);
  std::vector<FxU16> back = random_words(random, kPixels);
  std::vector<FxU16> front = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, back);
  fill(GR_BUFFER_FRONTBUFFER, front);
  std::vector<FxU16> back2 = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, back2);
  EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_FRONTBUFFER), front,
                              "front buffer after rewriting the back buffer"),
            0);
  std::vector<FxU16> front2 = random_words(random, kPixels);
  fill(GR_BUFFER_FRONTBUFFER, front2);
  EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_BACKBUFFER), back2,
                              "back buffer after rewriting the front buffer"),
            0);
  expect_no_error();
}

TEST_F(LfbTest, SubRegionWriteWithPaddedSourceStrideChangesOnlyTheRegion) {
  std::mt19937 random(2003);
  std::vector<FxU16> background = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, background);

  // A 21x11 region at (13,7) from rows of 21 words plus 10 bytes of padding. The padding holds
  // 0xA5A5, a word the region never uses, so any pixel taken from it shows.
  constexpr int kX = 13, kY = 7, kRegionW = 21, kRegionH = 11;
  constexpr int kSrcStride = kRegionW * 2 + 10;
  std::vector<unsigned char> source(static_cast<std::size_t>(kSrcStride) * kRegionH, 0xA5);
  std::vector<FxU16> expected = background;
  std::uniform_int_distribution<int> word(0, 0xA5A4);
  for (int row = 0; row < kRegionH; ++row) {
    for (int col = 0; col < kRegionW; ++col) {
      const auto w = static_cast<FxU16>(word(random));
      std::memcpy(&source[static_cast<std::size_t>(row * kSrcStride + col * 2)], &w, 2);
      expected[static_cast<std::size_t>((kY + row) * kW + kX + col)] = w;
    }
  }
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, kX, kY, GR_LFB_SRC_FMT_565, kRegionW,
                               kRegionH, kSrcStride, source.data()))
      << glideShimGetLastErrorMessage();
  EXPECT_EQ(count_differences(read_buffer(), expected,
                              "after a 21x11 write at (13,7) with a 52-byte source stride"),
            0);
  expect_no_error();
}

TEST_F(LfbTest, SubRegionReadWithPaddedDestinationStrideLeavesPaddingUntouched) {
  std::mt19937 random(2004);
  std::vector<FxU16> background = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, background);

  constexpr int kX = 29, kY = 40, kRegionW = 17, kRegionH = 9;
  constexpr int kDstStride = kRegionW * 2 + 14;
  constexpr unsigned char kGuard = 0x5C;
  // 16 guard bytes past the last row as well.
  std::vector<unsigned char> destination(static_cast<std::size_t>(kDstStride) * kRegionH + 16,
                                         kGuard);
  ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_BACKBUFFER, kX, kY, kRegionW, kRegionH, kDstStride,
                              destination.data()))
      << glideShimGetLastErrorMessage();
  int wrong_words = 0, touched_padding = 0;
  for (int row = 0; row < kRegionH; ++row) {
    for (int col = 0; col < kRegionW; ++col) {
      FxU16 got;
      std::memcpy(&got, &destination[static_cast<std::size_t>(row * kDstStride + col * 2)], 2);
      const FxU16 want = background[static_cast<std::size_t>((kY + row) * kW + kX + col)];
      if (got != want && wrong_words++ < 3) {
        ADD_FAILURE() << "region word (" << col << "," << row << ") is " << hex(got) << ", want "
                      << hex(want);
      }
    }
    for (int byte = kRegionW * 2; byte < kDstStride; ++byte) {
      touched_padding += destination[static_cast<std::size_t>(row * kDstStride + byte)] != kGuard;
    }
  }
  for (std::size_t i = static_cast<std::size_t>(kDstStride) * kRegionH; i < destination.size();
       ++i) {
    touched_padding += destination[i] != kGuard;
  }
  EXPECT_EQ(wrong_words, 0) << "words of the 17x9 region read at (29,40)";
  EXPECT_EQ(touched_padding, 0) << "bytes of row padding (or past the last row) were written";
  expect_no_error();
}

// ---------------------------------------------------------------------------------------------
// grLfbWriteRegion source formats

TEST_F(LfbTest, Source555ConvertsEveryWordWithReplicatedGreen) {
  std::vector<FxU16> words(32768);  // every 555 word, bit 15 clear
  for (std::size_t i = 0; i < words.size(); ++i) words[i] = static_cast<FxU16>(i);
  check_555_family(GR_LFB_SRC_FMT_555, words, "GR_LFB_SRC_FMT_555");
  expect_no_error();
}

TEST_F(LfbTest, Source1555ConvertsEveryWordIgnoringTheAlphaBit) {
  std::vector<FxU16> words(65536);  // every word: the alpha bit must not leak into red
  for (std::size_t i = 0; i < words.size(); ++i) words[i] = static_cast<FxU16>(i);
  check_555_family(GR_LFB_SRC_FMT_1555, words, "GR_LFB_SRC_FMT_1555");
  expect_no_error();
}

TEST_F(LfbTest, Source888TruncatesEachChannel) {
  check_32bit_format(GR_LFB_SRC_FMT_888, "GR_LFB_SRC_FMT_888");
  expect_no_error();
}

TEST_F(LfbTest, Source8888TruncatesEachChannelIgnoringAlpha) {
  check_32bit_format(GR_LFB_SRC_FMT_8888, "GR_LFB_SRC_FMT_8888");
  expect_no_error();
}

// ---------------------------------------------------------------------------------------------
// The pipeline's 565 write

TEST_F(LfbTest, PipelineWritesTruncateEveryLevelOfEveryChannel) {
  // 256 4x4 rects in a 16x16 grid; rect n has r = n, g = n + 85, b = n + 170 (mod 256), so each
  // channel takes all 256 levels once. With dither off the word is r>>3, g>>2, b>>3.
  use_constant_colour(0);
  grBufferClear(0, 0, 0);
  auto level = [](int n, int offset) { return (n + offset) & 0xFF; };
  for (int n = 0; n < 256; ++n) {
    const int r = level(n, 0), g = level(n, 85), b = level(n, 170);
    grConstantColorValue(0xFF000000u | static_cast<GrColor_t>(r << 16 | g << 8 | b));
    const float x = static_cast<float>(n % 16 * 4), y = static_cast<float>(n / 16 * 4);
    draw_rect(x, y, x + 4, y + 4, vertex());
  }
  const std::vector<FxU16> frame = read_buffer();
  int wrong = 0;
  for (int n = 0; n < 256; ++n) {
    const int r = level(n, 0), g = level(n, 85), b = level(n, 170);
    const FxU16 want = voodoo_ref::pack_rgb565(voodoo_ref::Rgba{r, g, b, 255});
    for (int i = 0; i < 16; ++i) {
      const int x = n % 16 * 4 + i % 4, y = n / 16 * 4 + i / 4;
      const FxU16 got = frame[static_cast<std::size_t>(y * kW + x)];
      if (got != want && wrong++ < 5) {
        ADD_FAILURE() << "colour (" << r << "," << g << "," << b << ") at (" << x << "," << y
                      << ") wrote 565 (" << red5(got) << "," << green6(got) << "," << blue5(got)
                      << "), want (" << (r >> 3) << "," << (g >> 2) << "," << (b >> 3) << ")";
      }
    }
  }
  EXPECT_EQ(wrong, 0) << "pixels whose 565 word is not the truncation of their colour";
  expect_no_error();
}

TEST_F(LfbTest, RedTwoFortyReadsBackAsF000ExactlyWhereDrawn) {
  // The article's trick: red 240 = 11110b in the 565 red field, i.e. word 0xF000, which read as
  // ARGB_4444 is alpha 0xF and black. Drawn over black, the shape must be 0xF000 and the rest 0.
  use_constant_colour(0xFFF00000u);
  grBufferClear(0x00000000u, 0, 0);
  constexpr int kX0 = 9, kY0 = 21, kX1 = 47, kY1 = 50;
  draw_rect(kX0, kY0, kX1, kY1, vertex());
  std::vector<FxU16> want(kPixels, 0);
  for (int y = kY0; y < kY1; ++y) {
    for (int x = kX0; x < kX1; ++x) want[static_cast<std::size_t>(y * kW + x)] = 0xF000;
  }
  const std::vector<FxU16> frame = read_buffer();
  EXPECT_EQ(count_differences(frame, want, "red 240 shape [9,47)x[21,50) over black"), 0);
  const FxU16 inside = frame[static_cast<std::size_t>(30 * kW + 30)];
  EXPECT_EQ(inside >> 12, 0xF) << "ARGB_4444 alpha of " << hex(inside);
  EXPECT_EQ(inside & 0x0FFF, 0) << "ARGB_4444 RGB of " << hex(inside);
  expect_no_error();
}


}  // namespace
