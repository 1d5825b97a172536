// `glideshadows demo --window` under Xvfb (ctest label `window`): screenshots from the X server
// (xwd) against the headless demo's frames, keys typed with xdotool. Paused, the window shows
// exactly the headless frame of the same moment once the overlay is off; each key's effect is
// seen in the window and in the line the demo prints for it.
#include "x_session.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <memory>

namespace {

using window_test::ChildProcess;
using window_test::RgbImage;

std::string output_file(const std::string &name) {
  const std::filesystem::path dir = std::filesystem::path(DEMO_WINDOW_OUTPUT_DIR);
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

// A screenshot also as PNG beside its xwd, for people looking at a failure.
void save_png(const RgbImage &image, const std::string &path) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  if (!out || !out->open(path, OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::UINT8))) return;
  out->write_image(OIIO::TypeDesc::UINT8, image.rgb.data());
  out->close();
}

// Pixels that differ inside the rectangle [x0, x1) x [y0, y1).
long differing(const RgbImage &a, const RgbImage &b, int x0, int y0, int x1, int y1) {
  long n = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const std::size_t at = (static_cast<std::size_t>(y) * a.width + x) * 3;
      n += std::memcmp(&a.rgb[at], &b.rgb[at], 3) != 0;
    }
  }
  return n;
}

class DemoInWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    // The headless demo's first two frames, the reference for the paused window.
    const std::string out = output_file("headless");
    std::filesystem::remove_all(out);
    const std::string command = std::string(GLIDESHADOWS_PATH) + " demo --frames 2 --out " + out + " > /dev/null";
    ASSERT_EQ(window_test::run_command(command), 0) << command;
    std::string error;
    ASSERT_TRUE(window_test::read_png(out + "/frame_0000.png", frames_[0], error)) << error;
    ASSERT_TRUE(window_test::read_png(out + "/frame_0001.png", frames_[1], error)) << error;
  }

  // Reads the demo's output until `text` appears at or after `from`; its position, or npos.
  static std::size_t wait_after(ChildProcess &demo, std::size_t from, const std::string &text) {
    for (int tries = 0; tries < 300; ++tries) {  // 0.1 s each
      const std::size_t at = demo.output().find(text, from);
      if (at != std::string::npos && demo.output().find('\n', at) != std::string::npos) return at;
      demo.wait_for_line("\x01never printed", 0.1);  // reads whatever arrives meanwhile
    }
    return std::string::npos;
  }

  // Types `keys` into the window, waits for the demo's line `expect` and then for the frame
  // it shows next (paused), and takes a screenshot.
  RgbImage after_keys(ChildProcess &demo, const std::string &window, const std::string &keys,
                      const std::string &expect, const std::string &name) {
    const std::size_t seen = demo.output().size();
    EXPECT_EQ(window_test::run_command("xdotool windowfocus --sync " + window + " key " + keys), 0);
    const std::size_t said = wait_after(demo, seen, expect);
    EXPECT_NE(said, std::string::npos) << "no '" << expect << "' after " << keys << ": " << demo.output();
    EXPECT_NE(wait_after(demo, said == std::string::npos ? seen : said, "showing"), std::string::npos)
        << demo.output();
    RgbImage image;
    std::string error;
    EXPECT_TRUE(window_test::screenshot(window, output_file(name + ".xwd"), image, error)) << error;
    save_png(image, output_file(name + ".png"));
    return image;
  }

  RgbImage frames_[2];
};

TEST_F(DemoInWindow, PausedItShowsTheHeadlessFramesAndTheKeysChangeTheView) {
  ChildProcess demo({GLIDESHADOWS_PATH, "demo", "--window", "--paused"}, {"GLIDESHIM_BACKEND=sdl"});
  ASSERT_TRUE(demo.wait_for_line("showing 0.000 s", 60.0)) << "output: " << demo.output();
  EXPECT_NE(demo.output().find("window 640x480 (backend sdl)"), std::string::npos) << demo.output();
  const std::string window = window_test::window_of_process(demo.pid());
  ASSERT_FALSE(window.empty()) << "no visible window of the demo";

  RgbImage with_overlay;
  std::string error;
  ASSERT_TRUE(window_test::screenshot(window, output_file("overlay.xwd"), with_overlay, error)) << error;
  save_png(with_overlay, output_file("overlay.png"));
  ASSERT_EQ(with_overlay.width, 640);
  ASSERT_EQ(with_overlay.height, 480);
  // The overlay (top left) is on at the start; the rest of the frame is the headless one.
  EXPECT_GT(differing(with_overlay, frames_[0], 0, 0, 200, 60), 2000) << "no overlay of fps and step times";
  EXPECT_EQ(differing(with_overlay, frames_[0], 0, 300, 640, 480), 0);

  const RgbImage plain = after_keys(demo, window, "o", "overlay off", "plain");
  EXPECT_EQ(differing(plain, frames_[0], 0, 0, 640, 480), 0) << "paused at 0 s without the overlay";
  const RgbImage stepped = after_keys(demo, window, "period", "paused at 0.083 s", "stepped");
  EXPECT_EQ(differing(stepped, frames_[1], 0, 0, 640, 480), 0) << "'.' steps to the next frame";

  const RgbImage help = after_keys(demo, window, "h", "help on", "help");
  EXPECT_GT(differing(help, frames_[1], 80, 120, 640, 480), 10000) << "the help panel";
  EXPECT_EQ(differing(help, frames_[1], 0, 0, 640, 110), 0) << "only the help panel changed";
  const RgbImage inset = after_keys(demo, window, "h v", "inset on", "inset");
  EXPECT_GT(differing(inset, frames_[1], 480, 0, 640, 330), 10000) << "the insets, top right";
  EXPECT_EQ(differing(inset, frames_[1], 0, 0, 470, 480), 0) << "only the insets changed";

  const RgbImage orbited = after_keys(demo, window, "v Right", "camera orbit 10 degrees", "orbited");
  EXPECT_GT(differing(orbited, frames_[1], 0, 0, 640, 480), 20000) << "the camera moved";
  const RgbImage lit = after_keys(demo, window, "r w w w", "light raised 0.6 m", "light_raised");
  EXPECT_GT(differing(lit, frames_[1], 0, 0, 640, 480), 2000) << "the light moved, so did the shadows";
  const RgbImage planar = after_keys(demo, window, "r t t", "technique planar", "planar");
  EXPECT_GT(differing(planar, frames_[1], 0, 0, 640, 480), 500) << "another technique draws other shadows";
  after_keys(demo, window, "minus", "shadow texture 128", "smaller");

  ASSERT_EQ(window_test::run_command("xdotool key Escape"), 0);
  EXPECT_EQ(demo.wait_for_exit(30.0), 0) << demo.output();
  EXPECT_NE(demo.output().find("window closed"), std::string::npos) << demo.output();
}

TEST(DemoHelp, ListsTheWindowKeys) {
  std::string help;
  ASSERT_EQ(window_test::run_command(std::string(GLIDESHADOWS_PATH) + " demo --help", &help), 0);
  for (const char *key : {"--window", "SPACE", "LEFT RIGHT", "UP DOWN", "A D", "W S", "T SHIFT+T", "+ -", "V ", "O ", "H F1"}) {
    EXPECT_NE(help.find(key), std::string::npos) << key << " missing from:\n" << help;
  }
}

}  // namespace
