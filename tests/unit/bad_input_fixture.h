// Shared by the bad-input tests, one file per Glide chapter (bad_input_*_test.cpp). The rule
// under test (glide_shim.h): a bad call reports exactly one error (a GlideShimError kind, with a
// message naming the function the program called), hands that message once to the
// grErrorSetCallback callback, changes no state (every group of glide_shim::current(), TMU
// memory, both colour buffers) and never crashes. Here: the fixture and the checks of that rule.
#pragma once

#include "context.h"
#include "glide_window.h"

#include <glideutl.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace bad_input {

using glide_shim::current;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// ---- the error callback ------------------------------------------------------------------------

struct CallbackLog {
  int calls = 0;
  std::string message;
  FxBool fatal = FXFALSE;
};
extern CallbackLog g_log;

// The callback the fixture hands to grErrorSetCallback: it records each call in g_log.
void record_error(const char *string, FxBool fatal);
void reset_errors();  // clears g_log and the last error

// ---- state snapshots ---------------------------------------------------------------------------

// Every group of the context (copied), so a rejected call can be shown to have changed nothing.
struct Snapshot {
  bool initialized;
  glide_shim::ColorPathState color_path;
  glide_shim::BlendState blend;
  glide_shim::ChromaKeyState chroma;
  glide_shim::DepthState depth;
  glide_shim::RasterState raster;
  glide_shim::TmuState tmu;
  glide_shim::DisplayState display;
  glide_shim::LfbLockState lfb;
};

Snapshot capture();
void expect_same_state(const Snapshot &before, const Snapshot &after);

// Exactly one error of `kind` reported since reset_errors(), naming `function`, and the same
// message handed once to the callback.
void expect_one_error(GlideShimError kind, const std::string &function);
void expect_no_error_reported();

// A bad call: the function the program calls, and the call itself (which checks the return).
struct BadCall {
  std::string function;
  std::function<void()> call;
};

// ---- vertices ----------------------------------------------------------------------------------

GrVertex make_vertex(float x, float y);  // white, ooz 1000, every oow 0.5

// A triangle covering pixel (16,16); lines and points are drawn through the same pixel.
extern const GrVertex kA, kB, kC;
constexpr int kProbeX = 16, kProbeY = 16;

// ---- texture descriptions ----------------------------------------------------------------------

std::vector<FxU8> &texel_source();  // 0xAB bytes, more than any mip-map chain
GrTexInfo tex_info(GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                   GrTextureFormat_t format);

// ---- the fixture -------------------------------------------------------------------------------

class BadInputTest : public GlideWindowTest {
 protected:
  static constexpr GrColor_t kFrontColor = 0x00336699u;  // ARGB; neither is white
  static constexpr GrColor_t kBackColor = 0x00204080u;

  void SetUp() override {
    GlideWindowTest::SetUp();
    grErrorSetCallback(record_error);
    grDitherMode(GR_DITHER_DISABLE);
    // Different front and back buffers, so a swap or a write to either one would show.
    grBufferClear(kFrontColor, 0, 0);
    grBufferSwap(0);
    grBufferClear(kBackColor, 0, 0);
    expect_no_error();
    reset_errors();
  }

  // `call` must be rejected with exactly one error of `kind` naming `call.function`, leave every
  // state group unchanged and (with a window open) write no pixel to either colour buffer.
  void expect_rejected(GlideShimError kind, const BadCall &call, const std::string &what = "") {
    SCOPED_TRACE(call.function + (what.empty() ? "" : " (" + what + ")"));
    const bool open = current().display.open;
    std::vector<FxU16> front, back;
    if (open) {
      front = read_buffer(GR_BUFFER_FRONTBUFFER);
      back = read_buffer(GR_BUFFER_BACKBUFFER);
      glideShimResetPixelsWritten();
    }
    const Snapshot before = capture();
    reset_errors();
    call.call();
    expect_one_error(kind, call.function);
    expect_same_state(before, capture());
    if (open) {
      EXPECT_EQ(glideShimPixelsWritten(), 0u) << "pixels were drawn";
      EXPECT_TRUE(read_buffer(GR_BUFFER_FRONTBUFFER) == front) << "the front buffer changed";
      EXPECT_TRUE(read_buffer(GR_BUFFER_BACKBUFFER) == back) << "the back buffer changed";
    }
    reset_errors();
  }

  void expect_all_rejected(GlideShimError kind, const std::vector<BadCall> &calls,
                           const std::string &what = "") {
    for (const BadCall &call : calls) expect_rejected(kind, call, what);
  }

  // `call` draws without any error: the probe pixel becomes `expected` (565).
  void expect_drawn(const BadCall &call, FxU16 expected, const std::string &what) {
    SCOPED_TRACE(call.function + " (" + what + ")");
    grBufferClear(kBackColor, 0, 0);
    ASSERT_NE(pixel(kProbeX, kProbeY), expected);
    glideShimResetPixelsWritten();
    reset_errors();
    call.call();
    EXPECT_GT(glideShimPixelsWritten(), 0u) << "nothing was drawn";
    expect_no_error_reported();
    EXPECT_EQ(pixel(kProbeX, kProbeY), expected);
    reset_errors();
  }

  // Calls that need an open window, each harmless with one open.
  static std::vector<BadCall> calls_needing_a_window();
};

}  // namespace bad_input
