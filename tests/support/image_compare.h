// Image tests against reference_images/: compare a PNG with its golden copy through
// OpenImageIO, with a tolerance stated by each test; on failure write the actual image and a
// magnified difference into the build tree. GLIDESHADOWS_REGENERATE=1 rewrites the golden copy
// instead (only through the regenerate_reference_images target, deliberately).
#pragma once

#include <gtest/gtest.h>

#include <string>

struct ImageTolerance {
  float channel;          // a pixel fails when any channel differs by more than this (0..1)
  double failed_fraction; // the image fails when more than this fraction of pixels fail
};

// `actual_png` is compared with reference_images/<name>.png.
::testing::AssertionResult matches_reference(const std::string &name,
                                             const std::string &actual_png,
                                             const ImageTolerance &tolerance);

// A path in the build tree for a test's output image.
std::string output_path(const std::string &file_name);
// output_path of `name` followed by the running test's name: a place of its own for each test,
// since ctest runs the tests of one program at the same time.
std::string test_output_path(const std::string &name);
