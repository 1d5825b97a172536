// The texture chapter's one-feature Glide programs of tests/sdk (mip_levels, palette_texture,
// load_3df, gu_texture_manager: plain C, public headers only), run as a user would from the
// directory holding their .3df files, each frame captured by GLIDESHIM_DUMP_DIR and compared with
// reference_images/sdk_<name>.png. Tolerance as the other image tests.
#include "image_compare.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

namespace fs = std::filesystem;

const ImageTolerance kAcrossCpus{4.0f / 255.0f, 0.01};

std::string file_bytes(const fs::path &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Runs sdk_<name> -n `frames` in tests/sdk/data with the frame dump on; returns the dump dir.
fs::path run_program(const std::string &name, int frames) {
  const fs::path dir = fs::path(test_output_path("sdk_" + name));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string command = "cd " + std::string(SDK_DATA_DIR) + " && GLIDESHIM_DUMP_DIR=" +
                              dir.string() + " " + SDK_PROGRAM_DIR + "/sdk_" + name + " -n " +
                              std::to_string(frames) + " > " + (dir / "log.txt").string() +
                              " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command << "\n" << file_bytes(dir / "log.txt");
  return dir;
}

class SdkTextureProgram : public ::testing::TestWithParam<const char *> {};

TEST_P(SdkTextureProgram, RendersItsReferenceFrameWithoutGlideErrors) {
  const std::string name = GetParam();
  const fs::path dir = run_program(name, 1);
  const fs::path frame = dir / "frame_00000.png";
  ASSERT_TRUE(fs::exists(frame)) << "no frame dumped for " << name;
  EXPECT_TRUE(matches_reference("sdk_" + name, frame.string(), kAcrossCpus));
}

TEST_P(SdkTextureProgram, EveryFrameOfALoopIsTheSame) {
  // Tables and textures are downloaded again each frame: the frames must not drift.
  const std::string name = GetParam();
  const fs::path dir = run_program(name, 3);
  const std::string first = file_bytes(dir / "frame_00000.png");
  ASSERT_FALSE(first.empty());
  EXPECT_EQ(file_bytes(dir / "frame_00001.png"), first);
  EXPECT_EQ(file_bytes(dir / "frame_00002.png"), first);
}

INSTANTIATE_TEST_SUITE_P(Programs, SdkTextureProgram,
                         ::testing::Values("mip_levels", "palette_texture", "load_3df",
                                           "gu_texture_manager"));

}  // namespace
