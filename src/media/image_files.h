// Every use of OpenImageIO in src/: reading, writing, comparing and drawing on images. The
// functions live in the image files module (libglideshadows_image_files.so, built from
// image_files_module.cpp), which a program loads the first time it asks for them. OpenImageIO
// brings some 260 libraries, all bound at load time, and relocating them took about 0.4 s of
// CPU at every start of a program that linked it; a program that reads or writes no image
// file no longer pays that. Both sides are built by the same compiler in the same build, so the
// table below passes C++ types; nothing is thrown out of the module.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace gs::media {

// An image's pixels as floats (8-bit files read as 0..1), rows from the top, channels
// interleaved; alpha_channel is the index of alpha, or -1.
struct FloatImage {
  int width = 0, height = 0, channels = 0, alpha_channel = -1;
  std::vector<float> pixels;
};

// An 8-bit RGB image to draw on, rows from the top (x right, y down, in pixels).
struct RgbCanvas {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

// OpenImageIO's comparison of two images of the same size: mean and largest channel
// difference (0..1), PSNR in dB (+inf when identical), pixels with a channel over the threshold.
struct Difference {
  double mean = 0.0, max = 0.0, psnr = 0.0;
  long over_threshold = 0;
};

// The module's functions. A failing call returns false and says why in `error` (OpenImageIO's
// message; the caller adds the file's name where the message lacks it).
struct ImageFiles {
  // `format` names the file format ("png"), or is empty to take it from the path's extension.
  bool (*write_rgb)(const std::string &path, const std::string &format, int width, int height,
                    const std::uint8_t *rgb, std::string &error);
  bool (*read)(const std::string &path, FloatImage &image, std::string &error);
  // Reads an image and resamples it to side x side RGB (a grey image gives r = g = b; alpha
  // is dropped), channel values as the file holds them.
  bool (*read_square)(const std::string &path, int side, std::vector<float> &rgb,
                      std::string &error);
  Difference (*compare)(const FloatImage &a, const FloatImage &b, float threshold);
  // The same for two 8-bit RGB images in memory.
  Difference (*compare_rgb)(const std::uint8_t *a, const std::uint8_t *b, int width, int height,
                            float threshold);
  // Up to 16 frames spread over the sequence at half size, four to a row.
  bool (*write_contact_sheet)(const std::vector<std::string> &frames, const std::string &path,
                              std::string &error);
  // Every frame at half size, `fps` frames a second.
  bool (*write_gif)(const std::vector<std::string> &frames, const std::string &path, int fps,
                    std::string &error);
  // Drawing, colours as 0..1 RGB: the whole canvas, a filled box (corners included), a line
  // and a single pixel; what falls outside the canvas is not drawn.
  void (*fill)(RgbCanvas &canvas, const float colour[3]);
  void (*draw_box)(RgbCanvas &canvas, int x1, int y1, int x2, int y2, const float colour[3]);
  void (*draw_line)(RgbCanvas &canvas, int x1, int y1, int x2, int y2, const float colour[3]);
  void (*draw_point)(RgbCanvas &canvas, int x, int y, const float colour[3]);
};

// The module's table, loaded on the first call from the path this build gave it
// ($GLIDESHADOWS_IMAGE_FILES overrides it); null with `error` naming the module and why.
const ImageFiles *image_files(std::string &error);

}  // namespace gs::media
