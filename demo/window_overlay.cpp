// The window's overlays through the LFB: regions are read back, changed in 8-bit RGB (the
// bitmap font draws there) and written back as 565 words.
#include "window_overlay.h"

#include "measure/plot.h"

#include <algorithm>

namespace gs::demo {
namespace {

constexpr int kPanelMargin = 4;  // screen pixels of panel around the text

void to_rgb(FxU16 word, unsigned char *rgb) {
  rgb[0] = static_cast<unsigned char>((word >> 11) << 3 | (word >> 13));
  rgb[1] = static_cast<unsigned char>(((word >> 5) & 0x3F) << 2 | ((word >> 9) & 0x3));
  rgb[2] = static_cast<unsigned char>((word & 0x1F) << 3 | ((word >> 2) & 0x7));
}

FxU16 to_word(const unsigned char *rgb) {
  return static_cast<FxU16>((rgb[0] >> 3) << 11 | (rgb[1] >> 2) << 5 | (rgb[2] >> 3));
}

Picture read_region(int x, int y, int width, int height) {
  Picture region{width, height, std::vector<FxU16>(static_cast<std::size_t>(width) * height)};
  grLfbReadRegion(GR_BUFFER_BACKBUFFER, static_cast<FxU32>(x), static_cast<FxU32>(y),
                  static_cast<FxU32>(width), static_cast<FxU32>(height),
                  static_cast<FxU32>(width) * 2, region.words.data());
  return region;
}

void write_region(const Picture &region, int x, int y) {
  grLfbWriteRegion(GR_BUFFER_BACKBUFFER, static_cast<FxU32>(x), static_cast<FxU32>(y),
                   GR_LFB_SRC_FMT_565, static_cast<FxU32>(region.width),
                   static_cast<FxU32>(region.height), static_cast<FxI32>(region.width) * 2,
                   const_cast<FxU16 *>(region.words.data()));  // Glide 2.x takes a non-const pointer
}

}  // namespace

Picture read_back_buffer(int width, int height) { return read_region(0, 0, width, height); }

void draw_picture(const Picture &picture, int x, int y, int side) {
  if (picture.width <= 0 || picture.height <= 0) return;
  Picture framed{side + 2, side + 2, std::vector<FxU16>(static_cast<std::size_t>(side + 2) * (side + 2), 0xFFFF)};
  for (int row = 0; row < side; ++row) {
    for (int column = 0; column < side; ++column) {
      const int source_x = column * picture.width / side, source_y = row * picture.height / side;
      framed.words[static_cast<std::size_t>((row + 1) * (side + 2) + column + 1)] =
          picture.words[static_cast<std::size_t>(source_y * picture.width + source_x)];
    }
  }
  write_region(framed, x, y);
}

Picture alpha_nibble_picture(const Picture &words) {
  Picture picture = words;
  for (FxU16 &word : picture.words) {
    const unsigned alpha = word >> 12;
    word = alpha == 15 ? 0xFFFF : alpha == 0 ? 0x0000 : 0x8410;
  }
  return picture;
}

int text_panel_height(int lines, int scale) { return lines * 7 * scale + 2 * kPanelMargin; }

std::vector<std::string> wrap_for_panel(const std::string &text, int width, int scale,
                                        const std::string &indent) {
  std::vector<std::string> lines;
  std::string line;
  for (std::size_t start = 0, end = 0; start < text.size(); start = end + 1) {
    end = std::min(text.find(' ', start), text.size());
    const std::string word = text.substr(start, end - start);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && line != indent && bitmap_text_width(longer, scale) + 2 * kPanelMargin > width) {
      lines.push_back(line);
      line = indent + word;
    } else {
      line = longer;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

void draw_text_panel(const std::vector<std::string> &lines, int x, int y, int scale,
                     int screen_width, int screen_height, const unsigned char *colour) {
  int text_width = 0;
  for (const std::string &line : lines) text_width = std::max(text_width, bitmap_text_width(line, scale));
  const int line_height = 7 * scale;
  const int width = std::min(text_width + 2 * kPanelMargin, screen_width - x);
  const int height = std::min(text_panel_height(static_cast<int>(lines.size()), scale), screen_height - y);
  if (width <= 0 || height <= 0) return;
  Picture panel = read_region(x, y, width, height);
  std::vector<unsigned char> rgb(panel.words.size() * 3);
  for (std::size_t i = 0; i < panel.words.size(); ++i) {
    to_rgb(panel.words[i], &rgb[3 * i]);
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = static_cast<unsigned char>(rgb[3 * i + c] / 4);  // darkened
  }
  const unsigned char pale_yellow[3] = {255, 236, 150};
  if (colour == nullptr) colour = pale_yellow;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    draw_bitmap_text(rgb, width, height, kPanelMargin, kPanelMargin + static_cast<int>(i) * line_height,
                     lines[i], scale, colour);
  }
  for (std::size_t i = 0; i < panel.words.size(); ++i) panel.words[i] = to_word(&rgb[3 * i]);
  write_region(panel, x, y);
}

}  // namespace gs::demo
