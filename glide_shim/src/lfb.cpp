// Chapter "linear frame buffer": locks and region copies. Reads return the raw 16-bit words the
// pipeline wrote (565 colour, or depth codes from the aux buffer), always exact, which is what
// lets a program reinterpret a rendered frame as an ARGB_4444 texture.
#include "context.h"
#include "depth.h"
#include "gl_renderer.h"

#include <algorithm>
#include <cstring>
#include <string>

using glide_shim::current;

namespace {

bool is_lfb_buffer(GrBuffer_t buffer) {
  return buffer == GR_BUFFER_FRONTBUFFER || buffer == GR_BUFFER_BACKBUFFER ||
         buffer == GR_BUFFER_AUXBUFFER;
}

bool region_inside(FxU32 x, FxU32 y, FxU32 w, FxU32 h) {
  const auto &display = current().display;
  const auto width = static_cast<FxU32>(display.width), height = static_cast<FxU32>(display.height);
  return w > 0 && h > 0 && x < width && y < height && w <= width - x && h <= height - y;
}

std::string region_text(FxU32 x, FxU32 y, FxU32 w, FxU32 h) {
  const auto &display = current().display;
  return std::to_string(w) + "x" + std::to_string(h) + " at (" + std::to_string(x) + "," +
         std::to_string(y) + ") is not inside the " + std::to_string(display.width) + "x" +
         std::to_string(display.height) + " buffer";
}

// Reads a region of `buffer` as 16-bit words with an upper-left origin.
void read_words(GrBuffer_t buffer, int x, int y, int w, int h, std::uint16_t *dst,
                std::size_t stride) {
  auto &ctx = current();
  if (buffer != GR_BUFFER_AUXBUFFER) {
    ctx.renderer->read_color(ctx.renderer->buffer_index(buffer), x, y, w, h, dst, stride);
    return;
  }
  std::vector<float> depth(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  ctx.renderer->read_depth(x, y, w, h, depth.data());
  const bool w_buffer = glide_shim::is_w_buffer(ctx.depth.mode);
  auto *out = reinterpret_cast<std::uint8_t *>(dst);
  for (int row = 0; row < h; ++row) {
    auto *line = reinterpret_cast<std::uint16_t *>(out + static_cast<std::size_t>(row) * stride);
    for (int col = 0; col < w; ++col) {
      line[col] = glide_shim::code_from_gl_depth(depth[static_cast<std::size_t>(row * w + col)],
                                                 w_buffer);
    }
  }
}

// One source pixel of grLfbWriteRegion as a 565 word (8-bit channels truncate, dither off).
std::uint16_t to_565(GrLfbSrcFmt_t format, const std::uint8_t *p) {
  std::uint16_t word;
  std::uint32_t dword;
  switch (format) {
    case GR_LFB_SRC_FMT_565: std::memcpy(&word, p, 2); return word;
    case GR_LFB_SRC_FMT_555:
    case GR_LFB_SRC_FMT_1555:  // x/a in bit 15, then 5-5-5: green widens by replication
      std::memcpy(&word, p, 2);
      return static_cast<std::uint16_t>(((word & 0x7C00) << 1) |
                                        (((word >> 5) & 0x1F) << 6) |
                                        ((((word >> 5) & 0x1F) >> 4) << 5) | (word & 0x1F));
    default:  // 888 and 8888: 32-bit words, 0xAARRGGBB
      std::memcpy(&dword, p, 4);
      return static_cast<std::uint16_t>((((dword >> 16) & 0xFF) >> 3) << 11 |
                                        (((dword >> 8) & 0xFF) >> 2) << 5 | ((dword & 0xFF) >> 3));
  }
}

// Bytes per pixel of an LFB write mode, and what its pixels carry.
int write_mode_bytes(GrLfbWriteMode_t mode) {
  return mode == GR_LFBWRITEMODE_888 || mode == GR_LFBWRITEMODE_8888 ||
                 mode == GR_LFBWRITEMODE_565_DEPTH || mode == GR_LFBWRITEMODE_555_DEPTH ||
                 mode == GR_LFBWRITEMODE_1555_DEPTH
             ? 4
             : 2;
}
bool mode_has_color(GrLfbWriteMode_t mode) { return mode != GR_LFBWRITEMODE_ZA16; }
bool mode_has_depth(GrLfbWriteMode_t mode) {
  return mode == GR_LFBWRITEMODE_ZA16 || mode == GR_LFBWRITEMODE_565_DEPTH ||
         mode == GR_LFBWRITEMODE_555_DEPTH || mode == GR_LFBWRITEMODE_1555_DEPTH;
}
// The colour-only format of a mode's colour word (the LFB write modes share the source-format
// values of grLfbWriteRegion).
GrLfbSrcFmt_t color_format_of(GrLfbWriteMode_t mode) {
  switch (mode) {
    case GR_LFBWRITEMODE_565_DEPTH: return GR_LFB_SRC_FMT_565;
    case GR_LFBWRITEMODE_555_DEPTH: return GR_LFB_SRC_FMT_555;
    case GR_LFBWRITEMODE_1555_DEPTH: return GR_LFB_SRC_FMT_1555;
    default: return mode;
  }
}

// A 565 word in a write mode's colour layout, so that a pixel the program leaves alone reads
// back as what the buffer holds (888/8888 widen by bit replication, 555 drops green's low bit).
void encode_color(GrLfbSrcFmt_t format, std::uint16_t word, std::uint8_t *p) {
  const unsigned r5 = word >> 11, g6 = (word >> 5) & 0x3F, b5 = word & 0x1F;
  if (format == GR_LFB_SRC_FMT_555 || format == GR_LFB_SRC_FMT_1555) {
    const auto packed = static_cast<std::uint16_t>((format == GR_LFB_SRC_FMT_1555 ? 0x8000u : 0u) |
                                                   (r5 << 10) | ((g6 >> 1) << 5) | b5);
    std::memcpy(p, &packed, 2);
  } else if (format == GR_LFB_SRC_FMT_888 || format == GR_LFB_SRC_FMT_8888) {
    const std::uint32_t packed = 0xFF000000u | (((r5 << 3) | (r5 >> 2)) << 16) |
                                 (((g6 << 2) | (g6 >> 4)) << 8) | ((b5 << 3) | (b5 >> 2));
    std::memcpy(p, &packed, 4);
  } else {
    std::memcpy(p, &word, 2);
  }
}

// Flips the rows of a whole-screen block (lower-left origin locks).
void flip_rows(std::vector<std::uint8_t> &bytes, std::size_t row_bytes, int height) {
  for (int row = 0; row < height / 2; ++row) {
    std::swap_ranges(bytes.begin() + static_cast<long>(row * row_bytes),
                     bytes.begin() + static_cast<long>((row + 1) * row_bytes),
                     bytes.begin() + static_cast<long>((height - 1 - row) * row_bytes));
  }
}

// Writes the pixels of row `row` in [first, last) of a locked block back through the renderer.
void write_span(GrBuffer_t buffer, GrLfbWriteMode_t mode, const std::uint8_t *row_bytes, int row,
                int first, int last) {
  auto &ctx = current();
  const int bytes = write_mode_bytes(mode), n = last - first;
  std::vector<std::uint16_t> words(static_cast<std::size_t>(n));
  std::vector<float> depths(static_cast<std::size_t>(n));
  const bool w_buffer = glide_shim::is_w_buffer(ctx.depth.mode);
  for (int i = 0; i < n; ++i) {
    const std::uint8_t *p = row_bytes + static_cast<std::size_t>((first + i) * bytes);
    if (mode_has_color(mode)) words[static_cast<std::size_t>(i)] = to_565(color_format_of(mode), p);
    if (mode_has_depth(mode)) {
      std::uint16_t code;
      std::memcpy(&code, mode_has_color(mode) ? p + 2 : p, 2);
      depths[static_cast<std::size_t>(i)] = static_cast<float>(glide_shim::gl_depth_from_code(code, w_buffer));
    }
  }
  if (mode_has_color(mode)) {
    ctx.renderer->write_color(ctx.renderer->buffer_index(buffer), first, row, n, 1, words.data(),
                              static_cast<std::size_t>(n) * 2);
  }
  if (mode_has_depth(mode)) ctx.renderer->write_depth(first, row, n, 1, depths.data());
}

}  // namespace

extern "C" {

FxBool grLfbLock(GrLock_t type, GrBuffer_t buffer, GrLfbWriteMode_t writeMode,
                 GrOriginLocation_t origin, FxBool pixelPipeline, GrLfbInfo_t *info) {
  auto &ctx = current();
  if (!ctx.require_open("grLfbLock")) return FXFALSE;
  const GrLock_t access = type & ~GR_LFB_NOIDLE;
  if (info == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grLfbLock: info is NULL");
    return FXFALSE;
  }
  if (info->size != static_cast<int>(sizeof(GrLfbInfo_t))) {
    ctx.report(GLIDESHIM_ERR_INCONSISTENT, "grLfbLock: info->size must be sizeof(GrLfbInfo_t)");
    return FXFALSE;
  }
  if ((access != GR_LFB_READ_ONLY && access != GR_LFB_WRITE_ONLY) || !is_lfb_buffer(buffer) ||
      (origin != GR_ORIGIN_UPPER_LEFT && origin != GR_ORIGIN_LOWER_LEFT)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grLfbLock: unknown lock type, buffer or origin");
    return FXFALSE;
  }
  const bool reading = access == GR_LFB_READ_ONLY;
  const bool defined_write_mode = (writeMode >= GR_LFBWRITEMODE_565 && writeMode <= GR_LFBWRITEMODE_1555) ||
                                  writeMode == GR_LFBWRITEMODE_888 || writeMode == GR_LFBWRITEMODE_8888 ||
                                  (writeMode >= GR_LFBWRITEMODE_565_DEPTH && writeMode <= GR_LFBWRITEMODE_ZA16) ||
                                  writeMode == GR_LFBWRITEMODE_ANY;
  if (!reading && !defined_write_mode) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grLfbLock: unknown write mode " + std::to_string(writeMode));
    return FXFALSE;
  }
  if (reading ? ctx.lfb.read_locked : ctx.lfb.write_locked) {
    ctx.report(GLIDESHIM_ERR_INCONSISTENT, "grLfbLock: this lock type is already held");
    return FXFALSE;
  }
  if (!reading && pixelPipeline != FXFALSE) {
    ctx.report(GLIDESHIM_ERR_UNSUPPORTED,
               "grLfbLock: writes through the pixel pipeline are not implemented yet");
    return FXFALSE;
  }
  // ANY means 565 colour, or ZA16 for the aux buffer; ZA16 writes depth whichever buffer is
  // named, and colour modes need a colour buffer.
  const GrLfbWriteMode_t mode = writeMode != GR_LFBWRITEMODE_ANY ? writeMode
                                : buffer == GR_BUFFER_AUXBUFFER  ? GR_LFBWRITEMODE_ZA16
                                                                 : GR_LFBWRITEMODE_565;
  if (!reading && buffer == GR_BUFFER_AUXBUFFER && mode_has_color(mode)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grLfbLock: colour write modes lock GR_BUFFER_FRONTBUFFER or GR_BUFFER_BACKBUFFER");
    return FXFALSE;
  }
  const int w = ctx.display.width, h = ctx.display.height;
  const auto count = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  if (reading) {
    std::vector<std::uint16_t> &pixels = ctx.lfb.read_pixels;
    pixels.resize(count);
    read_words(buffer, 0, 0, w, h, pixels.data(), static_cast<std::size_t>(w) * 2);
    if (origin == GR_ORIGIN_LOWER_LEFT) {
      for (int row = 0; row < h / 2; ++row) {
        std::swap_ranges(pixels.begin() + row * w, pixels.begin() + (row + 1) * w,
                         pixels.begin() + (h - 1 - row) * w);
      }
    }
    ctx.lfb.read_locked = true;
    info->lfbPtr = pixels.data();
    info->strideInBytes = static_cast<FxU32>(w) * 2;
    info->writeMode = buffer == GR_BUFFER_AUXBUFFER ? GR_LFBWRITEMODE_ZA16 : GR_LFBWRITEMODE_565;
    info->origin = origin;
    return FXTRUE;
  }
  // A write lock starts from the buffers' contents in the lock's format, so pixels the program
  // skips are recognised as unchanged at the unlock and survive as they are.
  const int bytes = write_mode_bytes(mode);
  std::vector<std::uint16_t> colors(mode_has_color(mode) ? count : 0), codes(mode_has_depth(mode) ? count : 0);
  if (mode_has_color(mode)) read_words(buffer, 0, 0, w, h, colors.data(), static_cast<std::size_t>(w) * 2);
  if (mode_has_depth(mode)) read_words(GR_BUFFER_AUXBUFFER, 0, 0, w, h, codes.data(), static_cast<std::size_t>(w) * 2);
  std::vector<std::uint8_t> &pixels = ctx.lfb.write_pixels;
  pixels.assign(count * static_cast<std::size_t>(bytes), 0);
  for (std::size_t i = 0; i < count; ++i) {
    std::uint8_t *p = pixels.data() + i * static_cast<std::size_t>(bytes);
    if (mode_has_color(mode)) encode_color(color_format_of(mode), colors[i], p);
    if (mode_has_depth(mode)) std::memcpy(mode_has_color(mode) ? p + 2 : p, &codes[i], 2);
  }
  const std::size_t row_bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(bytes);
  if (origin == GR_ORIGIN_LOWER_LEFT) flip_rows(pixels, row_bytes, h);
  ctx.lfb.write_original = pixels;
  ctx.lfb.write_locked = true;
  ctx.lfb.write_buffer = buffer;
  ctx.lfb.write_origin = origin;
  ctx.lfb.write_mode = mode;
  info->lfbPtr = pixels.data();
  info->strideInBytes = static_cast<FxU32>(row_bytes);
  info->writeMode = mode;
  info->origin = origin;
  return FXTRUE;
}

FxBool grLfbUnlock(GrLock_t type, GrBuffer_t buffer) {
  auto &ctx = current();
  if (!ctx.require_open("grLfbUnlock")) return FXFALSE;
  const GrLock_t access = type & ~GR_LFB_NOIDLE;
  if (access == GR_LFB_READ_ONLY && ctx.lfb.read_locked) {
    ctx.lfb.read_locked = false;
    return FXTRUE;
  }
  if (access == GR_LFB_WRITE_ONLY && ctx.lfb.write_locked && buffer == ctx.lfb.write_buffer) {
    const int w = ctx.display.width, h = ctx.display.height;
    const GrLfbWriteMode_t mode = ctx.lfb.write_mode;
    const int bytes = write_mode_bytes(mode);
    const std::size_t row_bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(bytes);
    std::vector<std::uint8_t> &pixels = ctx.lfb.write_pixels, &original = ctx.lfb.write_original;
    if (ctx.lfb.write_origin == GR_ORIGIN_LOWER_LEFT) {
      flip_rows(pixels, row_bytes, h);
      flip_rows(original, row_bytes, h);
    }
    // Only runs of pixels the program changed go back, so drawing done while the lock was held
    // survives, and untouched depth keeps its full precision.
    for (int row = 0; row < h; ++row) {
      const std::uint8_t *line = pixels.data() + static_cast<std::size_t>(row) * row_bytes;
      const std::uint8_t *was = original.data() + static_cast<std::size_t>(row) * row_bytes;
      int x = 0;
      while (x < w) {
        auto changed = [&](int px) {
          return std::memcmp(line + px * bytes, was + px * bytes, static_cast<std::size_t>(bytes)) != 0;
        };
        if (!changed(x)) {
          ++x;
          continue;
        }
        int end = x + 1;
        while (end < w && changed(end)) ++end;
        write_span(buffer, mode, line, row, x, end);
        x = end;
      }
    }
    ctx.lfb.write_locked = false;
    return FXTRUE;
  }
  ctx.report(GLIDESHIM_ERR_INCONSISTENT, "grLfbUnlock: no such lock is held");
  return FXFALSE;
}

FxBool grLfbReadRegion(GrBuffer_t src_buffer, FxU32 src_x, FxU32 src_y, FxU32 src_width,
                       FxU32 src_height, FxU32 dst_stride, void *dst_data) {
  auto &ctx = current();
  if (!ctx.require_open("grLfbReadRegion")) return FXFALSE;
  if (!is_lfb_buffer(src_buffer)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grLfbReadRegion: unknown buffer");
    return FXFALSE;
  }
  if (dst_data == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grLfbReadRegion: dst_data is NULL");
    return FXFALSE;
  }
  if (!region_inside(src_x, src_y, src_width, src_height)) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grLfbReadRegion: " + region_text(src_x, src_y, src_width, src_height));
    return FXFALSE;
  }
  if (dst_stride < src_width * 2) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "grLfbReadRegion: dst_stride " +
                                               std::to_string(dst_stride) +
                                               " is less than width * 2 bytes");
    return FXFALSE;
  }
  read_words(src_buffer, static_cast<int>(src_x), static_cast<int>(src_y),
             static_cast<int>(src_width), static_cast<int>(src_height),
             static_cast<std::uint16_t *>(dst_data), dst_stride);
  return FXTRUE;
}

FxBool grLfbWriteRegion(GrBuffer_t dst_buffer, FxU32 dst_x, FxU32 dst_y, GrLfbSrcFmt_t src_format,
                        FxU32 src_width, FxU32 src_height, FxI32 src_stride, void *src_data) {
  auto &ctx = current();
  if (!ctx.require_open("grLfbWriteRegion")) return FXFALSE;
  int bytes_per_pixel = 0;
  bool color = true, depth = false;  // what the source pixels carry
  switch (src_format) {
    case GR_LFB_SRC_FMT_565:
    case GR_LFB_SRC_FMT_555:
    case GR_LFB_SRC_FMT_1555: bytes_per_pixel = 2; break;
    case GR_LFB_SRC_FMT_888:
    case GR_LFB_SRC_FMT_8888: bytes_per_pixel = 4; break;
    case GR_LFB_SRC_FMT_565_DEPTH:
    case GR_LFB_SRC_FMT_555_DEPTH:
    case GR_LFB_SRC_FMT_1555_DEPTH: bytes_per_pixel = 4, depth = true; break;
    case GR_LFB_SRC_FMT_ZA16: bytes_per_pixel = 2, color = false, depth = true; break;
    case GR_LFB_SRC_FMT_RLE16:
      // The SST-1 driver (glfb.c) leaves RLE16 unimplemented and returns FXFALSE.
      ctx.report(GLIDESHIM_ERR_UNSUPPORTED,
                 "grLfbWriteRegion: GR_LFB_SRC_FMT_RLE16 is not implemented (nor by the SST-1 driver)");
      return FXFALSE;
    default:
      ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grLfbWriteRegion: unknown source format " +
                                                 std::to_string(src_format));
      return FXFALSE;
  }
  // A ZA16 word carries depth only, which the aux buffer takes whichever buffer is named;
  // colour formats need a colour buffer (the aux buffer holds depth, not colour).
  if (!is_lfb_buffer(dst_buffer) || (color && dst_buffer == GR_BUFFER_AUXBUFFER)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grLfbWriteRegion: colour formats write GR_BUFFER_FRONTBUFFER or GR_BUFFER_BACKBUFFER");
    return FXFALSE;
  }
  if (src_data == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grLfbWriteRegion: src_data is NULL");
    return FXFALSE;
  }
  if (!region_inside(dst_x, dst_y, src_width, src_height)) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grLfbWriteRegion: " + region_text(dst_x, dst_y, src_width, src_height));
    return FXFALSE;
  }
  if (src_stride < static_cast<FxI32>(src_width) * bytes_per_pixel) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "grLfbWriteRegion: src_stride " +
                                               std::to_string(src_stride) +
                                               " is less than one row of pixels");
    return FXFALSE;
  }
  const std::size_t count = static_cast<std::size_t>(src_width) * src_height;
  std::vector<std::uint16_t> words(count);
  std::vector<float> depths(depth ? count : 0);
  const bool w_buffer = glide_shim::is_w_buffer(ctx.depth.mode);
  // The 32-bit colour-and-depth formats hold the colour word low and the depth code high.
  const GrLfbSrcFmt_t color_format = src_format == GR_LFB_SRC_FMT_565_DEPTH   ? GR_LFB_SRC_FMT_565
                                     : src_format == GR_LFB_SRC_FMT_555_DEPTH ? GR_LFB_SRC_FMT_555
                                     : src_format == GR_LFB_SRC_FMT_1555_DEPTH ? GR_LFB_SRC_FMT_1555
                                                                                : src_format;
  const auto *in = static_cast<const std::uint8_t *>(src_data);
  for (FxU32 row = 0; row < src_height; ++row) {
    for (FxU32 col = 0; col < src_width; ++col) {
      const std::uint8_t *p = in + static_cast<std::size_t>(row) * static_cast<std::size_t>(src_stride) +
                              static_cast<std::size_t>(col) * static_cast<std::size_t>(bytes_per_pixel);
      const std::size_t i = static_cast<std::size_t>(row) * src_width + col;
      if (color) words[i] = to_565(color_format, p);
      if (depth) {
        std::uint16_t code;
        std::memcpy(&code, color ? p + 2 : p, 2);
        depths[i] = static_cast<float>(glide_shim::gl_depth_from_code(code, w_buffer));
      }
    }
  }
  const int x = static_cast<int>(dst_x), y = static_cast<int>(dst_y);
  const int w = static_cast<int>(src_width), h = static_cast<int>(src_height);
  if (color) {
    ctx.renderer->write_color(ctx.renderer->buffer_index(dst_buffer), x, y, w, h, words.data(),
                              static_cast<std::size_t>(src_width) * 2);
  }
  if (depth) ctx.renderer->write_depth(x, y, w, h, depths.data());
  return FXTRUE;
}

void grLfbConstantAlpha(GrAlpha_t alpha) {
  auto &ctx = current();
  if (!ctx.require_open("grLfbConstantAlpha")) return;
  ctx.lfb.constant_alpha = alpha;
}

void grLfbConstantDepth(FxU16 depth) {
  auto &ctx = current();
  if (!ctx.require_open("grLfbConstantDepth")) return;
  ctx.lfb.constant_depth = depth;
}

}  // extern "C"
