// The command line's exit status (docs/cli.md): 0 for success and --help, 1 for bad input or a
// run that failed (a scene file that is missing or broken, a frame missing shadows its technique
// could not cast), 2 for a command line the tool refuses (CLI11's own codes, 105 and 106, never
// reach the shell).
#include "tool_run.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#ifndef GLIDESHADOWS_PATH
#error "GLIDESHADOWS_PATH must name the glideshadows executable"
#endif

namespace {

namespace fs = std::filesystem;

ToolRun run_tool(const std::string &arguments) { return ::run_tool(GLIDESHADOWS_PATH, arguments); }

std::string scratch(const std::string &name) {
  const fs::path path = fs::path(::testing::TempDir()) / ("cli_exit_" + name);
  fs::remove_all(path);
  fs::create_directories(path);
  return path.string();
}

const std::string kHardCases = GLIDESHADOWS_HARD_CASES_DIR;

TEST(CommandLineExitCodes, HelpIsASuccess) {
  EXPECT_EQ(run_tool("--help").exit_code, 0);
  EXPECT_EQ(run_tool("render --help").exit_code, 0);
}

TEST(CommandLineExitCodes, UsageErrorsExitTwo) {
  const std::string out = scratch("usage");
  for (const std::string &arguments :
       {std::string(""), std::string("no-such-command"), std::string("render"),
        "render " + kHardCases + "/box_over_floor.json --technique no-such-technique",
        "render " + kHardCases + "/box_over_floor.json --shadow-size 100",
        "render " + kHardCases + "/box_over_floor.json --no-such-option",
        // CLI11's Range lets NaN through; render once ran with glPolygonOffset(NaN) and exited 0.
        "render " + kHardCases + "/box_over_floor.json --bias-slope nan",
        "render " + kHardCases + "/box_over_floor.json --bias-units nan",
        "render " + kHardCases + "/box_over_floor.json --bias-receiver nan",
        "render " + kHardCases + "/box_over_floor.json --bias-bound nan",
        "render " + kHardCases + "/box_over_floor.json --bias-bound -1",
        std::string("bench --quick --budget nan"),
        std::string("truth --mask ") + out + "/m.png", "demo --frames 0 --out " + out,
        "render " + kHardCases + "/box_over_floor.json --shadow-size 8192",
        // The projected techniques draw at most 512 texels; larger sizes are the depth map's.
        "render " + kHardCases + "/box_over_floor.json --technique projected-chroma --shadow-size 1024",
        "demo --shadow-size 4096 --out " + out}) {
    const ToolRun run = run_tool(arguments);
    EXPECT_EQ(run.exit_code, 2) << "'" << arguments << "': " << run.output;
  }
}

TEST(CommandLineExitCodes, MissingOrBrokenInputExitsOne) {
  const std::string out = scratch("input");
  const std::string missing = out + "/missing.json";
  for (const std::string &arguments :
       {"render " + missing + " --out " + out + "/r.png", "truth " + missing + " --mask " + out + "/m.png",
        "bench " + missing, "compare " + out + "/a.png " + out + "/b.png"}) {
    const ToolRun run = run_tool(arguments);
    EXPECT_EQ(run.exit_code, 1) << "'" << arguments << "': " << run.output;
  }
  const ToolRun run = run_tool("render " + missing + " --out " + out + "/r.png");
  EXPECT_NE(run.output.find(missing + ": cannot open"), std::string::npos) << run.output;
  std::ofstream(out + "/broken.json") << "{\"objects\": [";
  EXPECT_EQ(run_tool("render " + out + "/broken.json --out " + out + "/r.png").exit_code, 1);
}

// The images are PNG whatever their names say: a path with no extension, or another format's, is
// not a reason to fail (a script's `--out /dev/null` once exited 1: no writer for the name).
TEST(CommandLineExitCodes, RenderWritesPngWhateverTheName) {
  const std::string out = scratch("png_names");
  const std::string scene = kHardCases + "/box_over_floor.json";
  const ToolRun discarded = run_tool("render " + scene + " --out /dev/null --mask /dev/null");
  EXPECT_EQ(discarded.exit_code, 0) << discarded.output;
  for (const std::string &name : {std::string("frame"), std::string("frame.jpg")}) {
    const ToolRun run = run_tool("render " + scene + " --out " + out + "/" + name);
    ASSERT_EQ(run.exit_code, 0) << name << ": " << run.output;
    std::ifstream written(out + "/" + name, std::ios::binary);
    std::string signature(8, '\0');
    written.read(signature.data(), 8);
    EXPECT_EQ(signature, std::string("\x89PNG\r\n\x1a\n", 8)) << name;
  }
}

// A depth-map refusal may name a size above 512 ("size 1024 would be accepted"): render takes
// it for the depth map, and refuses it for the projected techniques, saying what they draw.
TEST(CommandLineExitCodes, ShadowSizesAbove512AreTheDepthMaps) {
  const std::string scene = kHardCases + "/box_over_floor.json";
  const ToolRun depth_map =
      run_tool("render " + scene + " --technique depth-map --shadow-size 1024 --out /dev/null");
  EXPECT_EQ(depth_map.exit_code, 0) << depth_map.output;
  const ToolRun projected =
      run_tool("render " + scene + " --technique projected --shadow-size 2048 --out /dev/null");
  EXPECT_EQ(projected.exit_code, 2) << projected.output;
  EXPECT_NE(projected.output.find("the projected technique draws at most 512 texels"),
            std::string::npos)
      << projected.output;
}

// A frame the technique cannot shadow fully is an error unless the user allows missing shadows.
TEST(CommandLineExitCodes, RenderMissingAShadowExitsOneUnlessAllowed) {
  const std::string out = scratch("missing_shadow");
  const std::string scene = kHardCases + "/light_inside_tube.json";
  const ToolRun refused = run_tool("render " + scene + " --out " + out + "/r.png");
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("error: light 0 and 'tube'"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("--allow-missing-shadows"), std::string::npos) << refused.output;
  const ToolRun allowed =
      run_tool("render " + scene + " --allow-missing-shadows --out " + out + "/r.png");
  EXPECT_EQ(allowed.exit_code, 0) << allowed.output;
  EXPECT_NE(allowed.output.find("warning: light 0 and 'tube'"), std::string::npos)
      << allowed.output;
  const ToolRun planar = run_tool("render " + scene + " --technique planar --out " + out + "/r.png");
  EXPECT_EQ(planar.exit_code, 0) << planar.output;
}

// Slides and beams from image files are decoded by the image files module, loaded when first
// needed: a module that cannot be loaded is a failed load naming the image and the module.
TEST(CommandLineExitCodes, MissingImageFilesModuleExitsOneNamingIt) {
  const std::string out = scratch("image_files");
  std::ofstream(out + "/beam.png") << "not read: the module is missing";
  std::ofstream(out + "/scene.json")
      << R"({"camera": {"position": [0, 2, 5], "target": [0, 0, 0]},
             "lights": [{"position": [0, 5, 0], "target": [0, 0, 0], "beam": "beam.png"}],
             "objects": [{"mesh": {"shape": "box"}}]})";
  const std::string module = out + "/no_such_module.so";
  const ToolRun run = ::run_tool("GLIDESHADOWS_IMAGE_FILES=" + module + " " GLIDESHADOWS_PATH,
                                 "render " + out + "/scene.json --out " + out + "/r.png");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find(out + "/beam.png: cannot load the image files module " + module),
            std::string::npos)
      << run.output;
}

}  // namespace
