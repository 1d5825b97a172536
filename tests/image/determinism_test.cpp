// Determinism: the same command writes the same bytes, run after run and whatever number of
// threads llvmpipe rasterises with (LP_NUM_THREADS=0 draws on the calling thread; 1, 2 and 4
// split the screen into tiles across threads). Each command runs once per thread count, and once
// more with the first count, and every output file is compared byte for byte with the first run.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kThreadCounts = {"0", "1", "2", "4", "0"};

std::string read_bytes(const fs::path &path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs `arguments` (with OUT standing for a fresh output directory) once per thread count and
// checks that every run wrote exactly the files of the first, byte for byte.
void expect_same_bytes_across_runs(const std::string &name, const std::string &arguments) {
  const fs::path root = fs::path(::testing::TempDir()) / ("determinism_" + name);
  fs::remove_all(root);
  std::vector<fs::path> outputs;
  for (std::size_t run = 0; run < kThreadCounts.size(); ++run) {
    const fs::path out = root / ("run" + std::to_string(run) + "_threads" + kThreadCounts[run]);
    fs::create_directories(out);
    std::string expanded = arguments;
    for (std::size_t at = expanded.find("OUT"); at != std::string::npos; at = expanded.find("OUT"))
      expanded.replace(at, 3, out.string());
    const std::string command = "LP_NUM_THREADS=" + kThreadCounts[run] + " " + GLIDESHADOWS_PATH +
                                " " + expanded + " > " + (out / "stdout.txt").string();
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    fs::remove(out / "stdout.txt");  // timings differ from run to run; only images are compared
    outputs.push_back(out);
  }
  std::vector<fs::path> files;
  for (const auto &entry : fs::directory_iterator(outputs.front())) files.push_back(entry.path().filename());
  ASSERT_FALSE(files.empty()) << "the command wrote nothing";
  for (std::size_t run = 1; run < outputs.size(); ++run) {
    std::size_t count = 0;
    for (const auto &entry : fs::directory_iterator(outputs[run])) {
      (void)entry;
      ++count;
    }
    EXPECT_EQ(count, files.size()) << outputs[run];
    for (const fs::path &file : files) {
      EXPECT_TRUE(read_bytes(outputs[run] / file) == read_bytes(outputs.front() / file))
          << file << " differs between LP_NUM_THREADS=" << kThreadCounts.front() << " and "
          << kThreadCounts[run] << " (run " << run << ")";
    }
  }
}

TEST(Determinism, RenderWritesTheSameImageAndMaskForEveryThreadCount) {
  expect_same_bytes_across_runs(
      "render", std::string("render ") + SCENES_DIR + "/box_on_plane.json --out OUT/image.png --mask OUT/mask.png");
}

TEST(Determinism, EveryOtherTechniqueRendersTheSameBytesForEveryThreadCount) {
  for (const std::string technique : {"planar", "depth-map", "stencil-volume"}) {
    SCOPED_TRACE(technique);
    expect_same_bytes_across_runs("render_" + technique,
                                  std::string("render ") + SCENES_DIR +
                                      "/fighters.json --technique " + technique +
                                      " --out OUT/image.png --mask OUT/mask.png");
  }
}

TEST(Determinism, DemoWritesTheSameFramesForEveryThreadCount) {
  expect_same_bytes_across_runs("demo", "demo --frames 2 --size 320x240 --out OUT");
}

TEST(Determinism, TruthWritesTheSameMaskAndImageEveryRun) {
  expect_same_bytes_across_runs(
      "truth", std::string("truth ") + SCENES_DIR + "/fighters.json --mask OUT/mask.png --image OUT/image.png");
}

}  // namespace
