// What the scene-file tests share: the source tree's path, a load that must succeed, and a
// scene file written into the test's scratch directory.
#pragma once

#include "scene/scene.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#ifndef GLIDESHADOWS_SOURCE_DIR
#define GLIDESHADOWS_SOURCE_DIR ".."
#endif

namespace scene_file_test {

inline const std::string kSourceDir = GLIDESHADOWS_SOURCE_DIR;

inline gs::Scene load_or_fail(const std::string &path) {
  gs::Scene scene;
  std::string error;
  EXPECT_TRUE(gs::load_scene(path, scene, error)) << error;
  return scene;
}

// Writes `contents` as a scene file in the test's scratch directory and returns its path.
inline std::string write_scene(const std::string &name, const std::string &contents) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << contents;
  return path;
}

}  // namespace scene_file_test
