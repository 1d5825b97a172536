// Bad input, chapters "buffers" and "linear frame buffer": unknown buffer, origin and LFB
// enums, undefined LFB formats, regions and clip windows outside the screen, and lock misuse
// (second locks, unlocks without a lock, wrong info sizes).
#include "bad_input_fixture.h"

#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace bad_input;

TEST_F(BadInputTest, UnknownBufferAndOriginEnumsAreInvalidEnum) {
  static FxU16 words[4] = {0, 0, 0, 0};
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grRenderBuffer", [] { grRenderBuffer(GR_BUFFER_AUXBUFFER); }},
       {"grRenderBuffer", [] { grRenderBuffer(7); }},
       {"grSstOrigin", [] { grSstOrigin(2); }},
       {"grSstOrigin", [] { grSstOrigin(GR_ORIGIN_ANY); }},
       {"grHints", [] { grHints(GR_HINTTYPE_MAX + 1, 0); }},
       {"grLfbReadRegion", [] { EXPECT_EQ(grLfbReadRegion(7, 0, 0, 1, 1, 2, words), FXFALSE); }},
       {"grLfbWriteRegion", [] { EXPECT_EQ(grLfbWriteRegion(7, 0, 0, GR_LFB_SRC_FMT_565, 1, 1, 2, words), FXFALSE); }},
       {"grLfbLock",
        [] {
          GrLfbInfo_t lock{};
          lock.size = sizeof lock;
          EXPECT_EQ(grLfbLock(GR_LFB_READ_ONLY, 7, GR_LFBWRITEMODE_ANY, GR_ORIGIN_UPPER_LEFT, FXFALSE, &lock), FXFALSE);
        }},
       {"grLfbLock",
        [] {
          GrLfbInfo_t lock{};
          lock.size = sizeof lock;
          EXPECT_EQ(grLfbLock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_ANY, 2, FXFALSE, &lock), FXFALSE);
        }},
       {"grLfbLock",
        [] {
          GrLfbInfo_t lock{};
          lock.size = sizeof lock;
          EXPECT_EQ(grLfbLock(0x2, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_ANY, GR_ORIGIN_UPPER_LEFT, FXFALSE, &lock), FXFALSE);
        }}});
}

// Values Glide 2.x does not define at all are INVALID_ENUM; UNSUPPORTED is only for values
// Glide defines but the shim does not implement yet.
TEST_F(BadInputTest, UndefinedLfbFormatsAreInvalidEnumNotUnsupported) {
  static FxU16 words[4] = {0, 0, 0, 0};
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grLfbWriteRegion", [] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, 3, 1, 1, 2, words), FXFALSE); }},
       {"grLfbWriteRegion", [] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, 0x42, 1, 1, 2, words), FXFALSE); }},
       {"grLfbLock",
        [] {
          GrLfbInfo_t lock{};
          lock.size = sizeof lock;
          EXPECT_EQ(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, 0x42, GR_ORIGIN_UPPER_LEFT, FXFALSE, &lock), FXFALSE);
        }}},
      "undefined format");
  // Defined but not implemented.
  expect_all_rejected(
      GLIDESHIM_ERR_UNSUPPORTED,
      {{"grLfbWriteRegion", [] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_RLE16, 1, 1, 2, words), FXFALSE); }}},
      "defined, not implemented");
}

// ---- regions -----------------------------------------------------------------------------------

struct Region {
  FxU32 x, y, w, h;
};

const Region kBadRegions[] = {
    {0, 0, 0, 1},                  // width 0
    {0, 0, 1, 0},                  // height 0
    {0, 0, 0, 0},
    {64, 0, 1, 1},                 // starts just right of the buffer
    {0, 64, 1, 1},                 // starts just below it
    {63, 0, 2, 1},                 // runs one pixel past the right edge
    {0, 63, 1, 2},                 // one past the bottom
    {0, 0, 65, 64},
    {0xFFFFFFFFu, 0, 2, 1},        // x + width wraps to 1
    {1, 0, 0xFFFFFFFFu, 1},        // x + width wraps to 0
    {0, 0xFFFFFFFFu, 1, 2},        // y + height wraps to 1
    {0, 1, 1, 0xFFFFFFFFu},
    {0x80000000u, 0, 0x80000000u, 1},
    {0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu},
};

std::string describe(const Region &r) {
  return std::to_string(r.w) + "x" + std::to_string(r.h) + " at (" + std::to_string(r.x) + "," +
         std::to_string(r.y) + ")";
}

TEST_F(BadInputTest, LfbReadRegionOutsideTheBufferIsOutOfRange) {
  std::vector<FxU16> dst(4 * kWidth * kHeight, 0xBEEF);
  for (const Region &r : kBadRegions) {
    for (GrBuffer_t buffer : {GR_BUFFER_FRONTBUFFER, GR_BUFFER_BACKBUFFER, GR_BUFFER_AUXBUFFER}) {
      expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                      {"grLfbReadRegion",
                       [&] { EXPECT_EQ(grLfbReadRegion(buffer, r.x, r.y, r.w, r.h, 4 * kWidth, dst.data()), FXFALSE); }},
                      describe(r) + " of buffer " + std::to_string(buffer));
    }
  }
  // A stride shorter than one row of 16-bit pixels.
  expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                  {"grLfbReadRegion", [&] { EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 4, 1, 7, dst.data()), FXFALSE); }},
                  "stride 7 for width 4");
  expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                  {"grLfbReadRegion", [&] { EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 64, 2, 126, dst.data()), FXFALSE); }},
                  "stride 126 for width 64");
  expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                  {"grLfbReadRegion", [&] { EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, 0, 0, 1, 1, 0, dst.data()), FXFALSE); }},
                  "stride 0");
  for (FxU16 word : dst) ASSERT_EQ(word, 0xBEEF) << "a rejected read wrote into the destination";
  // The regions at the very edges are accepted.
  for (const Region &r : {Region{63, 63, 1, 1}, Region{0, 0, 64, 64}, Region{0, 63, 64, 1}}) {
    reset_errors();
    EXPECT_EQ(grLfbReadRegion(GR_BUFFER_BACKBUFFER, r.x, r.y, r.w, r.h, 2 * r.w, dst.data()), FXTRUE)
        << describe(r);
    expect_no_error_reported();
  }
}

TEST_F(BadInputTest, LfbWriteRegionOutsideTheBufferIsOutOfRange) {
  std::vector<FxU32> src(4 * kWidth * kHeight, 0xFFFFFFFFu);  // white in every source format
  for (const Region &r : kBadRegions) {
    for (GrLfbSrcFmt_t format : {GR_LFB_SRC_FMT_565, GR_LFB_SRC_FMT_8888}) {
      for (GrBuffer_t buffer : {GR_BUFFER_FRONTBUFFER, GR_BUFFER_BACKBUFFER}) {
        expect_rejected(
            GLIDESHIM_ERR_OUT_OF_RANGE,
            {"grLfbWriteRegion",
             [&] { EXPECT_EQ(grLfbWriteRegion(buffer, r.x, r.y, format, r.w, r.h, 16 * kWidth, src.data()), FXFALSE); }},
            describe(r) + " format " + std::to_string(format) + " buffer " + std::to_string(buffer));
      }
    }
  }
  // Strides shorter than one row.
  expect_all_rejected(
      GLIDESHIM_ERR_OUT_OF_RANGE,
      {{"grLfbWriteRegion", [&] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_565, 4, 2, 7, src.data()), FXFALSE); }},
       {"grLfbWriteRegion", [&] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_1555, 64, 2, 126, src.data()), FXFALSE); }},
       {"grLfbWriteRegion", [&] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_888, 4, 2, 15, src.data()), FXFALSE); }},
       {"grLfbWriteRegion", [&] { EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 0, 0, GR_LFB_SRC_FMT_8888, 4, 2, 8, src.data()), FXFALSE); }}},
      "stride too small");
  // The edge region is accepted and writes white.
  reset_errors();
  EXPECT_EQ(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 63, 63, GR_LFB_SRC_FMT_565, 1, 1, 2, src.data()), FXTRUE);
  expect_no_error_reported();
  EXPECT_EQ(pixel(63, 63), 0xFFFF);
}

TEST_F(BadInputTest, ClipWindowOutsideTheScreenOrInvertedIsOutOfRange) {
  grClipWindow(4, 5, 60, 61);  // a non-default window, so a reset to full screen would show
  expect_no_error();
  const Region bad[] = {
      {0, 0, 65, 64},  {0, 0, 64, 65},  {10, 0, 5, 64}, {0, 10, 64, 5},
      {65, 0, 66, 64}, {0, 0, 0xFFFFFFFFu, 64}, {0xFFFFFFFFu, 0, 64, 64}, {0, 0xFFFFFFFFu, 64, 64},
  };
  for (const Region &r : bad) {  // here {x, y, w, h} hold minx, miny, maxx, maxy
    expect_rejected(GLIDESHIM_ERR_OUT_OF_RANGE,
                    {"grClipWindow", [&] { grClipWindow(r.x, r.y, r.w, r.h); }},
                    "(" + std::to_string(r.x) + "," + std::to_string(r.y) + ")-(" +
                        std::to_string(r.w) + "," + std::to_string(r.h) + ")");
  }
  // The full screen and an empty window are valid.
  reset_errors();
  grClipWindow(0, 0, 64, 64);
  grClipWindow(7, 7, 7, 7);
  expect_no_error_reported();
  EXPECT_EQ(current().raster.clip.max_x, 7u);
}

// ---- LFB locks ---------------------------------------------------------------------------------

// A rejected lock must leave every field of info as it was.
void expect_info_untouched(const GrLfbInfo_t &info, const GrLfbInfo_t &before) {
  EXPECT_EQ(info.size, before.size);
  EXPECT_EQ(info.lfbPtr, before.lfbPtr) << "a rejected lock handed out a pointer";
  EXPECT_EQ(info.strideInBytes, before.strideInBytes);
  EXPECT_EQ(info.writeMode, before.writeMode);
  EXPECT_EQ(info.origin, before.origin);
}

GrLfbInfo_t fresh_info() {
  GrLfbInfo_t info;
  std::memset(&info, 0x5C, sizeof info);  // a pattern a rejected lock must leave alone
  info.size = sizeof info;
  return info;
}

TEST_F(BadInputTest, SecondLockOfTheSameKindIsInconsistent) {
  for (GrLock_t type : {GrLock_t{GR_LFB_READ_ONLY}, GrLock_t{GR_LFB_WRITE_ONLY},
                        GrLock_t{GR_LFB_READ_ONLY | GR_LFB_NOIDLE}}) {
    SCOPED_TRACE("lock type " + std::to_string(type));
    GrLfbInfo_t first = fresh_info();
    ASSERT_EQ(grLfbLock(type, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, &first), FXTRUE)
        << glideShimGetLastErrorMessage();
    GrLfbInfo_t second = fresh_info();
    const GrLfbInfo_t untouched = second;
    expect_rejected(GLIDESHIM_ERR_INCONSISTENT,
                    {"grLfbLock",
                     [&] { EXPECT_EQ(grLfbLock(type, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, &second), FXFALSE); }},
                    "second lock");
    expect_info_untouched(second, untouched);
    // The first lock is still held and unlocks once.
    EXPECT_EQ(grLfbUnlock(type, GR_BUFFER_BACKBUFFER), FXTRUE) << glideShimGetLastErrorMessage();
    expect_no_error_reported();
  }
}

TEST_F(BadInputTest, UnlockWithoutLockIsInconsistent) {
  expect_all_rejected(
      GLIDESHIM_ERR_INCONSISTENT,
      {{"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER), FXFALSE); }},
       {"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER), FXFALSE); }},
       {"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_FRONTBUFFER), FXFALSE); }}});
  // A write lock on the back buffer is not released by unlocking another buffer, and the pixels
  // written through it are not copied anywhere until the right unlock.
  GrLfbInfo_t info = fresh_info();
  ASSERT_EQ(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, &info), FXTRUE);
  auto *words = static_cast<FxU16 *>(info.lfbPtr);
  words[0] = 0xF81F;
  expect_all_rejected(
      GLIDESHIM_ERR_INCONSISTENT,
      {{"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_FRONTBUFFER), FXFALSE); }},
       {"grLfbUnlock", [] { EXPECT_EQ(grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_BACKBUFFER), FXFALSE); }}},
      "write lock held on the back buffer");
  EXPECT_EQ(grLfbUnlock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER), FXTRUE);
  expect_no_error_reported();
  EXPECT_EQ(pixel(0, 0), 0xF81F);
}

TEST_F(BadInputTest, PipelineWriteLockWhileRenderingToATextureIsUnsupported) {
  GrLfbInfo_t info = fresh_info();
  ASSERT_EQ(glideShimRenderToTexture(GR_TMU0, 0, GR_LOD_64), FXTRUE) << glideShimGetLastErrorMessage();
  expect_rejected(GLIDESHIM_ERR_UNSUPPORTED,
                  {"grLfbLock", [&] { EXPECT_EQ(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXTRUE, &info), FXFALSE); }},
                  "pixel pipeline while rendering to a texture");
  glideShimRenderToFrameBuffer();
  expect_rejected(GLIDESHIM_ERR_INVALID_ENUM,
                  {"grLfbLock", [&] { EXPECT_EQ(grLfbLock(GR_LFB_WRITE_ONLY, GR_BUFFER_AUXBUFFER, GR_LFBWRITEMODE_8888, GR_ORIGIN_UPPER_LEFT, FXFALSE, &info), FXFALSE); }},
                  "colour mode on the aux buffer");
}

TEST_F(BadInputTest, LockInfoWithWrongSizeIsRejected) {
  for (int size : {0, static_cast<int>(sizeof(GrLfbInfo_t)) - 4, static_cast<int>(sizeof(GrLfbInfo_t)) + 4, -1}) {
    for (GrLock_t type : {GrLock_t{GR_LFB_READ_ONLY}, GrLock_t{GR_LFB_WRITE_ONLY}}) {
      GrLfbInfo_t info = fresh_info();
      info.size = size;
      const GrLfbInfo_t untouched = info;
      expect_rejected(GLIDESHIM_ERR_INCONSISTENT,
                      {"grLfbLock",
                       [&] { EXPECT_EQ(grLfbLock(type, GR_BUFFER_BACKBUFFER, GR_LFBWRITEMODE_565, GR_ORIGIN_UPPER_LEFT, FXFALSE, &info), FXFALSE); }},
                      "info->size " + std::to_string(size) + " type " + std::to_string(type));
      expect_info_untouched(info, untouched);
    }
  }
}

}  // namespace
