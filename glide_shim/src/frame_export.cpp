// Frame export through OpenImageIO. Gamma lives only here: the frame buffer and LFB reads stay
// pre-gamma, as on the hardware, where the CLUT sits between frame buffer and DAC.
#include "frame_export.h"

#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>
#include <memory>

namespace glide_shim {
namespace {

std::array<int, 33> gamma_clut(float gamma) {
  std::array<int, 33> clut{};
  for (int i = 0; i < 32; ++i) {
    const double x = (i * 8) / 255.0;
    clut[static_cast<std::size_t>(i)] =
        static_cast<int>(std::lround(255.0 * std::pow(x, 1.0 / gamma)));
  }
  clut[32] = 255;
  return clut;
}

std::uint8_t through_clut(const std::array<int, 33> &clut, unsigned x) {  // x: 8-bit channel
  const unsigned entry = x >> 3, weight = x & 7;
  return static_cast<std::uint8_t>(
      (static_cast<unsigned>(clut[entry]) * (8 - weight) +
       static_cast<unsigned>(clut[entry + 1]) * weight) >> 3);
}

}  // namespace

std::vector<std::uint8_t> scan_out(const std::vector<std::uint16_t> &pixels, float gamma) {
  const std::array<int, 33> clut = gamma_clut(gamma);
  std::vector<std::uint8_t> rgb(pixels.size() * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const unsigned p = pixels[i];
    const unsigned r5 = p >> 11, g6 = (p >> 5) & 0x3F, b5 = p & 0x1F;
    rgb[3 * i + 0] = through_clut(clut, (r5 << 3) | (r5 >> 2));
    rgb[3 * i + 1] = through_clut(clut, (g6 << 2) | (g6 >> 4));
    rgb[3 * i + 2] = through_clut(clut, (b5 << 3) | (b5 >> 2));
  }
  return rgb;
}

bool write_png(const std::string &path, int width, int height,
               const std::vector<std::uint8_t> &rgb, std::string &error) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  if (!out) {
    error = "cannot write '" + path + "': " + OIIO::geterror();
    return false;
  }
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  // Level 6 keeps files small without making a frame dump the slowest part of a frame.
  spec.attribute("png:compressionLevel", 6);
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::UINT8, rgb.data()) ||
      !out->close()) {
    error = "cannot write '" + path + "': " + out->geterror();
    return false;
  }
  return true;
}

}  // namespace glide_shim
