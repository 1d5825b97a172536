// The one-feature Glide programs of tests/sdk (plain C, public headers only, in the style of the
// SDK's test programs), run as a user would, each frame captured by the shim's
// GLIDESHIM_DUMP_DIR and compared with reference_images/sdk_<name>.png. Tolerance as the other
// image tests: llvmpipe's output varies across CPU vector ISAs by a few levels on a few pixels.
#include "image_compare.h"

#include <OpenImageIO/imagebuf.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const ImageTolerance kAcrossCpus{4.0f / 255.0f, 0.01};

std::string file_bytes(const fs::path &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs tests/sdk/<name> for `frames` frames with the frame dump on; returns the dump directory.
fs::path run_program(const std::string &name, int frames) {
  const fs::path dir = fs::path(test_output_path("sdk_" + name));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string command = "GLIDESHIM_DUMP_DIR=" + dir.string() + " " + SDK_PROGRAM_DIR +
                              "/sdk_" + name + " -n " + std::to_string(frames) + " > " +
                              (dir / "log.txt").string() + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << file_bytes(dir / "log.txt");
  return dir;
}

class SdkProgram : public ::testing::TestWithParam<const char *> {};

TEST_P(SdkProgram, RendersItsReferenceFrameWithoutGlideErrors) {
  const std::string name = GetParam();
  const fs::path dir = run_program(name, 1);
  const fs::path frame = dir / "frame_00000.png";
  ASSERT_TRUE(fs::exists(frame)) << "no frame dumped for " << name;
  EXPECT_FALSE(fs::exists(dir / "frame_00001.png"));
  EXPECT_TRUE(matches_reference("sdk_" + name, frame.string(), kAcrossCpus));
}

TEST_P(SdkProgram, EveryFrameOfALoopIsTheSame) {
  // `-n 3`: the program draws the same frame three times; the dumps must be byte-identical.
  const std::string name = GetParam();
  const fs::path dir = run_program(name, 3);
  const std::string first = file_bytes(dir / "frame_00000.png");
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(file_bytes(dir / "frame_00001.png"), first);
  EXPECT_EQ(file_bytes(dir / "frame_00002.png"), first);
}

INSTANTIATE_TEST_SUITE_P(Programs, SdkProgram,
                         ::testing::Values("fog_ramp", "polygon_fans", "state_round_trip",
                                           "lfb_formats", "aa_lines", "lfb_pipeline"));

TEST(SdkStateRoundTrip, RestoredPanelEqualsTheSavedOne) {
  // The right panel is drawn after grGlideSetState restored the left panel's state: the two
  // must be identical pixel for pixel (the middle panel, in another state, must not be).
  const fs::path dir = run_program("state_round_trip", 1);
  OIIO::ImageBuf image((dir / "frame_00000.png").string());
  ASSERT_TRUE(image.read());
  const int width = image.spec().width, height = image.spec().height, channels = image.spec().nchannels;
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width * height * channels));
  image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, pixels.data());
  int left_right = 0, left_middle = 0, left_drawn = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < 106; ++x)
      for (int c = 0; c < channels; ++c) {
        auto at = [&](int px) { return pixels[static_cast<std::size_t>((y * width + px) * channels + c)]; };
        left_right += at(x) != at(x + 214);
        left_middle += at(x) != at(x + 107);
        left_drawn += at(x) != at(0);  // the top-left pixel is the clear colour
      }
  EXPECT_GT(left_drawn, 3000) << "the saved state draws the left panel";
  EXPECT_EQ(left_right, 0);
  EXPECT_GT(left_middle, 1000);
}

}  // namespace
