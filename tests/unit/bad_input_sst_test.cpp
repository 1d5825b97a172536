// Bad input, chapter "SST routines": every call that needs the library and a window is
// NOT_INITIALIZED before grGlideInit, before grSstWinOpen and after grSstWinClose; unknown
// grSstWinOpen enums; glideShimFlush drawing what is queued; out-of-range numbers (gamma, LOD bias,
// swap interval, board, window size).
#include "bad_input_fixture.h"

#include <string>
#include <vector>

namespace {

using namespace bad_input;

// ---- calls without a library or a window -------------------------------------------------------

TEST_F(BadInputTest, CallsBeforeGrGlideInitAreNotInitialized) {
  grGlideShutdown();
  reset_errors();
  std::vector<BadCall> calls = calls_needing_a_window();
  calls.push_back({"grSstWinOpen", [] {
                     EXPECT_EQ(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                                            GR_ORIGIN_UPPER_LEFT, 2, 1),
                               FXFALSE);
                   }});
  calls.push_back({"grSstQueryHardware", [] {
                     GrHwConfiguration hw;
                     EXPECT_EQ(grSstQueryHardware(&hw), FXFALSE);
                   }});
  expect_all_rejected(GLIDESHIM_ERR_NOT_INITIALIZED, calls, "before grGlideInit");
}

TEST_F(BadInputTest, CallsBeforeGrSstWinOpenAreNotInitialized) {
  grGlideShutdown();
  grGlideInit();
  reset_errors();
  expect_all_rejected(GLIDESHIM_ERR_NOT_INITIALIZED, calls_needing_a_window(), "before grSstWinOpen");
}

TEST_F(BadInputTest, CallsAfterGrSstWinCloseAreNotInitialized) {
  grSstWinClose();
  reset_errors();
  expect_all_rejected(GLIDESHIM_ERR_NOT_INITIALIZED, calls_needing_a_window(), "after grSstWinClose");
  // Closing again is harmless and reports nothing.
  grSstWinClose();
  expect_no_error_reported();
}

TEST_F(BadInputTest, UnknownWinOpenEnumsAreInvalidEnum) {
  grSstWinClose();
  reset_errors();
  auto open = [](GrScreenResolution_t resolution, GrColorFormat_t format, GrOriginLocation_t origin) {
    return [=] {
      EXPECT_EQ(grSstWinOpen(0, resolution, GR_REFRESH_60Hz, format, origin, 2, 1), FXFALSE);
    };
  };
  expect_all_rejected(
      GLIDESHIM_ERR_INVALID_ENUM,
      {{"grSstWinOpen", open(GR_RESOLUTION_400x300 + 1, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(-1, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(0xfe, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(GR_RESOLUTION_NONE, 4, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(GR_RESOLUTION_NONE, -1, GR_ORIGIN_UPPER_LEFT)},
       {"grSstWinOpen", open(GR_RESOLUTION_NONE, GR_COLORFORMAT_ARGB, 2)},
       {"grSstWinOpen", open(GR_RESOLUTION_NONE, GR_COLORFORMAT_ARGB, GR_ORIGIN_ANY)}});
  EXPECT_FALSE(current().display.open);
  // A good open still works afterwards, and a second open while one is open is refused.
  EXPECT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1));
  expect_no_error_reported();
  expect_rejected(GLIDESHIM_ERR_INCONSISTENT,
                  {"grSstWinOpen", open(GR_RESOLUTION_NONE, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT)},
                  "already open");
}

// ---- glideShimFlush ----------------------------------------------------------------------------

// It hands the queued triangle to GL without waiting: no error, no state changed, and the pixel
// read afterwards is the triangle's, as without it; with nothing queued it does nothing.
TEST_F(BadInputTest, GlideShimFlushDrawsWhatIsQueuedAndChangesNoState) {
  const Snapshot before = capture();
  expect_drawn({"glideShimFlush", [] { grDrawTriangle(&kA, &kB, &kC), glideShimFlush(); }}, 0xFFFF,
               "a queued triangle");
  glideShimFlush();
  expect_no_error_reported();
  expect_same_state(before, capture());
}

// ---- out-of-range numbers ----------------------------------------------------------------------

TEST_F(BadInputTest, OutOfRangeNumbersAreRejected) {
  grGammaCorrectionValue(2.2f);
  grTexLodBiasValue(GR_TMU0, 0.5f);
  expect_no_error();
  expect_all_rejected(
      GLIDESHIM_ERR_OUT_OF_RANGE,
      {{"grGammaCorrectionValue", [] { grGammaCorrectionValue(kNaN); }},
       {"grGammaCorrectionValue", [] { grGammaCorrectionValue(0.0f); }},
       {"grGammaCorrectionValue", [] { grGammaCorrectionValue(-1.0f); }},
       {"grGammaCorrectionValue", [] { grGammaCorrectionValue(kInf); }},
       {"grTexLodBiasValue", [] { grTexLodBiasValue(GR_TMU0, 100.0f); }},
       {"grTexLodBiasValue", [] { grTexLodBiasValue(GR_TMU0, -100.0f); }},
       {"grTexLodBiasValue", [] { grTexLodBiasValue(GR_TMU0, kNaN); }},
       {"grBufferSwap", [] { grBufferSwap(-1); }},
       {"grSstSelect", [] { grSstSelect(1); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(0, 10), FXFALSE); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(10, 0), FXFALSE); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(-5, 10), FXFALSE); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(100000, 100000), FXFALSE); }},
       {"glideShimSetWindowSize", [] { EXPECT_EQ(glideShimSetWindowSize(2049, 16), FXFALSE); }}});
  EXPECT_FLOAT_EQ(current().display.gamma, 2.2f);
  EXPECT_FLOAT_EQ(current().tmu.lod_bias, 0.5f);
  // The refused window size is not used by the next open.
  grSstWinClose();
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT, 2, 1));
  EXPECT_EQ(current().display.width, kWidth);
  EXPECT_EQ(current().display.height, kHeight);
}

}  // namespace
