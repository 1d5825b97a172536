// Reference-image comparison through OpenImageIO (ImageBufAlgo::compare, like idiff).
#include "image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace fs = std::filesystem;

std::string output_path(const std::string &file_name) {
  fs::create_directories(GLIDESHADOWS_FAILURE_DIR);
  return (fs::path(GLIDESHADOWS_FAILURE_DIR) / file_name).string();
}

std::string test_output_path(const std::string &name) {
  const ::testing::TestInfo *test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string test_name = test != nullptr ? std::string(test->test_suite_name()) + "." + test->name() : "";
  std::replace(test_name.begin(), test_name.end(), '/', '_');  // parameterised tests' names
  return output_path(name + "_" + test_name);
}

::testing::AssertionResult matches_reference(const std::string &name,
                                             const std::string &actual_png,
                                             const ImageTolerance &tolerance) {
  const fs::path reference = fs::path(GLIDESHADOWS_REFERENCE_DIR) / (name + ".png");
  const char *regenerate = std::getenv("GLIDESHADOWS_REGENERATE");
  if (regenerate != nullptr && std::string(regenerate) == "1") {
    fs::copy_file(actual_png, reference, fs::copy_options::overwrite_existing);
    return ::testing::AssertionSuccess() << "regenerated " << reference;
  }
  if (!fs::exists(reference)) {
    return ::testing::AssertionFailure()
           << reference << " is missing; regenerate it deliberately with "
           << "`cmake --build build --target regenerate_reference_images`";
  }
  OIIO::ImageBuf actual(actual_png), golden(reference.string());
  if (!actual.read() || !golden.read()) {
    return ::testing::AssertionFailure() << "cannot read " << actual_png << " or " << reference;
  }
  if (actual.spec().width != golden.spec().width || actual.spec().height != golden.spec().height) {
    const std::string kept = output_path(name + ".actual.png");
    fs::copy_file(actual_png, kept, fs::copy_options::overwrite_existing);
    return ::testing::AssertionFailure() << name << ": size " << actual.spec().width << "x"
                                         << actual.spec().height << " differs from the reference's "
                                         << golden.spec().width << "x" << golden.spec().height
                                         << " (no difference image). Actual: " << kept;
  }
  const auto result = OIIO::ImageBufAlgo::compare(actual, golden, tolerance.channel, tolerance.channel);
  const double pixels = static_cast<double>(actual.spec().width) * actual.spec().height;
  const double failed = static_cast<double>(result.nfail) / pixels;
  if (failed <= tolerance.failed_fraction) return ::testing::AssertionSuccess();

  const std::string kept = output_path(name + ".actual.png");
  const std::string diff_path = output_path(name + ".diff.png");
  fs::copy_file(actual_png, kept, fs::copy_options::overwrite_existing);
  OIIO::ImageBuf diff = OIIO::ImageBufAlgo::absdiff(actual, golden);
  diff = OIIO::ImageBufAlgo::mul(diff, 8.0f);
  diff.write(diff_path);
  std::ostringstream s;
  s << name << ": " << result.nfail << " pixels (" << 100.0 * failed << "%) differ by more than "
    << tolerance.channel << " (allowed " << 100.0 * tolerance.failed_fraction << "%); mean error "
    << result.meanerror << ", max " << result.maxerror << ", PSNR " << result.PSNR
    << ". Actual: " << kept << ", difference x8: " << diff_path;
  return ::testing::AssertionFailure() << s.str();
}
