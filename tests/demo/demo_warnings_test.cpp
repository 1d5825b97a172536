// The demo's account of its warnings: each distinct one with the number of frames it came in,
// errors (a shadow the frame lacks) told apart, and the frames that lack a shadow; and the
// headless run's default, --grow-size, against --no-grow-size at the demo's frame 90 (7.5 s),
// where both fighters' 256-texel shadows are refused as too coarse for the screen.
#include "fight_demo.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

gs::FrameReport frame_with(const std::vector<std::string> &warnings,
                           const std::vector<std::string> &errors) {
  gs::FrameReport frame;
  frame.errors = errors;
  frame.warnings = errors;  // errors are warnings too (technique.h)
  frame.warnings.insert(frame.warnings.end(), warnings.begin(), warnings.end());
  return frame;
}

// `glideshadows demo ARGS` into a scratch directory; its standard error.
std::string demo_stderr(const std::string &name, const std::string &args) {
  const fs::path dir = fs::path(::testing::TempDir()) / "demo_warnings" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string log = (dir / "stderr.txt").string();
  const std::string command = std::string(GLIDESHADOWS_PATH) + " demo --out " + (dir / "frames").string() +
                              " " + args + " > /dev/null 2> " + log;
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(log);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST(DemoWarnings, EachWarningCountsTheFramesItCameIn) {
  gs::demo::DemoRun run;
  gs::demo::count_warnings(frame_with({"a note", "a note"}, {"no shadow"}), 0, run);
  gs::demo::count_warnings(frame_with({"a note"}, {}), 1, run);
  gs::demo::count_warnings(frame_with({}, {"no shadow"}), 2, run);
  ASSERT_EQ(run.warnings.size(), 2u);
  EXPECT_EQ(run.warnings[0].text, "no shadow");
  EXPECT_EQ(run.warnings[0].frames, 2);
  EXPECT_TRUE(run.warnings[0].error);
  EXPECT_EQ(run.warnings[1].text, "a note");
  EXPECT_EQ(run.warnings[1].frames, 2) << "twice in frame 0 counts once";
  EXPECT_FALSE(run.warnings[1].error);
  EXPECT_EQ(run.frames_missing_shadow, std::vector<int>({0, 2}));
  const std::vector<std::string> lines = gs::demo::warning_summary(run, 3);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].rfind("2 of 3 frames lack a shadow they should show (frames 0, 2", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1], "error in 2 of 3 frames: no shadow");
  EXPECT_EQ(lines[2], "warning in 2 of 3 frames: a note");
}

TEST(DemoCommand, GrowSizeIsTheDefaultAndNoGrowSizeShowsTheRefusal) {
  // 16 frames at 2 a second: the last is the fight at 7.5 s, the demo's frame 90.
  const std::string frames = "--frames 16 --fps 2";
  const std::string grown = demo_stderr("default", frames);
  const std::string plain = demo_stderr("no_grow", frames + " --no-grow-size");
  for (const std::string fighter : {"red fighter", "blue fighter"}) {
    const std::string refused = "light 0 and '" + fighter + "': a shadow texel spans 5.1 screen pixels "
                                "(the largest accepted is 5.0) on 'ring', so the 256-texel shadow is too "
                                "coarse for the screen (size 512 would be accepted)";
    EXPECT_NE(grown.find("warning in 1 of 16 frames: " + refused + "; its shadow is drawn at 512 texels"),
              std::string::npos)
        << grown;
    EXPECT_EQ(grown.find("error in 1 of 16 frames: " + refused), std::string::npos) << grown;
    EXPECT_NE(plain.find("error in 1 of 16 frames: " + refused + "; it casts no shadow from this light"),
              std::string::npos)
        << plain;
  }
  // Frame 15 lacks both shadows without --grow-size, and no shadow with it.
  const std::size_t with = grown.find("frames lack a shadow they should show");
  const std::size_t without = plain.find("frames lack a shadow they should show (frames ");
  ASSERT_NE(with, std::string::npos) << grown;
  ASSERT_NE(without, std::string::npos) << plain;
  const std::string listed = plain.substr(without, plain.find(';', without) - without);
  EXPECT_NE(listed.find(" 15"), std::string::npos) << listed;
  EXPECT_EQ(grown.substr(with, grown.find('\n', with) - with).find(" 15"), std::string::npos) << grown;
}
