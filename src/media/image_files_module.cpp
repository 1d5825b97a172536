// The image files module (libglideshadows_image_files.so): the functions of image_files.h,
// through OpenImageIO. Only this file of src/ includes OpenImageIO. Every function catches what
// OpenImageIO or the standard library throws and reports it as an error.
#include "media/image_files.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <exception>
#include <memory>

namespace gs::media {
namespace {

namespace IBA = OIIO::ImageBufAlgo;

// An ImageBuf over pixels the caller owns (no copy): OpenImageIO reads and draws in place.
OIIO::ImageBuf wrap_rgb(int width, int height, const std::uint8_t *rgb) {
  return OIIO::ImageBuf(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8),
                        const_cast<std::uint8_t *>(rgb));
}

OIIO::ImageBuf wrap_float(const FloatImage &image) {
  return OIIO::ImageBuf(OIIO::ImageSpec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT),
                        const_cast<float *>(image.pixels.data()));
}

bool write_rgb(const std::string &path, const std::string &format, int width, int height,
               const std::uint8_t *rgb, std::string &error) {
  try {
    OIIO::ImageBuf image = wrap_rgb(width, height, rgb);
    if (image.write(path, OIIO::TypeDesc::UINT8, format)) return true;
    error = image.geterror();
  } catch (const std::exception &e) {
    error = e.what();
  }
  return false;
}

bool read(const std::string &path, FloatImage &image, std::string &error) {
  try {
    OIIO::ImageBuf file(path);
    if (!file.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
      error = file.geterror();
      return false;
    }
    const OIIO::ImageSpec &spec = file.spec();
    FloatImage read_image;
    read_image.width = spec.width;
    read_image.height = spec.height;
    read_image.channels = spec.nchannels;
    read_image.alpha_channel = spec.alpha_channel;
    read_image.pixels.resize(std::size_t(spec.width) * spec.height * spec.nchannels);
    file.get_pixels(file.roi(), OIIO::TypeDesc::FLOAT, read_image.pixels.data());
    image = std::move(read_image);
    return true;
  } catch (const std::exception &e) {
    error = e.what();
    return false;
  }
}

bool read_square(const std::string &path, int side, std::vector<float> &rgb, std::string &error) {
  try {
    OIIO::ImageBuf file(path);
    if (!file.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
      error = "cannot read the image (" + file.geterror() + ")";
      return false;
    }
    const OIIO::ImageSpec &spec = file.spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) {
      error = "the image is empty";
      return false;
    }
    const OIIO::ROI square(0, side, 0, side, 0, 1, 0, spec.nchannels);
    const OIIO::ImageBuf resized = IBA::resize(file, "", 0, square);
    if (resized.has_error()) {
      error = "cannot resample the image (" + resized.geterror() + ")";
      return false;
    }
    std::vector<float> pixels(std::size_t(side) * side * spec.nchannels);
    resized.get_pixels(square, OIIO::TypeDesc::FLOAT, pixels.data());
    const int channels = std::min(spec.nchannels, 3);
    rgb.assign(std::size_t(side) * side * 3, 0.0f);
    for (std::size_t i = 0; i < std::size_t(side) * side; ++i) {
      const float *p = &pixels[i * std::size_t(spec.nchannels)];
      for (int c = 0; c < 3; ++c) rgb[3 * i + c] = channels == 3 ? p[c] : p[0];
    }
    return true;
  } catch (const std::exception &e) {
    error = std::string("cannot read the image (") + e.what() + ")";
    return false;
  }
}

Difference difference(const OIIO::ImageBuf &a, const OIIO::ImageBuf &b, float threshold) {
  // r.error is not read: OpenImageIO 2.4 sets it whenever a pixel exceeds the threshold.
  const IBA::CompareResults r = IBA::compare(a, b, threshold, threshold);
  return {r.meanerror, r.maxerror, r.PSNR, static_cast<long>(r.nfail)};
}

Difference compare(const FloatImage &a, const FloatImage &b, float threshold) {
  return difference(wrap_float(a), wrap_float(b), threshold);
}

Difference compare_rgb(const std::uint8_t *a, const std::uint8_t *b, int width, int height,
                       float threshold) {
  return difference(wrap_rgb(width, height, a), wrap_rgb(width, height, b), threshold);
}

OIIO::ImageBuf half_size(const OIIO::ImageBuf &frame) {
  return IBA::resize(frame, "", 0,
                     OIIO::ROI(0, frame.spec().width / 2, 0, frame.spec().height / 2, 0, 1, 0, 3));
}

bool write_contact_sheet(const std::vector<std::string> &frames, const std::string &path,
                         std::string &error) {
  try {
    const std::size_t count = std::min<std::size_t>(frames.size(), 16);
    if (count == 0) return true;
    const int columns = 4;
    const int rows = static_cast<int>((count + columns - 1) / columns);
    OIIO::ImageBuf first(frames[0]);
    if (!first.read()) {
      error = first.geterror();
      return false;
    }
    const int w = first.spec().width / 2, h = first.spec().height / 2;
    OIIO::ImageBuf sheet(OIIO::ImageSpec(w * columns, h * rows, 3, OIIO::TypeDesc::UINT8));
    IBA::zero(sheet);
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t index = i * frames.size() / count;  // spread over the whole run
      OIIO::ImageBuf frame(frames[index]);
      OIIO::ImageBuf small = IBA::resize(frame, "", 0, OIIO::ROI(0, w, 0, h, 0, 1, 0, 3));
      const int x = static_cast<int>(i % columns) * w, y = static_cast<int>(i / columns) * h;
      IBA::paste(sheet, x, y, 0, 0, small);
    }
    if (sheet.write(path)) return true;
    error = sheet.geterror();
  } catch (const std::exception &e) {
    error = e.what();
  }
  return false;
}

bool write_gif(const std::vector<std::string> &frames, const std::string &path, int fps,
               std::string &error) {
  try {
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out || !out->supports("multiimage") || frames.empty()) {
      error = !out ? OIIO::geterror() : frames.empty() ? "no frames" : "not a multi-image format";
      return false;
    }
    std::vector<OIIO::ImageSpec> specs;
    std::vector<OIIO::ImageBuf> images;
    for (const std::string &file : frames) {
      OIIO::ImageBuf frame(file);
      if (!frame.read()) {
        error = frame.geterror();
        return false;
      }
      OIIO::ImageBuf small = half_size(frame);
      OIIO::ImageSpec spec = small.spec();
      spec.attribute("FramesPerSecond", OIIO::TypeRational, std::vector<int>{fps, 1}.data());
      spec.attribute("oiio:Movie", 1);
      specs.push_back(spec);
      images.push_back(std::move(small));
    }
    bool written = out->open(path, static_cast<int>(specs.size()), specs.data());
    for (std::size_t i = 0; written && i < images.size(); ++i) {
      written = (i == 0 || out->open(path, specs[i], OIIO::ImageOutput::AppendSubimage)) &&
                images[i].write(out.get());
    }
    written = written && out->close();
    if (!written) error = out->geterror();
    return written;
  } catch (const std::exception &e) {
    error = e.what();
    return false;
  }
}

// Drawing never fails on a canvas of the right size; OpenImageIO clips what falls outside.
void fill(RgbCanvas &canvas, const float colour[3]) {
  OIIO::ImageBuf image = wrap_rgb(canvas.width, canvas.height, canvas.rgb.data());
  IBA::fill(image, {colour, 3});
}

void draw_box(RgbCanvas &canvas, int x1, int y1, int x2, int y2, const float colour[3]) {
  OIIO::ImageBuf image = wrap_rgb(canvas.width, canvas.height, canvas.rgb.data());
  IBA::render_box(image, x1, y1, x2, y2, {colour, 3}, true);
}

void draw_line(RgbCanvas &canvas, int x1, int y1, int x2, int y2, const float colour[3]) {
  OIIO::ImageBuf image = wrap_rgb(canvas.width, canvas.height, canvas.rgb.data());
  IBA::render_line(image, x1, y1, x2, y2, {colour, 3});
}

void draw_point(RgbCanvas &canvas, int x, int y, const float colour[3]) {
  OIIO::ImageBuf image = wrap_rgb(canvas.width, canvas.height, canvas.rgb.data());
  IBA::render_point(image, x, y, {colour, 3});
}

const ImageFiles kImageFiles = {write_rgb, read, read_square, compare, compare_rgb,
                                write_contact_sheet, write_gif, fill, draw_box, draw_line,
                                draw_point};

}  // namespace
}  // namespace gs::media

extern "C" __attribute__((visibility("default"))) const gs::media::ImageFiles *
glideshadows_image_files() {
  return &gs::media::kImageFiles;
}
