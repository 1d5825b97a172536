// Reading a projected image: the file checks here, the decoding and resampling in the image
// files module (media/image_files.h, OpenImageIO), which is loaded on first use.
#include "scene/projected_image_file.h"

#include "media/image_files.h"

#include <filesystem>
#include <system_error>
#include <vector>

#include <glm/glm.hpp>

namespace gs {
namespace {

constexpr std::uintmax_t kMaxImageFileBytes = 64u << 20;  // far above any slide or beam map

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
  std::string why;
  const media::ImageFiles *files = media::image_files(why);
  std::vector<float> rgb;
  if (files == nullptr || !files->read_square(path, side, rgb, why)) {
    error = path + ": " + why;
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
