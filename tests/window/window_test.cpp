// The SDL window backend under Xvfb (ctest label `window`; the tests run inside xvfb-run).
// Screenshots are taken from the X server with xwd, so they show what the display shows. The
// window must show exactly the bytes of the headless frame (both are the front buffer through
// the same scan-out, and llvmpipe renders the same in the GLX context as in OSMesa), so every
// comparison is byte-equal: no tolerance.
#include "x_session.h"

#include <SDL.h>
#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>

namespace {

using window_test::ChildProcess;
using window_test::RgbImage;

std::string output_file(const std::string &name) {
  const std::filesystem::path dir = std::filesystem::path(WINDOW_TEST_OUTPUT_DIR);
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

::testing::AssertionResult same_pixels(const RgbImage &shown, const RgbImage &expected) {
  if (shown.width != expected.width || shown.height != expected.height) {
    return ::testing::AssertionFailure() << "shown " << shown.width << "x" << shown.height
                                         << ", expected " << expected.width << "x"
                                         << expected.height;
  }
  std::size_t differing = 0, first = 0;
  for (std::size_t i = 0; i < shown.rgb.size() / 3; ++i) {
    if (std::memcmp(&shown.rgb[3 * i], &expected.rgb[3 * i], 3) != 0 && differing++ == 0) first = i;
  }
  if (differing == 0) return ::testing::AssertionSuccess();
  const auto x = first % static_cast<std::size_t>(shown.width);
  const auto y = first / static_cast<std::size_t>(shown.width);
  return ::testing::AssertionFailure()
         << differing << " pixels differ; first at (" << x << "," << y << "): shown "
         << int(shown.rgb[3 * first]) << "," << int(shown.rgb[3 * first + 1]) << ","
         << int(shown.rgb[3 * first + 2]) << ", expected " << int(expected.rgb[3 * first]) << ","
         << int(expected.rgb[3 * first + 1]) << "," << int(expected.rgb[3 * first + 2]);
}

std::size_t distinct_colours(const RgbImage &image) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    colours.insert(static_cast<std::uint32_t>(image.rgb[i] << 16 | image.rgb[i + 1] << 8 |
                                              image.rgb[i + 2]));
  }
  return colours.size();
}

// ---- The sample program, run as a user would, in a window and headless ----

TEST(DemoProgram, WindowShowsTheHeadlessFrame) {
  const std::string headless_png = output_file("demo_headless.png");
  const std::string headless = "GLIDESHIM_BACKEND=osmesa " + std::string(INTERACTIVE_GLIDE_PATH) +
                               " -n 12 --png " + headless_png + " > /dev/null";
  ASSERT_EQ(window_test::run_command(headless), 0) << headless;

  ChildProcess demo({INTERACTIVE_GLIDE_PATH, "-n", "12", "--hold"}, {"GLIDESHIM_BACKEND=sdl"});
  ASSERT_TRUE(demo.wait_for_line("holding", 30.0)) << "output: " << demo.output();
  EXPECT_NE(demo.output().find("12 frames at 640x480 (backend sdl)"), std::string::npos)
      << demo.output();
  const std::string window = window_test::window_of_process(demo.pid());
  ASSERT_FALSE(window.empty()) << "no visible window of the demo (is xdotool installed?)";

  RgbImage shown, expected;
  std::string error;
  ASSERT_TRUE(window_test::screenshot(window, output_file("demo_window.xwd"), shown, error))
      << error;
  ASSERT_TRUE(window_test::read_png(headless_png, expected, error)) << error;
  EXPECT_EQ(shown.width, 640);
  EXPECT_EQ(shown.height, 480);
  EXPECT_GT(distinct_colours(expected), 100u) << "the frame should hold a shaded scene";
  EXPECT_TRUE(same_pixels(shown, expected));

  ASSERT_EQ(window_test::run_command("xdotool windowfocus --sync " + window + " key Escape"), 0);
  EXPECT_EQ(demo.wait_for_exit(20.0), 0) << demo.output();
}

TEST(DemoProgram, KeysTypedInTheWindowReachTheProgram) {
  // Real X key events (XTEST, as a keyboard makes them) into the focused window; the program
  // prints each key glideShimPollKey returns, and quits on Escape.
  ChildProcess demo({INTERACTIVE_GLIDE_PATH, "-n", "3", "--hold"}, {"GLIDESHIM_BACKEND=sdl"});
  ASSERT_TRUE(demo.wait_for_line("holding", 30.0)) << "output: " << demo.output();
  const std::string window = window_test::window_of_process(demo.pid());
  ASSERT_FALSE(window.empty()) << "no visible window of the demo (is xdotool installed?)";
  ASSERT_EQ(window_test::run_command("xdotool windowfocus --sync " + window), 0);
  ASSERT_EQ(window_test::run_command("xdotool type 'aB'"), 0);
  ASSERT_EQ(window_test::run_command("xdotool key Left F3 Return"), 0);
  ASSERT_TRUE(demo.wait_for_line("key 13", 20.0)) << "output: " << demo.output();
  const std::string expected_keys =
      "interactive_glide: key 97\n"                                                      // a
      "interactive_glide: key 66\n"                                                      // B
      "interactive_glide: key " + std::to_string(GLIDESHIM_KEY_LEFT) + "\n"              // Left
      "interactive_glide: key " + std::to_string(GLIDESHIM_KEY_F1 + 2) + "\n"            // F3
      "interactive_glide: key " + std::to_string(GLIDESHIM_KEY_ENTER) + "\n";            // Return
  EXPECT_NE(demo.output().find("holding\n" + expected_keys), std::string::npos) << demo.output();

  ASSERT_EQ(window_test::run_command("xdotool key Escape"), 0);
  EXPECT_EQ(demo.wait_for_exit(20.0), 0) << demo.output();
  EXPECT_NE(demo.output().find("key 27\n"), std::string::npos) << demo.output();
}

// ---- An unmodified SDK-style program: it knows nothing of windows or keys ----

TEST(SdkProgram, WindowShowsTheHeadlessFrame) {
  // examples/crate_3df.c is plain Glide: 640x480 ABGR, -n frames, textures from .3df files. The
  // same binary runs headless (frame dump) and in the window; GLIDESHIM_HOLD=1 keeps its last
  // frame up after it closes Glide, until a key.
  const std::string dump = output_file("crate_3df_headless");
  std::filesystem::remove_all(dump);
  std::filesystem::create_directories(dump);
  const std::string headless = "cd " + std::string(EXAMPLES_DATA_DIR) +
                               " && GLIDESHIM_BACKEND=osmesa GLIDESHIM_DUMP_DIR=" + dump + " " +
                               CRATE_3DF_PATH + " -n 12 > /dev/null";
  ASSERT_EQ(window_test::run_command(headless), 0) << headless;

  ChildProcess program({"/bin/sh", "-c",
                        "cd " + std::string(EXAMPLES_DATA_DIR) + " && exec " + CRATE_3DF_PATH +
                            " -n 12 2>&1"},
                       {"GLIDESHIM_BACKEND=sdl", "GLIDESHIM_HOLD=1"});
  ASSERT_TRUE(program.wait_for_line("holding the last frame", 60.0))
      << "output: " << program.output();
  const std::string window = window_test::window_of_process(program.pid());
  ASSERT_FALSE(window.empty()) << "no visible window of crate_3df";

  RgbImage shown, expected;
  std::string error;
  ASSERT_TRUE(window_test::screenshot(window, output_file("crate_3df_window.xwd"), shown, error))
      << error;
  ASSERT_TRUE(window_test::read_png(dump + "/frame_00011.png", expected, error)) << error;
  EXPECT_EQ(shown.width, 640);
  EXPECT_EQ(shown.height, 480);
  EXPECT_GT(distinct_colours(expected), 100u) << "the frame should hold a textured scene";
  EXPECT_TRUE(same_pixels(shown, expected));

  ASSERT_EQ(window_test::run_command("xdotool windowfocus --sync " + window + " key space"), 0);
  EXPECT_EQ(program.wait_for_exit(20.0), 0) << program.output();
  EXPECT_NE(program.output().find("crate_3df: 12 frames at 640x480"), std::string::npos)
      << program.output();
}

// ---- The shim in this process, with the window backend ----

class SdlWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    setenv("GLIDESHIM_BACKEND", "sdl", 1);
    grGlideInit();
    glideShimClearError();
  }
  void TearDown() override {
    grGlideShutdown();
    unsetenv("GLIDESHIM_BACKEND");
    glideShimClearError();
  }

  static void open(GrScreenResolution_t resolution) {
    ASSERT_TRUE(grSstWinOpen(0, resolution, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                             GR_ORIGIN_UPPER_LEFT, 2, 1))
        << glideShimGetLastErrorMessage();
    ASSERT_STREQ(glideShimBackendName(), "sdl");
  }

  // What the X display shows in this process's window.
  static RgbImage shown(const std::string &name) {
    const std::string window = window_test::window_of_process(getpid());
    RgbImage image;
    std::string error;
    EXPECT_FALSE(window.empty()) << "no visible window of this process";
    EXPECT_TRUE(window_test::screenshot(window, output_file(name + ".xwd"), image, error))
        << error;
    return image;
  }

  // A colour buffer as the frame export writes it.
  static RgbImage exported(GrBuffer_t buffer, const std::string &name) {
    const std::string png = output_file(name + ".png");
    RgbImage image;
    std::string error;
    EXPECT_TRUE(glideShimWritePng(buffer, png.c_str())) << glideShimGetLastErrorMessage();
    EXPECT_TRUE(window_test::read_png(png, image, error)) << error;
    return image;
  }

  static GrVertex vertex(float x, float y, float r, float g, float b) {
    GrVertex v;
    std::memset(&v, 0, sizeof v);
    v.x = x;
    v.y = y;
    v.oow = 1.0f;
    v.r = r;
    v.g = g;
    v.b = b;
    return v;
  }

  static void push_sdl_event(SDL_Event event) { ASSERT_EQ(SDL_PushEvent(&event), 1); }
  static std::uint32_t window_id() { return SDL_GetWindowID(SDL_GL_GetCurrentWindow()); }
};

TEST_F(SdlWindow, ShowsTheFrontBufferThroughGammaAtTheChosenResolution) {
  open(GR_RESOLUTION_800x600);
  grBufferClear(0x00203040, 0, 0);
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  GrVertex a = vertex(50, 40, 255, 0, 0), b = vertex(760, 90, 0, 255, 0),
           c = vertex(300, 560, 0, 0, 255);
  grDrawTriangle(&a, &b, &c);
  // An LFB write of mid grey (565 0x8410 = 8-bit 132,130,132) bypasses the pixel pipeline.
  std::vector<FxU16> grey(100 * 50, 0x8410);
  ASSERT_TRUE(grLfbWriteRegion(GR_BUFFER_BACKBUFFER, 650, 500, GR_LFB_SRC_FMT_565, 100, 50,
                               200, grey.data()))
      << glideShimGetLastErrorMessage();
  grGammaCorrectionValue(2.2f);  // not Glide's default 1.7: the window follows the setting
  grBufferSwap(0);

  const RgbImage window = shown("gamma_800x600");
  EXPECT_EQ(window.width, 800);
  EXPECT_EQ(window.height, 600);
  EXPECT_TRUE(same_pixels(window, exported(GR_BUFFER_FRONTBUFFER, "gamma_800x600")));
  // Gamma 2.2 brightens the grey at scan-out; the frame buffer itself keeps 0x8410.
  const std::uint8_t *grey_shown = &window.rgb[(520 * 800 + 700) * 3];
  EXPECT_GT(grey_shown[0], 132 + 20);
  EXPECT_GT(grey_shown[1], 130 + 20);
  FxU16 stored = 0;
  ASSERT_TRUE(grLfbReadRegion(GR_BUFFER_FRONTBUFFER, 700, 520, 1, 1, 2, &stored));
  EXPECT_EQ(stored, 0x8410);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

TEST_F(SdlWindow, ShowsOnlySwappedFrames) {
  open(GR_RESOLUTION_512x384);
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  grBufferClear(0x00C02020, 0, 0);
  GrVertex a = vertex(10, 10, 255, 255, 0), b = vertex(500, 30, 0, 255, 255),
           c = vertex(200, 370, 255, 0, 255);
  grDrawTriangle(&a, &b, &c);
  grBufferSwap(1);
  const RgbImage first = exported(GR_BUFFER_FRONTBUFFER, "swap_first");

  // The next frame is drawn into the back buffer: the window keeps showing the first.
  grBufferClear(0x002040C0, 0, 0);
  GrVertex d = vertex(400, 300, 255, 255, 255), e = vertex(20, 200, 0, 0, 0),
           f = vertex(300, 20, 128, 128, 128);
  grDrawTriangle(&d, &e, &f);
  EXPECT_EQ(glideShimPollKey(), GLIDESHIM_KEY_NONE);  // reads the window's pending events
  const RgbImage second = exported(GR_BUFFER_BACKBUFFER, "swap_second");
  ASSERT_FALSE(same_pixels(first, second)) << "the two frames must differ for this test";
  EXPECT_TRUE(same_pixels(shown("swap_before"), first));

  grBufferSwap(1);
  EXPECT_TRUE(same_pixels(shown("swap_after"), second));
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

TEST_F(SdlWindow, CloseButtonIsReportedAndTheWindowStaysUsable) {
  open(GR_RESOLUTION_640x480);
  EXPECT_FALSE(glideShimWindowClosed());
  // The event SDL makes from the window manager's WM_DELETE_WINDOW (the close button).
  SDL_Event close{};
  close.type = SDL_WINDOWEVENT;
  close.window.event = SDL_WINDOWEVENT_CLOSE;
  close.window.windowID = window_id();
  push_sdl_event(close);
  EXPECT_TRUE(glideShimWindowClosed());
  EXPECT_TRUE(glideShimWindowClosed());  // it stays set: the program decides when to stop
  grBufferClear(0x00FFFFFF, 0, 0);
  grBufferSwap(1);
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
  grSstWinClose();
  EXPECT_FALSE(glideShimWindowClosed());  // no window any more
}

TEST_F(SdlWindow, KeyQueueKeepsOrderAndDropsKeysWhenFull) {
  open(GR_RESOLUTION_640x480);
  for (int i = 0; i < 70; ++i) {
    SDL_Event key{};
    key.type = SDL_KEYDOWN;
    key.key.windowID = window_id();
    key.key.keysym.sym = SDLK_F1 + i % 12;
    push_sdl_event(key);
  }
  for (int i = 0; i < 64; ++i) {
    ASSERT_EQ(glideShimPollKey(), GLIDESHIM_KEY_F1 + i % 12) << "key " << i;
  }
  EXPECT_EQ(glideShimPollKey(), GLIDESHIM_KEY_NONE);  // keys 64..69 found the queue full
}

TEST_F(SdlWindow, ReopensAtAnotherSizeAndHandsOverToHeadless) {
  open(GR_RESOLUTION_640x480);
  grSstWinClose();
  open(GR_RESOLUTION_512x384);
  grBufferClear(0x00808080, 0, 0);
  grBufferSwap(1);
  const RgbImage window = shown("reopened");
  EXPECT_EQ(window.width, 512);
  EXPECT_EQ(window.height, 384);
  EXPECT_TRUE(same_pixels(window, exported(GR_BUFFER_FRONTBUFFER, "reopened")));
  grSstWinClose();

  setenv("GLIDESHIM_BACKEND", "osmesa", 1);
  ASSERT_TRUE(grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                           GR_ORIGIN_UPPER_LEFT, 2, 1))
      << glideShimGetLastErrorMessage();
  EXPECT_STREQ(glideShimBackendName(), "osmesa");
  EXPECT_EQ(glideShimPollKey(), GLIDESHIM_KEY_NONE);
  EXPECT_EQ(window_test::window_of_process(getpid(), false), "") << "the SDL window should be gone";
}

}  // namespace
