// Frame export. Gamma lives only here: the frame buffer and LFB reads stay pre-gamma, as on the
// hardware, where the CLUT sits between frame buffer and DAC. The PNG itself is written by the
// png_writer module (OpenImageIO), loaded on first use.
#include "frame_export.h"

#include <dlfcn.h>

#include <filesystem>

#include <array>
#include <cmath>

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
  // The writer lives in its own module, next to this library, so that programs which never
  // export a frame do not load OpenImageIO (and its ~250 dependent libraries) at start-up.
  using Writer = int (*)(const char *, int, int, const unsigned char *, char *, unsigned);
  static Writer writer = [] {
    Dl_info self{};
    if (dladdr(reinterpret_cast<void *>(&scan_out), &self) == 0 || self.dli_fname == nullptr) {
      return Writer{nullptr};
    }
    const std::string directory = std::filesystem::path(self.dli_fname).parent_path().string();
    void *module = dlopen((directory + "/libglide2x_png.so").c_str(), RTLD_NOW | RTLD_LOCAL);
    return module == nullptr ? Writer{nullptr}
                             : reinterpret_cast<Writer>(dlsym(module, "glideshim_write_png"));
  }();
  if (writer == nullptr) {
    error = "cannot load libglide2x_png.so from the directory of libglide2x (it writes the PNGs)";
    return false;
  }
  char message[512] = {};
  if (writer(path.c_str(), width, height, rgb.data(), message, sizeof message) == 0) {
    error = message;
    return false;
  }
  return true;
}

}  // namespace glide_shim
