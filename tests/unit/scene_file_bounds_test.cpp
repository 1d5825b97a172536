// Bounded parsing of scene files: any file under the 16 MiB size limit is refused or loaded in
// bounded time and memory (nesting and the count of values are budgeted while the text is read),
// each load measured in a child process.
#include "scene/scene.h"
#include "scene_file_test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using scene_file_test::kSourceDir;
using scene_file_test::load_or_fail;
using scene_file_test::write_scene;

// Any file under the 16 MiB size limit parses in bounded time and memory: nesting and the count
// of values are budgeted while the text is read, before anything is kept. Each load runs in a
// child process, whose peak resident memory the parent reads (ru_maxrss of its children).
namespace {

struct BoundedLoad {
  bool loaded = true;
  std::string error;
  double seconds = 0.0;
  long peak_kib = 0;  // what the load added to the child's resident memory at its peak
};

long resident_kib() {
  long pages = 0, resident = 0;
  std::ifstream("/proc/self/statm") >> pages >> resident;
  return resident * (::sysconf(_SC_PAGESIZE) / 1024);
}

BoundedLoad load_in_child(const std::string &path) {
  BoundedLoad result;
  int pipe_fds[2];
  EXPECT_EQ(::pipe(pipe_fds), 0);
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(pipe_fds[0]);
    const long before = resident_kib();
    gs::Scene scene;
    std::string error;
    const bool ok = gs::load_scene(path, scene, error);
    const std::string message = std::to_string(before) + " " + (ok ? "1" : "0") + error;
    const ssize_t written = ::write(pipe_fds[1], message.data(), message.size());
    ::_exit(written == static_cast<ssize_t>(message.size()) ? 0 : 1);
  }
  ::close(pipe_fds[1]);
  std::string message;
  char buffer[512];
  for (ssize_t got; (got = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0;) message.append(buffer, got);
  ::close(pipe_fds[0]);
  int status = 0;
  struct rusage usage {};
  EXPECT_EQ(::wait4(child, &status, 0, &usage), child);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "the child died loading " << path;
  const std::size_t space = message.find(' ');
  if (space == std::string::npos || space + 1 >= message.size()) {
    ADD_FAILURE() << "no answer from the child: " << message;
    return result;
  }
  result.peak_kib = usage.ru_maxrss - std::stol(message.substr(0, space));
  result.loaded = message[space + 1] == '1';
  result.error = message.substr(space + 2);
  return result;
}

// Just under the 16 MiB limit.
constexpr std::size_t kAlmostLimit = (16u << 20) - 16;

}  // namespace

// Writes a scene file and frees its text before the child is forked, so the child's peak is
// the loader's and the test process's own baseline.
std::string write_big_scene(const std::string &name, std::string text) {
  const std::string path = write_scene(name, text);
  std::string().swap(text);
  return path;
}

// Bounded work is shown by the refusal naming a parse-time limit (depth, value count) and by the
// child's peak memory; the time is printed for the reader, never asserted (a loaded machine).
TEST(SceneFileBounds, DeepNestingIsRefusedWhileParsing) {
  std::string text(kAlmostLimit / 2, '[');
  text += std::string(kAlmostLimit / 2, ']');
  const BoundedLoad load = load_in_child(write_big_scene("deep.json", std::move(text)));
  EXPECT_FALSE(load.loaded);
  EXPECT_NE(load.error.find("nested more than 32 deep"), std::string::npos) << load.error;
  EXPECT_LT(load.peak_kib, 100 * 1024) << "KiB";
  std::cout << "16 MiB of nested arrays: " << load.seconds << " s, peak " << load.peak_kib / 1024
            << " MiB\n";
}

TEST(SceneFileBounds, LongArraysAreRefusedWhileParsing) {
  std::string text = "{\"description\": [";
  while (text.size() + 3 < kAlmostLimit) text += "0,";
  text += "0]}";
  const BoundedLoad load = load_in_child(write_big_scene("long.json", std::move(text)));
  EXPECT_FALSE(load.loaded);
  EXPECT_NE(load.error.find("more than 100000 JSON values"), std::string::npos) << load.error;
  EXPECT_LT(load.peak_kib, 100 * 1024) << "KiB";
  std::cout << "16 MiB of one array: " << load.seconds << " s, peak " << load.peak_kib / 1024
            << " MiB\n";
}

TEST(SceneFileBounds, ManyKeysAreRefusedWhileParsing) {
  std::string text = "{\"objects\": [{";
  for (int i = 0; text.size() + 32 < kAlmostLimit; ++i) text += "\"k" + std::to_string(i) + "\": 0,";
  text += "\"last\": 0}]}";
  const BoundedLoad load = load_in_child(write_big_scene("keys.json", std::move(text)));
  EXPECT_FALSE(load.loaded);
  EXPECT_NE(load.error.find("JSON values"), std::string::npos) << load.error;
  EXPECT_LT(load.peak_kib, 100 * 1024) << "KiB";
}

TEST(SceneFileBounds, ALongStringStaysWithinTheMemoryBound) {
  // One value, almost the whole file: within the budget, and a string is kept whole, so the
  // file is read once and the string once: about 2 x 16 MiB.
  std::string text = "{\"description\": \"" + std::string(kAlmostLimit - 160, 'x') +
                     "\", \"camera\": {\"position\": [0, 2, 5], \"target\": [0, 0, 0]},"
                     " \"objects\": [{\"mesh\": {\"shape\": \"box\"}}]}";
  const BoundedLoad load = load_in_child(write_big_scene("string.json", std::move(text)));
  EXPECT_TRUE(load.loaded) << load.error;
  EXPECT_LT(load.peak_kib, 100 * 1024) << "KiB";
}

TEST(SceneFileBounds, EverySampleSceneIsWellWithinTheBudget) {
  for (const auto &entry : std::filesystem::directory_iterator(kSourceDir + "/scenes")) {
    if (entry.path().extension() != ".json") continue;
    load_or_fail(entry.path().string());
  }
}
