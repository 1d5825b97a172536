// The fixture of the LFB pipeline tests (lfb_pipeline_test.cpp, lfb_write_layout_test.cpp):
// a window with dither off, locks through the pixel pipeline, and pixel writes through the
// lock's pointer and stride (x right, y down from the upper-left origin, in window pixels).
#pragma once
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

namespace lfb_pipeline {

constexpr int kPipelineWidth = 64, kPipelineHeight = 64;  // GlideWindowTest's window

inline std::size_t at(int x, int y) { return static_cast<std::size_t>(y * kPipelineWidth + x); }

inline FxU16 rgb565(int r, int g, int b) { return static_cast<FxU16>((r >> 3) << 11 | (g >> 2) << 5 | (b >> 3)); }

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

}  // namespace lfb_pipeline
