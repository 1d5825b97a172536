// Reading a projected image: the file checks here, the decoding in the image reader module
// (image_reader_module.cpp, OpenImageIO), loaded on first use from the path the build gave it
// ($GLIDESHADOWS_IMAGE_READER overrides it).
#include "scene/projected_image_file.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

#include <glm/glm.hpp>

namespace gs {
namespace {

constexpr std::uintmax_t kMaxImageFileBytes = 64u << 20;  // far above any slide or beam map

using ImageReader = int (*)(const char *path, int side, float *rgb, char *error,
                            unsigned error_size);

// The module's path: $GLIDESHADOWS_IMAGE_READER when set (a build moved elsewhere), else the
// path it has in this build.
std::string image_reader_path() {
  const char *chosen = std::getenv("GLIDESHADOWS_IMAGE_READER");
  return chosen != nullptr && *chosen != '\0' ? chosen : GLIDESHADOWS_IMAGE_READER_MODULE;
}

// The module's entry, or null with `error` saying why (dlopen's own message names the file).
ImageReader image_reader(std::string &error) {
  static std::string load_error;
  static const ImageReader reader = [] {
    const std::string path = image_reader_path();
    void *module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (module == nullptr) {
      const char *why = dlerror();
      load_error = "cannot load the image reader module " + path + " (" +
                   (why != nullptr ? why : "no reason given") + ")";
      return ImageReader{nullptr};
    }
    auto entry = reinterpret_cast<ImageReader>(dlsym(module, "glideshadows_read_projected_image"));
    if (entry == nullptr) {
      load_error = "the image reader module " + path + " has no glideshadows_read_projected_image";
    }
    return entry;
  }();
  if (reader == nullptr) error = load_error;
  return reader;
}

}  // namespace

bool load_projected_image(const std::string &path, int side, ProjectedImage &image,
                          std::string &error) {
  // Only a regular file of a sane size is handed to the decoder: a FIFO or a device would block
  // or never end.
  std::error_code code;
  if (!std::filesystem::is_regular_file(path, code)) {
    error = path + ": cannot read the image (not a regular file)";
    return false;
  }
  const std::uintmax_t bytes = std::filesystem::file_size(path, code);
  if (code) {
    error = path + ": cannot read the image (" + code.message() + ")";
    return false;
  }
  if (bytes > kMaxImageFileBytes) {
    error = path + ": cannot read the image (larger than 64 MiB)";
    return false;
  }
  std::string module_error;
  const ImageReader reader = image_reader(module_error);
  if (reader == nullptr) {
    error = path + ": " + module_error;
    return false;
  }
  std::vector<float> rgb(static_cast<std::size_t>(side) * side * 3);
  char message[512] = {};
  if (reader(path.c_str(), side, rgb.data(), message, sizeof message) == 0) {
    error = path + ": " + message;
    return false;
  }
  ProjectedImage loaded;
  loaded.side = side;
  loaded.rgb.resize(static_cast<std::size_t>(side) * side);
  for (std::size_t i = 0; i < loaded.rgb.size(); ++i) {
    loaded.rgb[i] = glm::clamp(glm::vec3(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]), 0.0f, 1.0f);
  }
  image = std::move(loaded);
  return true;
}

}  // namespace gs
