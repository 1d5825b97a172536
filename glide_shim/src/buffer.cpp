// Chapter "buffers": clear, swap, the render buffer, the clip window and colour mask, and the
// shim's frame export (glideShimWritePng, and a PNG per swap when GLIDESHIM_DUMP_DIR is set).
#include "context.h"
#include "depth.h"
#include "frame_export.h"
#include "gl/gl_renderer.h"

#include "texture_layout.h"
#include "window.h"

#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <string>

using glide_shim::current;

namespace {

bool is_color_buffer(GrBuffer_t buffer) {
  return buffer == GR_BUFFER_FRONTBUFFER || buffer == GR_BUFFER_BACKBUFFER;
}

bool export_buffer(GrBuffer_t buffer, const std::string &path, std::string &error) {
  auto &ctx = current();
  const int w = ctx.display.width, h = ctx.display.height;
  std::vector<std::uint16_t> pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  ctx.renderer->read_color(ctx.renderer->buffer_index(buffer), 0, 0, w, h, pixels.data(),
                           static_cast<std::size_t>(w) * 2);
  return glide_shim::write_png(path, w, h, glide_shim::scan_out(pixels, ctx.display.gamma),
                               error);
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grBufferClear(GrColor_t color, GrAlpha_t alpha, FxU16 depth) {
  (void)alpha;  // the aux buffer holds depth, so there are no alpha planes to clear
  auto &ctx = current();
  if (!ctx.require_open("grBufferClear")) return;
  const glide_shim::Rgba8 c = glide_shim::unpack_color(color, ctx.display.color_format);
  // The fast fill writes the colour truncated to 565, like any pixel with dithering off.
  const auto rgb565 = static_cast<std::uint16_t>(((c.r >> 3) << 11) | ((c.g >> 2) << 5) | (c.b >> 3));
  const bool w_buffer = glide_shim::is_w_buffer(ctx.depth.mode);
  ctx.renderer->clear(rgb565, true, glide_shim::gl_depth_from_code(depth, w_buffer),
                      ctx.depth.mask);
}

void grBufferSwap(int swap_interval) {
  auto &ctx = current();
  if (!ctx.require_open("grBufferSwap")) return;
  if (swap_interval < 0 || swap_interval > 255) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grBufferSwap: swap interval " + std::to_string(swap_interval) + " outside 0..255");
    return;
  }
  ctx.renderer->swap_buffers();
  glide_shim::show_front_buffer(ctx, swap_interval);
  const int frame = ctx.display.swaps++;
  const char *dir = std::getenv("GLIDESHIM_DUMP_DIR");
  if (dir != nullptr && *dir != '\0') {
    std::error_code ignored;  // a directory that cannot be examined counts as missing
    if (!std::filesystem::is_directory(dir, ignored)) {
      if (!ctx.display.dump_dir_missing_reported) {
        ctx.display.dump_dir_missing_reported = true;
        ctx.report(GLIDESHIM_ERR_BACKEND, std::string("grBufferSwap: GLIDESHIM_DUMP_DIR '") + dir +
                                              "' is not an existing directory: no frames are written");
      }
      return;
    }
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%05d.png", frame);
    std::string error;
    if (!export_buffer(GR_BUFFER_FRONTBUFFER, dir + std::string(name), error)) {
      ctx.report(GLIDESHIM_ERR_BACKEND, "grBufferSwap: frame dump: " + error);
    }
  }
}

int grBufferNumPending(void) {
  auto &ctx = current();
  if (!ctx.require_open("grBufferNumPending")) return 0;
  return 0;  // a swap takes effect at once: none is ever waiting for the retrace
}

void grRenderBuffer(GrBuffer_t buffer) {
  auto &ctx = current();
  if (!ctx.require_open("grRenderBuffer")) return;
  if (!is_color_buffer(buffer)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grRenderBuffer: buffer must be GR_BUFFER_FRONTBUFFER or GR_BUFFER_BACKBUFFER");
    return;
  }
  if (buffer == ctx.raster.render_buffer) return;
  ctx.flush();
  ctx.raster.render_buffer = buffer;
}

void grClipWindow(FxU32 minx, FxU32 miny, FxU32 maxx, FxU32 maxy) {
  auto &ctx = current();
  if (!ctx.require_open("grClipWindow")) return;
  // Inside glideShimRenderToTexture the clip window lives in the target square.
  const auto width = static_cast<FxU32>(ctx.texture_target.active ? ctx.texture_target.side : ctx.display.width);
  const auto height = static_cast<FxU32>(ctx.texture_target.active ? ctx.texture_target.side : ctx.display.height);
  if (minx > maxx || miny > maxy || maxx > width || maxy > height) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grClipWindow: (" + std::to_string(minx) + "," + std::to_string(miny) + ")-(" +
                   std::to_string(maxx) + "," + std::to_string(maxy) + ") is not inside the " +
                   std::to_string(width) + "x" + std::to_string(height) + " screen");
    return;
  }
  ctx.flush();
  ctx.raster.clip = {minx, miny, maxx, maxy};
}

void grColorMask(FxBool rgb, FxBool a) {
  auto &ctx = current();
  if (!ctx.require_open("grColorMask")) return;
  ctx.flush();
  ctx.raster.rgb_mask = rgb != FXFALSE;
  ctx.raster.alpha_mask = a != FXFALSE;  // no alpha planes beside a depth buffer: stored only
}

FxBool glideShimWritePng(GrBuffer_t buffer, const char *path) {
  auto &ctx = current();
  if (!ctx.require_open("glideShimWritePng")) return FXFALSE;
  if (!is_color_buffer(buffer)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "glideShimWritePng: not a colour buffer");
    return FXFALSE;
  }
  if (path == nullptr || *path == '\0') {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "glideShimWritePng: path is NULL or empty");
    return FXFALSE;
  }
  std::string error;
  if (!export_buffer(buffer, path, error)) {
    ctx.report(GLIDESHIM_ERR_BACKEND, "glideShimWritePng: " + error);
    return FXFALSE;
  }
  return FXTRUE;
}

FxBool glideShimRenderToTexture(GrChipID_t tmu, FxU32 startAddress, GrLOD_t lod) {
  auto &ctx = current();
  if (!ctx.require_open("glideShimRenderToTexture")) return FXFALSE;
  if (tmu != GR_TMU0) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "glideShimRenderToTexture: TMU must be GR_TMU0");
    return FXFALSE;
  }
  if (!glide_shim::is_lod(lod)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "glideShimRenderToTexture: lod must be GR_LOD_256..GR_LOD_1");
    return FXFALSE;
  }
  if (ctx.texture_target.active) {
    ctx.report(GLIDESHIM_ERR_INCONSISTENT, "glideShimRenderToTexture: already rendering to a texture");
    return FXFALSE;
  }
  const int side = 256 >> lod;
  const auto bytes = static_cast<FxU32>(side * side * 2);
  if (startAddress % 8 != 0 || startAddress > glide_shim::kTmuMemoryBytes ||
      bytes > glide_shim::kTmuMemoryBytes - startAddress) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "glideShimRenderToTexture: a " + std::to_string(side) +
                                               "x" + std::to_string(side) + " target at " +
                                               std::to_string(startAddress) +
                                               " is misaligned or beyond TMU memory");
    return FXFALSE;
  }
  ctx.flush();
  ctx.texture_target = {true, startAddress, side, ctx.raster.clip};
  ctx.raster.clip = {0, 0, static_cast<FxU32>(side), static_cast<FxU32>(side)};
  ctx.renderer->begin_texture_target(side);
  return FXTRUE;
}

void glideShimRenderToFrameBuffer(void) {
  auto &ctx = current();
  if (!ctx.require_open("glideShimRenderToFrameBuffer")) return;
  if (!ctx.texture_target.active) return;  // already there: harmless, like grSstWinClose twice
  glide_shim::TextureTarget &target = ctx.texture_target;
  std::vector<std::uint16_t> words(static_cast<std::size_t>(target.side) * target.side);
  ctx.renderer->end_texture_target(words.data());
  const auto bytes = static_cast<FxU32>(words.size() * 2);
  std::memcpy(ctx.tmu.memory.data() + target.address, words.data(), bytes);
  ctx.renderer->textures().invalidate(target.address, target.address + bytes);
  ctx.raster.clip = target.saved_clip;
  target.active = false;
}

FxU32 glideShimPixelsWritten(void) {
  auto &ctx = current();
  if (!ctx.require_open("glideShimPixelsWritten")) return 0;
  ctx.flush();
  return ctx.renderer->pixels_counted();
}

void glideShimResetPixelsWritten(void) {
  auto &ctx = current();
  if (!ctx.require_open("glideShimResetPixelsWritten")) return;
  ctx.renderer->start_counting();
}

}  // namespace glide_shim_api
