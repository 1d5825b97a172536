// The media writers of media.h: OpenImageIO does the encoding; this file decides the sizes, the
// frame names and which files a run owns.
#include "media/media.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

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

OIIO::ImageBuf half_size(const OIIO::ImageBuf &frame) {
  return OIIO::ImageBufAlgo::resize(
      frame, "", 0, OIIO::ROI(0, frame.spec().width / 2, 0, frame.spec().height / 2, 0, 1, 0, 3));
}

}  // namespace

bool write_rgb_png(const std::string &path, int width, int height, const std::vector<std::uint8_t> &rgb) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8),
                       const_cast<std::uint8_t *>(rgb.data()));
  return image.write(path);
}

bool write_mask_png(const std::string &path, int width, int height, const std::vector<std::uint8_t> &mask) {
  std::vector<std::uint8_t> rgb;
  rgb.reserve(mask.size() * 3);
  for (std::uint8_t m : mask) rgb.insert(rgb.end(), 3, m != 0 ? 255 : 0);
  return write_rgb_png(path, width, height, rgb);
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

bool write_contact_sheet(const std::vector<std::string> &frames, const std::string &path) {
  const std::size_t count = std::min<std::size_t>(frames.size(), 16);
  if (count == 0) return true;
  const int columns = 4;
  const int rows = static_cast<int>((count + columns - 1) / columns);
  OIIO::ImageBuf first(frames[0]);
  if (!first.read()) return false;
  const int w = first.spec().width / 2, h = first.spec().height / 2;
  OIIO::ImageBuf sheet(OIIO::ImageSpec(w * columns, h * rows, 3, OIIO::TypeDesc::UINT8));
  OIIO::ImageBufAlgo::zero(sheet);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t index = i * frames.size() / count;  // spread over the whole run
    OIIO::ImageBuf frame(frames[index]);
    OIIO::ImageBuf small = OIIO::ImageBufAlgo::resize(frame, "", 0, OIIO::ROI(0, w, 0, h, 0, 1, 0, 3));
    const int x = static_cast<int>(i % columns) * w, y = static_cast<int>(i / columns) * h;
    OIIO::ImageBufAlgo::paste(sheet, x, y, 0, 0, small);
  }
  return sheet.write(path);
}

bool write_gif(const std::vector<std::string> &frames, const std::string &path, int fps) {
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  if (!out || !out->supports("multiimage") || frames.empty()) return false;
  std::vector<OIIO::ImageSpec> specs;
  std::vector<OIIO::ImageBuf> images;
  for (const std::string &file : frames) {
    OIIO::ImageBuf frame(file);
    if (!frame.read()) return false;
    OIIO::ImageBuf small = half_size(frame);
    OIIO::ImageSpec spec = small.spec();
    spec.attribute("FramesPerSecond", OIIO::TypeRational, std::vector<int>{fps, 1}.data());
    spec.attribute("oiio:Movie", 1);
    specs.push_back(spec);
    images.push_back(std::move(small));
  }
  if (!out->open(path, static_cast<int>(specs.size()), specs.data())) return false;
  for (std::size_t i = 0; i < images.size(); ++i) {
    if (i > 0 && !out->open(path, specs[i], OIIO::ImageOutput::AppendSubimage)) return false;
    if (!images[i].write(out.get())) return false;
  }
  return out->close();
}

}  // namespace gs::media
