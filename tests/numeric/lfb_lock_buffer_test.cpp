// The linear frame buffer's locks and the buffers chapter, exactly: grLfbLock / grLfbUnlock for
// reading and writing in both origins, grBufferSwap, grBufferClear against the clip window and
// masks, and the depth codes of the aux buffer. Every expectation is computed here, bit for bit.
// Region copies and formats: lfb_test.cpp.
#include "lfb_checks.h"

namespace {

using namespace lfb_checks;

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
