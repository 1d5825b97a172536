// Chapter "linear frame buffer": locks and region copies. Reads return the raw 16-bit words the
// pipeline wrote (565 colour, or depth codes from the aux buffer), always exact, which is what
// lets a program reinterpret a rendered frame as an ARGB_4444 texture. Written data is decoded as
// the SST-1 decodes it (lfb_data.cpp, after MAME's expand_lfb_data) under lfbMode's RGBA lanes,
// byte swizzle and word swap; direct writes store the colour truncated to 565 and the depth
// code, and pipelined writes (lfb_pipeline.cpp) run through the pixel pipeline.
#include "context.h"
#include "depth.h"
#include "gl/gl_renderer.h"
#include "lfb_data.h"
#include "lfb_pipeline.h"

#include <algorithm>
#include <cstring>
#include <string>

using glide_shim::current;
using glide_shim::encode_lfb_data;
using glide_shim::expand_lfb_data;
using glide_shim::lfb_landing_x;
using glide_shim::lfb_mode_has_color;
using glide_shim::lfb_mode_has_depth;
using glide_shim::lfb_write_mode_bytes;
using glide_shim::load_lfb_data;
using glide_shim::store_lfb_data;
using glide_shim::swizzled_lfb_data;
using glide_shim::truncate_to_565;

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
    std::uint8_t *line = out + static_cast<std::size_t>(row) * stride;
    for (int col = 0; col < w; ++col) {
      const std::uint16_t code = glide_shim::code_from_gl_depth(
          depth[static_cast<std::size_t>(row * w + col)], w_buffer);
      // memcpy: an odd dst_stride leaves the words of odd rows unaligned.
      std::memcpy(line + static_cast<std::size_t>(col) * 2, &code, sizeof code);
    }
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

// Stores expanded pixels straight into the buffers, bypassing the pipeline: a block of `w`
// columns starting at column `x`, of which only those `written` marks change; rows from `y` down.
void write_direct(GrBuffer_t buffer, bool color, bool depth, int x, int y, int w, int h,
                  const std::vector<glide_shim::LfbPixel> &block, const std::vector<bool> &written) {
  auto &ctx = current();
  const bool w_buffer = glide_shim::is_w_buffer(ctx.depth.mode);
  int first = 0;
  while (first < w) {
    if (!written[static_cast<std::size_t>(first)]) {
      ++first;
      continue;
    }
    int end = first + 1;
    while (end < w && written[static_cast<std::size_t>(end)]) ++end;
    const int run = end - first;
    std::vector<std::uint16_t> words(static_cast<std::size_t>(run * h));
    std::vector<float> depths(static_cast<std::size_t>(run * h));
    for (int row = 0; row < h; ++row) {
      for (int col = 0; col < run; ++col) {
        const glide_shim::LfbPixel &pixel = block[static_cast<std::size_t>(row * w + first + col)];
        const auto i = static_cast<std::size_t>(row * run + col);
        words[i] = truncate_to_565(pixel.color);
        depths[i] = static_cast<float>(glide_shim::gl_depth_from_code(pixel.depth, w_buffer));
      }
    }
    if (color) {
      ctx.renderer->write_color(ctx.renderer->buffer_index(buffer), x + first, y, run, h,
                                words.data(), static_cast<std::size_t>(run) * 2);
    }
    if (depth) ctx.renderer->write_depth(x + first, y, run, h, depths.data());
    first = end;
  }
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

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
  if (!reading && pixelPipeline != FXFALSE && ctx.texture_target.active) {
    ctx.report(GLIDESHIM_ERR_UNSUPPORTED,
               "grLfbLock: writes through the pixel pipeline are not available while "
               "glideShimRenderToTexture is active");
    return FXFALSE;
  }
  // ANY means 565 colour, or ZA16 for the aux buffer; ZA16 writes depth whichever buffer is
  // named, and colour modes need a colour buffer.
  const GrLfbWriteMode_t mode = writeMode != GR_LFBWRITEMODE_ANY ? writeMode
                                : buffer == GR_BUFFER_AUXBUFFER  ? GR_LFBWRITEMODE_ZA16
                                                                 : GR_LFBWRITEMODE_565;
  if (!reading && buffer == GR_BUFFER_AUXBUFFER && lfb_mode_has_color(mode)) {
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
  // A write lock starts from the buffers' contents in the lock's format and write layout, so
  // pixels the program skips are recognised as unchanged at the unlock and survive as they are.
  const int bytes = lfb_write_mode_bytes(mode);
  std::vector<std::uint16_t> colors(lfb_mode_has_color(mode) ? count : 0), codes(lfb_mode_has_depth(mode) ? count : 0);
  if (lfb_mode_has_color(mode)) read_words(buffer, 0, 0, w, h, colors.data(), static_cast<std::size_t>(w) * 2);
  if (lfb_mode_has_depth(mode)) read_words(GR_BUFFER_AUXBUFFER, 0, 0, w, h, codes.data(), static_cast<std::size_t>(w) * 2);
  const glide_shim::LfbWriteLayout &layout = ctx.lfb.layout;
  std::vector<std::uint8_t> &pixels = ctx.lfb.write_pixels;
  pixels.assign(count * static_cast<std::size_t>(bytes), 0);
  for (int row = 0; row < h; ++row) {
    for (int slot = 0; slot < w; ++slot) {
      // The slot shows the pixel its data would land on (itself unless the swizzle moves it).
      const int landing = lfb_landing_x(slot, bytes, layout);
      const auto i = static_cast<std::size_t>(row * w + (landing < w ? landing : slot));
      const std::uint32_t data =
          encode_lfb_data(mode, layout.color_format, lfb_mode_has_color(mode) ? colors[i] : 0,
                          lfb_mode_has_depth(mode) ? codes[i] : 0);
      store_lfb_data(swizzled_lfb_data(data, bytes, layout),
            pixels.data() + static_cast<std::size_t>(row * w + slot) * static_cast<std::size_t>(bytes), bytes);
    }
  }
  const std::size_t row_bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(bytes);
  if (origin == GR_ORIGIN_LOWER_LEFT) flip_rows(pixels, row_bytes, h);
  ctx.lfb.write_original = pixels;
  ctx.lfb.write_locked = true;
  ctx.lfb.write_buffer = buffer;
  ctx.lfb.write_origin = origin;
  ctx.lfb.write_mode = mode;
  ctx.lfb.write_pipeline = pixelPipeline != FXFALSE;
  // The driver loads zaColor with the constant depth and alpha at the lock (glfb.c).
  ctx.lfb.write_alpha = ctx.lfb.constant_alpha;
  ctx.lfb.write_depth = ctx.lfb.constant_depth;
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
    const int bytes = lfb_write_mode_bytes(mode);
    const std::size_t row_bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(bytes);
    std::vector<std::uint8_t> &pixels = ctx.lfb.write_pixels, &original = ctx.lfb.write_original;
    ctx.lfb.write_locked = false;
    if (ctx.lfb.write_pipeline && ctx.texture_target.active) {
      ctx.report(GLIDESHIM_ERR_UNSUPPORTED,
                 "grLfbUnlock: glideShimRenderToTexture started during a pixel-pipeline write "
                 "lock; its pixels were not written");
      return FXFALSE;
    }
    if (ctx.lfb.write_origin == GR_ORIGIN_LOWER_LEFT) {
      flip_rows(pixels, row_bytes, h);
      flip_rows(original, row_bytes, h);
    }
    // Only pixels the program changed go back, so drawing done while the lock was held
    // survives, and untouched depth keeps its full precision. The write layout in effect now
    // decodes them; the constant alpha and depth are the lock's.
    const glide_shim::LfbWriteLayout &layout = ctx.lfb.layout;
    std::vector<glide_shim::LfbPixel> written, row_pixels(static_cast<std::size_t>(w));
    std::vector<bool> row_written(static_cast<std::size_t>(w));
    for (int row = 0; row < h; ++row) {
      const std::uint8_t *line = pixels.data() + static_cast<std::size_t>(row) * row_bytes;
      const std::uint8_t *was = original.data() + static_cast<std::size_t>(row) * row_bytes;
      std::fill(row_written.begin(), row_written.end(), false);
      bool any = false;
      for (int slot = 0; slot < w; ++slot) {
        const std::size_t offset = static_cast<std::size_t>(slot * bytes);
        if (std::memcmp(line + offset, was + offset, static_cast<std::size_t>(bytes)) == 0) continue;
        const int x = lfb_landing_x(slot, bytes, layout);
        if (x >= w) continue;  // a 16-bit pixel's partner beyond an odd-width row
        const std::uint32_t data = swizzled_lfb_data(load_lfb_data(line + offset, bytes), bytes, layout);
        glide_shim::LfbPixel pixel = expand_lfb_data(mode, layout.color_format, data,
                                                     ctx.lfb.write_alpha, ctx.lfb.write_depth);
        pixel.x = x, pixel.row = row;
        row_pixels[static_cast<std::size_t>(x)] = pixel;
        row_written[static_cast<std::size_t>(x)] = true;
        any = true;
      }
      if (!any) continue;
      if (!ctx.lfb.write_pipeline) {
        write_direct(buffer, lfb_mode_has_color(mode), lfb_mode_has_depth(mode), 0, row, w, 1, row_pixels, row_written);
        continue;
      }
      for (int x = 0; x < w; ++x) {
        if (row_written[static_cast<std::size_t>(x)]) written.push_back(row_pixels[static_cast<std::size_t>(x)]);
      }
    }
    if (ctx.lfb.write_pipeline) glide_shim::write_through_pipeline(ctx, buffer, lfb_mode_has_color(mode), written);
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
  // The SST-1 driver's grLfbWriteRegion is a write lock without the pipeline, so the write
  // layout (lanes, swizzle, swap) decodes the data as it does a lock's; the constant alpha and
  // depth play no part in a direct write.
  const auto mode = static_cast<GrLfbWriteMode_t>(src_format);
  const glide_shim::LfbWriteLayout &layout = ctx.lfb.layout;
  const int width = ctx.display.width, x = static_cast<int>(dst_x);
  const int w = static_cast<int>(src_width), h = static_cast<int>(src_height);
  // Each source column lands on one frame-buffer column; the swizzle can move a 16-bit column to
  // its partner, one beyond either end of the region.
  std::vector<int> landing(static_cast<std::size_t>(w));
  int first = width, last = -1;
  for (int col = 0; col < w; ++col) {
    const int lands = lfb_landing_x(x + col, bytes_per_pixel, layout);
    landing[static_cast<std::size_t>(col)] = lands;
    if (lands < width) first = std::min(first, lands), last = std::max(last, lands);
  }
  if (last < first) return FXTRUE;  // a single column that lands beyond an odd-width row
  const int span = last - first + 1;
  std::vector<glide_shim::LfbPixel> block(static_cast<std::size_t>(span * h));
  std::vector<bool> written(static_cast<std::size_t>(span), false);
  const auto *in = static_cast<const std::uint8_t *>(src_data);
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      const int lands = landing[static_cast<std::size_t>(col)];
      if (lands >= width) continue;
      const std::uint8_t *p = in + static_cast<std::size_t>(row) * static_cast<std::size_t>(src_stride) +
                              static_cast<std::size_t>(col) * static_cast<std::size_t>(bytes_per_pixel);
      const std::uint32_t data =
          swizzled_lfb_data(load_lfb_data(p, bytes_per_pixel), bytes_per_pixel, layout);
      block[static_cast<std::size_t>(row * span + lands - first)] = expand_lfb_data(
          mode, layout.color_format, data, ctx.lfb.constant_alpha, ctx.lfb.constant_depth);
      written[static_cast<std::size_t>(lands - first)] = true;
    }
  }
  write_direct(dst_buffer, color, depth, first, static_cast<int>(dst_y), span, h, block, written);
  return FXTRUE;
}

void grLfbWriteColorFormat(GrColorFormat_t colorFormat) {
  auto &ctx = current();
  if (!ctx.require_open("grLfbWriteColorFormat")) return;
  if (colorFormat < GR_COLORFORMAT_ARGB || colorFormat > GR_COLORFORMAT_BGRA) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grLfbWriteColorFormat: unknown colour format " + std::to_string(colorFormat));
    return;
  }
  ctx.lfb.layout.color_format = colorFormat;
}

void grLfbWriteColorSwizzle(FxBool swizzleBytes, FxBool swapWords) {
  auto &ctx = current();
  if (!ctx.require_open("grLfbWriteColorSwizzle")) return;
  ctx.lfb.layout.swizzle_bytes = swizzleBytes != FXFALSE;
  ctx.lfb.layout.swap_words = swapWords != FXFALSE;
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

}  // namespace glide_shim_api
