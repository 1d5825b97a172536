// The SST-1's linear-frame-buffer data words (lfb_data.h): the write modes' pixel sizes and
// colour fields under lfbMode's RGBA lanes, their expansion to 8-bit colour and a depth code as
// MAME's expand_lfb_data does it, the inverse for pixels a write lock leaves alone, and
// grLfbWriteColorSwizzle's byte swizzle and word swap.
#include "lfb_data.h"

#include <cstring>

namespace glide_shim {
namespace {

// The colour-only mode of a mode's colour word: the +DEPTH modes hold it in their low 16 bits.
GrLfbWriteMode_t color_mode_of(GrLfbWriteMode_t mode) {
  switch (mode) {
    case GR_LFBWRITEMODE_565_DEPTH: return GR_LFBWRITEMODE_565;
    case GR_LFBWRITEMODE_555_DEPTH: return GR_LFBWRITEMODE_555;
    case GR_LFBWRITEMODE_1555_DEPTH: return GR_LFBWRITEMODE_1555;
    default: return mode;
  }
}

// Where one channel sits in an LFB colour word.
struct Field {
  int shift, bits;  // bits 0: the word has no such field
};
struct ColorFields {
  Field r, g, b, a;
};

// The channel layout of a colour mode under lfbMode's RGBA lanes (grLfbWriteColorFormat), as
// MAME's expand_lfb_data decodes it: ABGR and BGRA put blue in the high field and red in the
// low one; RGBA and BGRA move alpha (or the unused bits) below the colour. 565 has no spare bit,
// so its RGBA is ARGB and its BGRA is ABGR.
ColorFields color_fields(GrLfbWriteMode_t color_mode, GrColorFormat_t lanes) {
  const bool blue_high = lanes == GR_COLORFORMAT_ABGR || lanes == GR_COLORFORMAT_BGRA;
  const bool alpha_low = lanes == GR_COLORFORMAT_RGBA || lanes == GR_COLORFORMAT_BGRA;
  auto rgb = [blue_high](int base, int red_blue_bits, int green_bits) {
    const Field low{base, red_blue_bits}, high{base + red_blue_bits + green_bits, red_blue_bits};
    return ColorFields{blue_high ? low : high, {base + red_blue_bits, green_bits},
                       blue_high ? high : low, {0, 0}};
  };
  switch (color_mode) {
    case GR_LFBWRITEMODE_565: return rgb(0, 5, 6);
    case GR_LFBWRITEMODE_555:
    case GR_LFBWRITEMODE_1555: {
      ColorFields fields = rgb(alpha_low ? 1 : 0, 5, 5);
      if (color_mode == GR_LFBWRITEMODE_1555) fields.a = {alpha_low ? 0 : 15, 1};
      return fields;
    }
    default: {  // 888 and 8888: 32-bit words
      ColorFields fields = rgb(alpha_low ? 8 : 0, 8, 8);
      if (color_mode == GR_LFBWRITEMODE_8888) fields.a = {alpha_low ? 0 : 24, 8};
      return fields;
    }
  }
}

// A field widened to 8 bits by bit replication (a 1-bit alpha becomes 0 or 255).
std::uint8_t widen(std::uint32_t word, Field field) {
  const std::uint32_t value = (word >> field.shift) & ((1u << field.bits) - 1u);
  switch (field.bits) {
    case 1: return value != 0 ? 0xFF : 0;
    case 5: return static_cast<std::uint8_t>(value << 3 | value >> 2);
    case 6: return static_cast<std::uint8_t>(value << 2 | value >> 4);
    default: return static_cast<std::uint8_t>(value);
  }
}

}  // namespace

// Bytes per pixel of an LFB write mode, and what its pixels carry.
int lfb_write_mode_bytes(GrLfbWriteMode_t mode) {
  return mode == GR_LFBWRITEMODE_888 || mode == GR_LFBWRITEMODE_8888 ||
                 mode == GR_LFBWRITEMODE_565_DEPTH || mode == GR_LFBWRITEMODE_555_DEPTH ||
                 mode == GR_LFBWRITEMODE_1555_DEPTH
             ? 4
             : 2;
}
bool lfb_mode_has_color(GrLfbWriteMode_t mode) { return mode != GR_LFBWRITEMODE_ZA16; }
bool lfb_mode_has_depth(GrLfbWriteMode_t mode) {
  return mode == GR_LFBWRITEMODE_ZA16 || mode == GR_LFBWRITEMODE_565_DEPTH ||
         mode == GR_LFBWRITEMODE_555_DEPTH || mode == GR_LFBWRITEMODE_1555_DEPTH;
}

// One LFB data word (a 16-bit mode's in the low half) as the hardware expands it: the colour
// by the lanes, alpha from the data if the mode has alpha, else the constant alpha, and the depth
// code from the data for ZA16 and the +DEPTH modes (high half), else the constant depth.
LfbPixel expand_lfb_data(GrLfbWriteMode_t mode, GrColorFormat_t lanes, std::uint32_t data,
                GrAlpha_t constant_alpha, FxU16 constant_depth) {
  LfbPixel pixel{0, 0, {0, 0, 0, constant_alpha}, constant_depth};
  if (mode == GR_LFBWRITEMODE_ZA16) {
    pixel.depth = static_cast<FxU16>(data & 0xFFFF);
    return pixel;
  }
  if (lfb_mode_has_depth(mode)) pixel.depth = static_cast<FxU16>(data >> 16);
  const ColorFields fields = color_fields(color_mode_of(mode), lanes);
  pixel.color.r = widen(data, fields.r);
  pixel.color.g = widen(data, fields.g);
  pixel.color.b = widen(data, fields.b);
  if (fields.a.bits != 0) pixel.color.a = widen(data, fields.a);
  return pixel;
}

// The data word that stands for a stored 565 colour and depth code in a mode's layout (alpha
// full), so a pixel a write lock's program leaves alone is recognised as unchanged.
std::uint32_t encode_lfb_data(GrLfbWriteMode_t mode, GrColorFormat_t lanes, std::uint16_t word, FxU16 code) {
  if (mode == GR_LFBWRITEMODE_ZA16) return code;
  const ColorFields fields = color_fields(color_mode_of(mode), lanes);
  const Field stored_r{11, 5}, stored_g{5, 6}, stored_b{0, 5};
  auto put = [](std::uint8_t value, Field field) {
    return field.bits == 0 ? 0u : static_cast<std::uint32_t>(value >> (8 - field.bits)) << field.shift;
  };
  std::uint32_t data = put(widen(word, stored_r), fields.r) | put(widen(word, stored_g), fields.g) |
                       put(widen(word, stored_b), fields.b) | put(0xFF, fields.a);
  if (lfb_mode_has_depth(mode)) data |= static_cast<std::uint32_t>(code) << 16;
  return data;
}

std::uint16_t truncate_to_565(const Rgba8 &color) {  // truncation: direct writes do not dither
  return static_cast<std::uint16_t>((color.r >> 3) << 11 | (color.g >> 2) << 5 | (color.b >> 3));
}

std::uint32_t load_lfb_data(const std::uint8_t *p, int bytes) {
  if (bytes == 2) {
    std::uint16_t word;
    std::memcpy(&word, p, 2);
    return word;
  }
  std::uint32_t word;
  std::memcpy(&word, p, 4);
  return word;
}
void store_lfb_data(std::uint32_t value, std::uint8_t *p, int bytes) {
  if (bytes == 2) {
    const auto word = static_cast<std::uint16_t>(value);
    std::memcpy(p, &word, 2);
  } else {
    std::memcpy(p, &value, 4);
  }
}

// grLfbWriteColorSwizzle on one pixel's data (MAME's internal_lfb_w: the 32-bit bus word is
// byte-swizzled, then its 16-bit halves swapped). A 16-bit pixel shares its bus word with pixel
// x ^ 1 of its row, so the swizzle reverses its two bytes and, alone or with the swap alone, moves
// the data to that partner; both together swizzle it in place. Both steps undo themselves.
std::uint32_t swizzled_lfb_data(std::uint32_t data, int bytes, const LfbWriteLayout &layout) {
  if (bytes == 2) {
    return layout.swizzle_bytes ? ((data & 0xFF) << 8 | (data >> 8 & 0xFF)) : data;
  }
  if (layout.swizzle_bytes) {
    data = (data & 0xFF) << 24 | (data & 0xFF00) << 8 | (data >> 8 & 0xFF00) | data >> 24;
  }
  return layout.swap_words ? (data << 16 | data >> 16) : data;
}
int lfb_landing_x(int x, int bytes, const LfbWriteLayout &layout) {
  return bytes == 2 && layout.swizzle_bytes != layout.swap_words ? x ^ 1 : x;
}

}  // namespace glide_shim
