// The media writers of media.h: this file decides the sizes, the frame names and which files a
// run owns; the image files module (image_files.h, OpenImageIO) does the encoding.
#include "media/media.h"

#include "media/image_files.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace gs::media {
namespace {

// frame_ followed by four or more digits and .png, nothing else.
bool is_frame_file_name(const std::string &name) {
  const std::string prefix = "frame_", suffix = ".png";
  if (name.size() < prefix.size() + 4 + suffix.size()) return false;
  if (name.compare(0, prefix.size(), prefix) != 0) return false;
  if (name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) return false;
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

bool write_rgb_png(const std::string &path, int width, int height,
                   const std::vector<std::uint8_t> &rgb, std::string &error) {
  if (width < 1 || height < 1 || rgb.size() != std::size_t(width) * height * 3) {
    error = std::to_string(rgb.size()) + " bytes are not " +
            std::to_string(width) + "x" + std::to_string(height) + " RGB pixels";
    return false;
  }
  const ImageFiles *files = image_files(error);
  return files != nullptr && files->write_rgb(path, "", width, height, rgb.data(), error);
}

bool write_mask_png(const std::string &path, int width, int height,
                    const std::vector<std::uint8_t> &mask, std::string &error) {
  std::vector<std::uint8_t> rgb;
  rgb.reserve(mask.size() * 3);
  for (std::uint8_t m : mask) rgb.insert(rgb.end(), 3, m != 0 ? 255 : 0);
  return write_rgb_png(path, width, height, rgb, error);
}

bool prepare_frame_directory(const std::string &directory, std::string &error) {
  std::error_code code;
  fs::create_directories(directory, code);
  if (code) {
    error = "cannot create '" + directory + "': " + code.message();
    return false;
  }
  for (const fs::directory_entry &entry : fs::directory_iterator(directory, code)) {
    if (!entry.is_regular_file() || !is_frame_file_name(entry.path().filename().string())) continue;
    if (!fs::remove(entry.path(), code)) {
      error = "cannot remove the earlier run's '" + entry.path().string() + "': " + code.message();
      return false;
    }
  }
  if (code) {
    error = "cannot list '" + directory + "': " + code.message();
    return false;
  }
  return true;
}

std::string frame_path(const std::string &directory, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", index);
  return (fs::path(directory) / name).string();
}

bool write_contact_sheet(const std::vector<std::string> &frames, const std::string &path,
                         std::string &error) {
  const ImageFiles *files = image_files(error);
  return files != nullptr && files->write_contact_sheet(frames, path, error);
}

bool write_gif(const std::vector<std::string> &frames, const std::string &path, int fps,
               std::string &error) {
  const ImageFiles *files = image_files(error);
  return files != nullptr && files->write_gif(frames, path, fps, error);
}

}  // namespace gs::media
