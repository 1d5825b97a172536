// The linear frame buffer and the buffers chapter, exactly: LFB region copies and locks, the
// source-format conversions of grLfbWriteRegion, the truncating 565 write of the pipeline (and
// the article's red-240 trick), grBufferSwap, grBufferClear against the clip window and masks,
// and the depth codes of the aux buffer. Every expectation is computed here, bit for bit.
#include "glide_window.h"
#include "voodoo_reference.h"

#include <cstring>
#include <iomanip>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr int kW = 64;  // GlideWindowTest's window
constexpr int kH = 64;
constexpr std::size_t kPixels = static_cast<std::size_t>(kW) * kH;

std::string hex(unsigned value) {
  std::ostringstream s;
  s << "0x" << std::hex << std::uppercase << std::setw(4) << std::setfill('0') << value;
  return s.str();
}

std::vector<FxU16> random_words(std::mt19937 &random, std::size_t count) {
  std::uniform_int_distribution<int> word(0, 0xFFFF);
  std::vector<FxU16> words(count);
  for (FxU16 &w : words) w = static_cast<FxU16>(word(random));
  return words;
}

// Number of pixels where two whole frames differ; reports the first few with coordinates.
int count_differences(const std::vector<FxU16> &got, const std::vector<FxU16> &want,
                      const std::string &what) {
  if (got.size() != want.size()) {
    ADD_FAILURE() << what << ": " << got.size() << " pixels, want " << want.size();
    return static_cast<int>(want.size());
  }
  int differences = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (got[i] == want[i]) continue;
    if (differences++ < 3) {
      ADD_FAILURE() << what << ": pixel (" << i % kW << "," << i / kW << ") is " << hex(got[i])
                    << ", want " << hex(want[i]);
    }
  }
  return differences;
}

// The 565 word that the pipeline, with dither off, writes for an 8-bit colour: truncation.
FxU16 truncated_565(int r, int g, int b) {
  return static_cast<FxU16>((r >> 3) << 11 | (g >> 2) << 5 | (b >> 3));
}

// The 565 word grLfbWriteRegion stores for a 555 or 1555 source word: red and blue keep their
// 5 bits, green widens to 6 by replicating its top bit (g5 << 1 | g5 >> 4), bit 15 is ignored.
FxU16 from_555(FxU16 word) {
  const int r5 = word >> 10 & 0x1F, g5 = word >> 5 & 0x1F, b5 = word & 0x1F;
  const int g6 = g5 << 1 | g5 >> 4;
  return static_cast<FxU16>(r5 << 11 | g6 << 5 | b5);
}

class LfbTest : public GlideWindowTest {
 protected:
  // Writes a whole colour buffer through the LFB (565 words, no conversion).
  static void fill(GrBuffer_t buffer, std::vector<FxU16> &words) {
    ASSERT_EQ(words.size(), kPixels);
    ASSERT_TRUE(grLfbWriteRegion(buffer, 0, 0, GR_LFB_SRC_FMT_565, kW, kH, kW * 2, words.data()))
        << glideShimGetLastErrorMessage();
  }

  // Flat colour from the constant colour register, written without dither.
  static void use_constant_colour(GrColor_t argb) {
    grDitherMode(GR_DITHER_DISABLE);
    grColorCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                   GR_COMBINE_OTHER_NONE, FXFALSE);
    grConstantColorValue(argb);
  }

  // Writes `words` (16-bit source pixels in `format`) in full-screen batches and checks every
  // stored word against from_555.
  void check_555_family(GrLfbSrcFmt_t format, const std::vector<FxU16> &words,
                        const std::string &name) {
    int bad = 0;
    for (std::size_t start = 0; start < words.size(); start += kPixels) {
      std::vector<FxU16> batch(words.begin() + static_cast<std::ptrdiff_t>(start),
                               words.begin() + static_cast<std::ptrdiff_t>(start + kPixels));
      ASSERT_TRUE(
          grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, format, kW, kH, kW * 2, batch.data()))
          << name << ": " << glideShimGetLastErrorMessage();
      const std::vector<FxU16> got = read_buffer();
      for (std::size_t i = 0; i < kPixels; ++i) {
        const FxU16 want = from_555(batch[i]);
        if (got[i] != want && bad++ < 5) {
          ADD_FAILURE() << name << " source word " << hex(batch[i]) << " stored as "
                        << hex(got[i]) << ", want " << hex(want);
        }
      }
    }
    EXPECT_EQ(bad, 0) << name << ": source words converted wrongly (of " << words.size() << ")";
  }

  // Pixel i has r = i, g = 7i + 3, b = 13i + 5 (mod 256), so every level of every channel
  // occurs, in varied combinations; the top byte (888's pad, 8888's alpha) is random and must
  // not matter. Each channel truncates: r >> 3, g >> 2, b >> 3.
  void check_32bit_format(GrLfbSrcFmt_t format, const std::string &name) {
    std::mt19937 random(static_cast<unsigned>(format) + 17u);
    std::uniform_int_distribution<unsigned> top(0, 255);
    std::vector<FxU32> source(kPixels);
    std::vector<FxU16> want(kPixels);
    for (std::size_t i = 0; i < kPixels; ++i) {
      const int r = static_cast<int>(i & 0xFF), g = static_cast<int>((7 * i + 3) & 0xFF),
                b = static_cast<int>((13 * i + 5) & 0xFF);
      source[i] = top(random) << 24 | static_cast<FxU32>(r) << 16 | static_cast<FxU32>(g) << 8 |
                  static_cast<FxU32>(b);
      want[i] = truncated_565(r, g, b);
    }
    ASSERT_TRUE(
        grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, format, kW, kH, kW * 4, source.data()))
        << name << ": " << glideShimGetLastErrorMessage();
    EXPECT_EQ(count_differences(read_buffer(), want, name + " from 0xAARRGGBB words"), 0);
  }
};

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

// ---------------------------------------------------------------------------------------------
// grLfbLock / grLfbUnlock

TEST_F(LfbTest, ReadLockMatchesReadRegionUpperLeft) {
  std::mt19937 random(2005);
  std::vector<FxU16> words = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, words);
  use_constant_colour(0xFF3366CCu);
  draw_rect(5, 6, 20, 30, vertex());  // a pipeline draw still queued when the lock is taken
  GrLfbInfo_t info;
  std::memset(&info, 0, sizeof info);
  info.size = sizeof(GrLfbInfo_t);
  ASSERT_TRUE(grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_ANY,
                        GR_ORIGIN_UPPER_LEFT, FXFALSE, &info))
      << glideShimGetLastErrorMessage();
  ASSERT_NE(info.lfbPtr, nullptr);
  EXPECT_EQ(info.strideInBytes, static_cast<FxU32>(kW * 2));
  EXPECT_EQ(info.origin, GR_ORIGIN_UPPER_LEFT);
  EXPECT_EQ(info.writeMode, GR_LFBWRITEMODE_565);
  std::vector<FxU16> locked(kPixels);
  for (int y = 0; y < kH; ++y) {
    std::memcpy(&locked[static_cast<std::size_t>(y * kW)],
                static_cast<const unsigned char *>(info.lfbPtr) + y * info.strideInBytes, kW * 2);
  }
  EXPECT_TRUE(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER)) << glideShimGetLastErrorMessage();
  const std::vector<FxU16> region = read_buffer();
  EXPECT_EQ(region[static_cast<std::size_t>(10 * kW + 10)], truncated_565(0x33, 0x66, 0xCC))
      << "the queued rect is not in the buffer";
  EXPECT_EQ(count_differences(locked, region, "read lock vs grLfbReadRegion"), 0);
  expect_no_error();
}

TEST_F(LfbTest, ReadLockWithLowerLeftOriginFlipsTheRows) {
  std::mt19937 random(2006);
  std::vector<FxU16> words = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, words);
  GrLfbInfo_t info;
  std::memset(&info, 0, sizeof info);
  info.size = sizeof(GrLfbInfo_t);
  ASSERT_TRUE(grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_ANY,
                        GR_ORIGIN_LOWER_LEFT, FXFALSE, &info))
      << glideShimGetLastErrorMessage();
  ASSERT_NE(info.lfbPtr, nullptr);
  EXPECT_EQ(info.strideInBytes, static_cast<FxU32>(kW * 2));
  EXPECT_EQ(info.origin, GR_ORIGIN_LOWER_LEFT);
  // Row y of the lock is row kH - 1 - y of the (upper-left) region read.
  std::vector<FxU16> flipped(kPixels);
  for (int y = 0; y < kH; ++y) {
    std::memcpy(&flipped[static_cast<std::size_t>((kH - 1 - y) * kW)],
                static_cast<const unsigned char *>(info.lfbPtr) + y * info.strideInBytes, kW * 2);
  }
  EXPECT_TRUE(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER)) << glideShimGetLastErrorMessage();
  EXPECT_EQ(count_differences(flipped, words, "lower-left read lock, rows turned back"), 0);
  expect_no_error();
}

TEST_F(LfbTest, UnlockSucceedsOnceThenReportsInconsistent) {
  GrLfbInfo_t info;
  std::memset(&info, 0, sizeof info);
  info.size = sizeof(GrLfbInfo_t);
  ASSERT_TRUE(grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_FRONTBUFFER, GR_LFBWRITEMODE_ANY,
                        GR_ORIGIN_UPPER_LEFT, FXFALSE, &info))
      << glideShimGetLastErrorMessage();
  EXPECT_TRUE(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_FRONTBUFFER)) << glideShimGetLastErrorMessage();
  expect_no_error();
  EXPECT_FALSE(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_FRONTBUFFER)) << "second unlock";
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_INCONSISTENT)
      << glideShimErrorName(glideShimGetLastError()) << ": " << glideShimGetLastErrorMessage();
}

TEST_F(LfbTest, WriteLockChangesExactlyThePixelsWritten) {
  std::mt19937 random(2007);
  std::vector<FxU16> words = random_words(random, kPixels);
  std::vector<FxU16> front = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, words);
  fill(GR_BUFFER_FRONTBUFFER, front);
  GrLfbInfo_t info;
  std::memset(&info, 0, sizeof info);
  info.size = sizeof(GrLfbInfo_t);
  ASSERT_TRUE(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565,
                        GR_ORIGIN_UPPER_LEFT, FXFALSE, &info))
      << glideShimGetLastErrorMessage();
  ASSERT_NE(info.lfbPtr, nullptr);
  ASSERT_GE(info.strideInBytes, static_cast<FxU32>(kW * 2));
  struct Write {
    int x, y;
    FxU16 value;
  };
  // Corners, an interior pixel and a neighbour pair; values differ from what is there.
  const Write writes[] = {{0, 0, 0x1234},   {63, 0, 0xF000},  {0, 63, 0x07E0},
                          {63, 63, 0x001F}, {31, 17, 0xBEEF}, {32, 17, 0x0001}};
  std::vector<FxU16> want = words;
  for (const Write &w : writes) {
    FxU16 value = w.value;
    if (value == words[static_cast<std::size_t>(w.y * kW + w.x)]) value ^= 0x8421;
    std::memcpy(static_cast<unsigned char *>(info.lfbPtr) + w.y * info.strideInBytes + w.x * 2,
                &value, 2);
    want[static_cast<std::size_t>(w.y * kW + w.x)] = value;
  }
  ASSERT_TRUE(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER))
      << glideShimGetLastErrorMessage();
  EXPECT_EQ(count_differences(read_buffer(), want, "after a write lock of 6 pixels"), 0);
  EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_FRONTBUFFER), front,
                              "front buffer after a write lock of the back buffer"),
            0);
  expect_no_error();
}

TEST_F(LfbTest, WriteLockWithLowerLeftOriginWritesFlippedRows) {
  std::mt19937 random(2008);
  std::vector<FxU16> words = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, words);
  GrLfbInfo_t info;
  std::memset(&info, 0, sizeof info);
  info.size = sizeof(GrLfbInfo_t);
  ASSERT_TRUE(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565,
                        GR_ORIGIN_LOWER_LEFT, FXFALSE, &info))
      << glideShimGetLastErrorMessage();
  ASSERT_NE(info.lfbPtr, nullptr);
  // Lock row 2 is screen row 61 (from the top).
  FxU16 value = static_cast<FxU16>(words[static_cast<std::size_t>(61 * kW + 5)] ^ 0x5A5A);
  std::memcpy(static_cast<unsigned char *>(info.lfbPtr) + 2 * info.strideInBytes + 5 * 2, &value, 2);
  ASSERT_TRUE(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER))
      << glideShimGetLastErrorMessage();
  std::vector<FxU16> want = words;
  want[static_cast<std::size_t>(61 * kW + 5)] = value;
  EXPECT_EQ(count_differences(read_buffer(), want, "lower-left write lock of (5, row 2)"), 0);
  expect_no_error();
}

// ---------------------------------------------------------------------------------------------
// grBufferSwap and grBufferClear

TEST_F(LfbTest, SwapShowsTheBackBufferAndRecyclesTheFront) {
  std::mt19937 random(2009);
  std::vector<FxU16> front = random_words(random, kPixels);
  std::vector<FxU16> back = random_words(random, kPixels);
  fill(GR_BUFFER_FRONTBUFFER, front);
  fill(GR_BUFFER_BACKBUFFER, back);
  use_constant_colour(0xFF80C040u);
  draw_rect(16, 8, 40, 24, vertex());  // into the back buffer, not yet flushed
  std::vector<FxU16> drawn = back;
  for (int y = 8; y < 24; ++y) {
    for (int x = 16; x < 40; ++x) {
      drawn[static_cast<std::size_t>(y * kW + x)] = truncated_565(0x80, 0xC0, 0x40);
    }
  }
  grBufferSwap(1);
  EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_FRONTBUFFER), drawn,
                              "front buffer after the swap (the drawn back buffer)"),
            0);
  EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_BACKBUFFER), front,
                              "back buffer after the swap (the old front buffer)"),
            0);
  expect_no_error();
}

TEST_F(LfbTest, ClearFillsOnlyTheClipWindow) {
  std::mt19937 random(2010);
  std::vector<FxU16> words = random_words(random, kPixels);
  std::vector<FxU16> front = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, words);
  fill(GR_BUFFER_FRONTBUFFER, front);
  constexpr int kMinX = 10, kMinY = 20, kMaxX = 41, kMaxY = 53;  // max exclusive
  grClipWindow(kMinX, kMinY, kMaxX, kMaxY);
  grBufferClear(0x00C7A35Du, 0, 0);  // ARGB: truncates to 565 (24, 40, 11)
  std::vector<FxU16> want = words;
  for (int y = kMinY; y < kMaxY; ++y) {
    for (int x = kMinX; x < kMaxX; ++x) {
      want[static_cast<std::size_t>(y * kW + x)] = truncated_565(0xC7, 0xA3, 0x5D);
    }
  }
  EXPECT_EQ(count_differences(read_buffer(), want, "clear inside clip window [10,41)x[20,53)"), 0);
  EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_FRONTBUFFER), front,
                              "front buffer after clearing the back buffer"),
            0);
  expect_no_error();
}

TEST_F(LfbTest, ClearWithColourMaskOffKeepsColourButClearsDepth) {
  std::mt19937 random(2011);
  std::vector<FxU16> words = random_words(random, kPixels);
  fill(GR_BUFFER_BACKBUFFER, words);
  grDepthBufferMode(GR_DEPTHBUFFER_ZBUFFER);
  grDepthMask(FXTRUE);
  grBufferClear(0, 0, 0x0000);
  fill(GR_BUFFER_BACKBUFFER, words);
  grColorMask(FXFALSE, FXFALSE);
  grBufferClear(0x00FFFFFFu, 0, 0x4321);
  EXPECT_EQ(count_differences(read_buffer(), words, "colour after a clear with grColorMask off"),
            0);
  EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_AUXBUFFER),
                              std::vector<FxU16>(kPixels, 0x4321),
                              "aux buffer after the same clear (depth mask on)"),
            0);
  expect_no_error();
}

// ---------------------------------------------------------------------------------------------
// The aux buffer

class AuxBufferTest : public LfbTest {
 protected:
  void check_clear_codes(GrDepthBufferMode_t mode, const std::string &name) {
    grDepthBufferMode(mode);
    grDepthMask(FXTRUE);
    for (FxU16 code : {FxU16{0}, FxU16{0x1234}, FxU16{0x8000}, FxU16{0xFFFF}}) {
      grBufferClear(0, 0, code);
      EXPECT_EQ(count_differences(read_buffer(GR_BUFFER_AUXBUFFER),
                                  std::vector<FxU16>(kPixels, code),
                                  name + " aux buffer cleared to " + hex(code)),
                0);
    }
    expect_no_error();
  }
};

TEST_F(AuxBufferTest, WBufferClearCodesReadBackExactly) {
  check_clear_codes(GR_DEPTHBUFFER_WBUFFER, "W-buffer");
}

TEST_F(AuxBufferTest, ZBufferClearCodesReadBackExactly) {
  check_clear_codes(GR_DEPTHBUFFER_ZBUFFER, "Z-buffer");
}

}  // namespace

namespace {

TEST_F(GlideWindowTest, DrawingDuringAWriteLockSurvivesTheUnlock) {
  // The unlock writes back only what the program changed through the pointer.
  grDitherMode(GR_DITHER_DISABLE);
  grBufferClear(0, 0, 0);
  GrLfbInfo_t info{};
  info.size = sizeof info;
  ASSERT_TRUE(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565,
                        GR_ORIGIN_UPPER_LEFT, FXFALSE, &info));
  GrVertex white = vertex();
  white.r = white.g = white.b = 255;
  draw_rect(0, 0, 16, 16, white);
  static_cast<FxU16 *>(info.lfbPtr)[40 * (info.strideInBytes / 2) + 40] = 0x07E0;
  ASSERT_TRUE(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER));
  EXPECT_EQ(pixel(5, 5), 0xFFFF) << "the triangle drawn during the lock was erased";
  EXPECT_EQ(pixel(40, 40), 0x07E0);
  expect_no_error();
}

}  // namespace
