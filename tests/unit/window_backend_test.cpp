// The window backend's choice and its failure without a display, and the keyboard queries on
// headless backends. These run without any X server: the display variables are removed for
// each test and put back afterwards. The headless backend the tests open is the one the process
// was started with (GLIDESHIM_BACKEND, osmesa by default): ctest runs the suite once on each, the
// EGL run in a process of its own (tests/CMakeLists.txt says why). Drawing in a real window is
// tested under Xvfb (tests/window).
#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <string>

namespace {

class WindowBackend : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char *name : kDisplayVariables) {
      if (const char *value = std::getenv(name)) saved_[name] = value;
      unsetenv(name);
    }
    grGlideInit();
    glideShimClearError();
  }
  void TearDown() override {
    grGlideShutdown();
    unsetenv("GLIDESHIM_BACKEND");
    for (const auto &entry : saved_) setenv(entry.first.c_str(), entry.second.c_str(), 1);
    glideShimClearError();
  }

  // The backend GLIDESHIM_BACKEND named when the test started: osmesa or egl.
  std::string headless_backend() const {
    const auto started = saved_.find("GLIDESHIM_BACKEND");
    return started != saved_.end() ? started->second : "osmesa";
  }

  // Opens a window on headless_backend(), checks that backend was chosen, and draws and shows one
  // cleared frame; returns the backend's name.
  std::string open_headless_and_swap() {
    const std::string value = headless_backend();
    setenv("GLIDESHIM_BACKEND", value.c_str(), 1);
    EXPECT_TRUE(open_window()) << glideShimGetLastErrorMessage();
    EXPECT_STREQ(glideShimBackendName(), value.c_str());
    grBufferClear(0, 0, 0);
    grBufferSwap(1);
    return value;
  }

  static FxBool open_window() {
    return grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                        GR_ORIGIN_UPPER_LEFT, 2, 1);
  }

  static constexpr const char *kDisplayVariables[] = {"DISPLAY", "WAYLAND_DISPLAY",
                                                      "SDL_VIDEODRIVER", "GLIDESHIM_BACKEND"};
  std::map<std::string, std::string> saved_;
};

TEST_F(WindowBackend, NoDisplayFailsTheOpenNamingTheProblem) {
  for (const char *value : {"sdl", "window"}) {
    setenv("GLIDESHIM_BACKEND", value, 1);
    EXPECT_FALSE(open_window()) << value;
    EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_BACKEND) << value;
    const std::string message = glideShimGetLastErrorMessage();
    EXPECT_NE(message.find("grSstWinOpen: no display for the SDL window"), std::string::npos)
        << message;
    EXPECT_NE(message.find("DISPLAY"), std::string::npos) << message;
    EXPECT_STREQ(glideShimBackendName(), "");  // nothing was opened
    glideShimClearError();
  }
  // The failed open changed nothing: a headless window opens next.
  setenv("GLIDESHIM_BACKEND", "osmesa", 1);
  EXPECT_TRUE(open_window()) << glideShimGetLastErrorMessage();
  EXPECT_STREQ(glideShimBackendName(), "osmesa");
}

TEST_F(WindowBackend, UnknownBackendNamesTheWindowChoice) {
  setenv("GLIDESHIM_BACKEND", "glfw", 1);
  EXPECT_FALSE(open_window());
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_ERR_BACKEND);
  EXPECT_NE(std::string(glideShimGetLastErrorMessage()).find("sdl for a window"),
            std::string::npos)
      << glideShimGetLastErrorMessage();
}

TEST_F(WindowBackend, HeadlessHasNoKeysAndIsNeverClosed) {
  EXPECT_EQ(glideShimPollKey(), GLIDESHIM_KEY_NONE);  // no window at all
  EXPECT_FALSE(glideShimWindowClosed());
  const std::string value = open_headless_and_swap();
  if (::testing::Test::HasFailure()) return;
  EXPECT_EQ(glideShimPollKey(), GLIDESHIM_KEY_NONE) << value;
  EXPECT_FALSE(glideShimWindowClosed()) << value;
  grSstWinClose();
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

TEST_F(WindowBackend, HoldingTheLastFrameNeedsAWindow) {
  // GLIDESHIM_HOLD=1 waits for a key in the window at grSstWinClose; headless there is no
  // window and no key, so the close must return at once and say nothing.
  setenv("GLIDESHIM_HOLD", "1", 1);
  const std::string value = open_headless_and_swap();
  if (::testing::Test::HasFailure()) return;
  ::testing::internal::CaptureStderr();
  grSstWinClose();
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << value;
  unsetenv("GLIDESHIM_HOLD");
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

}  // namespace
