// The fighter demo as people run it: the inter-fighter shadow the demo exists to show (measured
// from the projected technique's own shadow mask, frame by frame over the run.sh demo), the
// texture sizes --auto-size picks as the camera dollies, run.sh's default arguments overridden
// by the user's, and a run clearing only the frames it owns.
#include "cli/options.h"
#include "fight_demo.h"
#include "figures/figures_kit.h"
#include "scene/fight_scene.h"

#include <glide.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace {

namespace fs = std::filesystem;

// run.sh's default arguments to `glideshadows demo` (its DEMO_DEFAULTS line), as words.
std::vector<std::string> run_sh_demo_defaults() {
  std::ifstream in(std::string(GLIDESHADOWS_SOURCE_DIR) + "/run.sh");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("DEMO_DEFAULTS=(", 0) != 0) continue;
    std::istringstream words(line.substr(line.find('(') + 1, line.find(')') - line.find('(') - 1));
    std::vector<std::string> defaults;
    for (std::string word; words >> word;) defaults.push_back(word);
    return defaults;
  }
  return {};
}

std::string scratch(const std::string &name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "demo_tests" / name;
  fs::remove_all(dir);
  fs::create_directories(dir.parent_path());
  return dir.string();
}

std::set<std::string> files_in(const std::string &dir) {
  std::set<std::string> names;
  for (const fs::directory_entry &entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

class DemoWindow : public ::testing::Test {
 protected:
  void SetUp() override { ASSERT_TRUE(gs::cli::open_window(640, 480)); }
  void TearDown() override { grGlideShutdown(); }
};

TEST_F(DemoWindow, OneFightersShadowCoversTheOtherInMostFrames) {
  // The frames of `./run.sh demo` (its defaults: 96 frames at 12 per second, the whole loop),
  // 640x480, the projected technique with 256-texel textures as the demo renders them.
  gs::demo::DemoSettings settings;
  std::string error;
  gs::TechniqueOptions options;
  options.projected.size = settings.shadow_size;
  std::unique_ptr<gs::ShadowTechnique> technique = gs::make_technique("projected", options, error);
  ASSERT_TRUE(technique) << error;
  gs::FightScene fight(settings.width, settings.height, settings.shadow_size);
  const long kTwoPercent = 640 * 480 / 50;
  int frames_with_shadow = 0, frames_of_red = 0, frames_of_blue = 0;
  std::string log;
  for (int i = 0; i < settings.frames; ++i) {
    const gs::Scene scene = gs::demo::demo_frame_scene(fight, settings, i);
    const gs::demo::InterFighterShadow shadow = gs::demo::measure_inter_fighter_shadow(*technique, scene);
    frames_with_shadow += shadow.share >= 0.02;
    frames_of_red += shadow.pixels[1] >= kTwoPercent;  // red's shadow on blue
    frames_of_blue += shadow.pixels[0] >= kTwoPercent;  // blue's shadow on red
    log += " " + std::to_string(static_cast<int>(1000 * shadow.share));
  }
  RecordProperty("per_mille_of_frame", log);
  EXPECT_GE(2 * frames_with_shadow, settings.frames)
      << frames_with_shadow << " of " << settings.frames << " frames have >= 2% of their pixels in "
      << "one fighter's shadow on the other; per mille per frame:" << log;
  // Both fighters get their turn: each one's shadow alone covers 2% of some frames.
  EXPECT_GE(frames_of_red, settings.frames / 5) << log;
  EXPECT_GE(frames_of_blue, settings.frames / 5) << log;
}

TEST_F(DemoWindow, AutoSizeFollowsTheFightersSizeOnScreen) {
  // The camera dollies in and out; the texture --auto-size picks must change with it, larger
  // when the fighter covers more of the screen.
  gs::demo::DemoSettings settings;
  gs::ProjectedShadowOptions options;
  options.auto_size = true;
  gs::FightScene fight(settings.width, settings.height, settings.shadow_size);
  std::vector<std::pair<long, int>> covered_and_size;  // the red fighter, per frame
  for (int i = 0; i < settings.frames; i += 4) {
    const gs::Scene scene = gs::demo::demo_frame_scene(fight, settings, i);
    const int size = gs::demo::fighter_texture_sizes(scene, options)[0];
    covered_and_size.emplace_back(
        gs::figures::count(gs::figures::coverage(scene, gs::FightScene::kFighters[0])), size);
  }
  std::set<int> sizes;
  for (const auto &[covered, size] : covered_and_size) sizes.insert(size);
  EXPECT_GE(sizes.size(), 2u) << "--auto-size should pick more than one size over the fight";
  const auto [smallest, largest] = std::minmax_element(covered_and_size.begin(), covered_and_size.end());
  EXPECT_LT(smallest->second, largest->second)
      << "the frame where the red fighter covers " << smallest->first << " pixels got a " << smallest->second
      << " texture, the one where it covers " << largest->first << " got " << largest->second;
}

TEST(DemoCommand, ArgumentsAfterRunShDefaultsOverrideThem) {
  // `./run.sh demo --frames 3 --out DIR --direct-path`: run.sh puts its defaults first.
  const std::vector<std::string> defaults = run_sh_demo_defaults();
  ASSERT_NE(std::find(defaults.begin(), defaults.end(), "--frames"), defaults.end()) << "DEMO_DEFAULTS in run.sh";
  ASSERT_NE(std::find(defaults.begin(), defaults.end(), "--out"), defaults.end()) << "DEMO_DEFAULTS in run.sh";
  const std::string out = scratch("override");
  std::string command = GLIDESHADOWS_PATH + std::string(" demo");
  for (const std::string &word : defaults) command += " '" + word + "'";
  command += " --frames 3 --out " + out + " --direct-path --size 160x120 > " + out + ".log 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::set<std::string> expected = {"frame_0000.png", "frame_0001.png", "frame_0002.png",
                                          "contact_sheet.png", "fight.gif"};
  EXPECT_EQ(files_in(out), expected);
}

TEST(DemoCommand, ARunClearsTheFramesItOwnsAndNothingElse) {
  const std::string out = scratch("clear");
  fs::create_directories(out);
  for (const char *name : {"frame_0000.png", "frame_0001.png", "frame_0007.png", "frame_0123.png",
                           "notes.txt", "frame_0001.png.bak"}) {
    std::ofstream(fs::path(out) / name) << "an earlier run";
  }
  const std::string command =
      GLIDESHADOWS_PATH + std::string(" demo --frames 2 --size 160x120 --out ") + out + " > /dev/null 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  const std::set<std::string> expected = {"frame_0000.png", "frame_0001.png", "notes.txt",
                                          "frame_0001.png.bak"};
  EXPECT_EQ(files_in(out), expected);
  EXPECT_GT(fs::file_size(fs::path(out) / "frame_0001.png"), 1000u) << "rewritten by this run";
}

}  // namespace
