// The image reader module (libglideshadows_image_reader.so): decodes a slide or beam image with
// OpenImageIO and resamples it to a square side, as floats. It is a module of its own so that
// the scene room does not link OpenImageIO (and its ~250 libraries): projected_image_file.cpp
// loads it the first time a scene names an image file. Nothing is thrown across this C entry.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace {

int fail(char *error, unsigned error_size, const std::string &message) {
  std::strncpy(error, message.c_str(), error_size - 1);
  error[error_size - 1] = '\0';
  return 0;
}

}  // namespace

// `rgb` receives side * side RGB triples, row 0 at the top of the image, each channel as the
// file holds it (not clamped); a grey image gives r = g = b. Returns 0 with `error` (no path in
// it: the caller names the file) on failure.
extern "C" __attribute__((visibility("default"))) int glideshadows_read_projected_image(
    const char *path, int side, float *rgb, char *error, unsigned error_size) {
  try {
    OIIO::ImageBuf file(path);
    if (!file.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
      return fail(error, error_size, "cannot read the image (" + file.geterror() + ")");
    }
    const OIIO::ImageSpec &spec = file.spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) {
      return fail(error, error_size, "the image is empty");
    }
    const OIIO::ROI square(0, side, 0, side, 0, 1, 0, spec.nchannels);
    const OIIO::ImageBuf resized = OIIO::ImageBufAlgo::resize(file, "", 0, square);
    if (resized.has_error()) {
      return fail(error, error_size, "cannot resample the image (" + resized.geterror() + ")");
    }
    std::vector<float> pixels(static_cast<std::size_t>(side) * side * spec.nchannels);
    resized.get_pixels(square, OIIO::TypeDesc::FLOAT, pixels.data());
    // Alpha is not used.
    const int channels = std::min(spec.nchannels, 3);
    for (std::size_t i = 0; i < static_cast<std::size_t>(side) * side; ++i) {
      const float *p = &pixels[i * static_cast<std::size_t>(spec.nchannels)];
      for (int c = 0; c < 3; ++c) rgb[3 * i + c] = channels == 3 ? p[c] : p[0];
    }
    return 1;
  } catch (const std::exception &e) {
    return fail(error, error_size, std::string("cannot read the image (") + e.what() + ")");
  }
}
