// `glideshadows compare` (docs/cli.md): it says which comparison it made, masks when both files
// are black and white (as `render --mask` and `truth` write them) or with --as masks, colour
// images otherwise, and prints the mask statistics for masks only.
#include "tool_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#ifndef GLIDESHADOWS_PATH
#error "GLIDESHADOWS_PATH must name the glideshadows executable"
#endif

namespace {

namespace fs = std::filesystem;

ToolRun run_tool(const std::string &arguments) { return ::run_tool(GLIDESHADOWS_PATH, arguments); }

bool contains(const std::string &text, const std::string &part) {
  return text.find(part) != std::string::npos;
}

const char kMaskStatistics[] = "as masks (B the truth):";

class CompareCommand : public ::testing::Test {
 protected:
  // One scene rendered by two techniques (colour images), its mask and the true mask.
  static void SetUpTestSuite() {
    // ctest runs each test as its own process, in parallel: one directory per process.
    dir_ = (fs::path(::testing::TempDir()) / ("cli_compare_" + std::to_string(::getpid()))).string();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const std::string scene = std::string(GLIDESHADOWS_HARD_CASES_DIR) + "/box_over_floor.json";
    for (const std::string &arguments :
         {"render " + scene + " --out " + file("projected.png") + " --mask " + file("mask.png"),
          "render " + scene + " --technique planar --out " + file("planar.png"),
          "truth " + scene + " --mask " + file("truth.png")}) {
      const ToolRun run = run_tool(arguments);
      ASSERT_EQ(run.exit_code, 0) << arguments << ": " << run.output;
    }
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string file(const std::string &name) { return dir_ + "/" + name; }
  static std::string dir_;
};

std::string CompareCommand::dir_;

TEST_F(CompareCommand, TwoMasksAreComparedAsMasks) {
  const ToolRun run = run_tool("compare " + file("mask.png") + " " + file("truth.png"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.rfind("comparison: masks, B the truth (both are black and white)\n", 0), 0u)
      << run.output;
  EXPECT_TRUE(contains(run.output, "PSNR")) << run.output;
  EXPECT_TRUE(contains(run.output, kMaskStatistics)) << run.output;
}

TEST_F(CompareCommand, TwoColourFramesGetNoMaskStatistics) {
  const ToolRun run = run_tool("compare " + file("projected.png") + " " + file("planar.png"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.rfind("comparison: colour images (neither is black and white)\n", 0), 0u)
      << run.output;
  EXPECT_TRUE(contains(run.output, "PSNR")) << run.output;
  EXPECT_FALSE(contains(run.output, kMaskStatistics)) << run.output;
}

TEST_F(CompareCommand, AColourFrameAgainstAMaskSaysWhichIsNotAMask) {
  const ToolRun a_colour = run_tool("compare " + file("projected.png") + " " + file("truth.png"));
  ASSERT_EQ(a_colour.exit_code, 0) << a_colour.output;
  EXPECT_EQ(a_colour.output.rfind("comparison: colour images (A is not black and white)\n", 0), 0u)
      << a_colour.output;
  EXPECT_FALSE(contains(a_colour.output, kMaskStatistics)) << a_colour.output;

  const ToolRun b_colour = run_tool("compare " + file("truth.png") + " " + file("projected.png"));
  EXPECT_EQ(b_colour.output.rfind("comparison: colour images (B is not black and white)\n", 0), 0u)
      << b_colour.output;
  EXPECT_FALSE(contains(b_colour.output, kMaskStatistics)) << b_colour.output;
}

TEST_F(CompareCommand, TheKindCanBeChosen) {
  const ToolRun masks =
      run_tool("compare --as masks " + file("projected.png") + " " + file("planar.png"));
  ASSERT_EQ(masks.exit_code, 0) << masks.output;
  EXPECT_EQ(masks.output.rfind("comparison: masks, B the truth (--as masks: ", 0), 0u) << masks.output;
  EXPECT_TRUE(contains(masks.output, kMaskStatistics)) << masks.output;

  const ToolRun images = run_tool("compare --as images " + file("mask.png") + " " + file("truth.png"));
  ASSERT_EQ(images.exit_code, 0) << images.output;
  EXPECT_EQ(images.output.rfind("comparison: colour images (--as images)\n", 0), 0u) << images.output;
  EXPECT_FALSE(contains(images.output, kMaskStatistics)) << images.output;

  EXPECT_EQ(run_tool("compare --as shapes " + file("mask.png") + " " + file("truth.png")).exit_code, 2);
}

TEST_F(CompareCommand, HelpSaysHowItDecides) {
  const ToolRun run = run_tool("compare --help");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(contains(run.output, "--as")) << run.output;
  EXPECT_TRUE(contains(run.output, "Masks: both files black and white")) << run.output;
}

}  // namespace
