// Chapter "SST routines": library start-up and shutdown, the hardware query (one Voodoo 1 with
// one TMU), opening and closing the window, origin and hints, the status and retrace queries,
// and the splash and logo calls (no-ops).
#include "context.h"
#include "gl/gl_renderer.h"
#include "window.h"

#include <cstring>
#include <string>

using glide_shim::current;

namespace {

struct Resolution {
  int width, height;
};

bool resolution_size(GrScreenResolution_t resolution, Resolution &size) {
  static const Resolution kSizes[] = {{320, 200},  {320, 240},  {400, 256},  {512, 384},
                                      {640, 200},  {640, 350},  {640, 400},  {640, 480},
                                      {800, 600},  {960, 720},  {856, 480},  {512, 256},
                                      {1024, 768}, {1280, 1024}, {1600, 1200}, {400, 300}};
  if (resolution == GR_RESOLUTION_NONE) {
    const auto &display = current().display;
    size = {display.none_width, display.none_height};
    return true;
  }
  if (resolution < 0 || resolution > GR_RESOLUTION_400x300) return false;
  size = kSizes[resolution];
  return true;
}

bool is_color_format(GrColorFormat_t format) {
  return format == GR_COLORFORMAT_ARGB || format == GR_COLORFORMAT_ABGR ||
         format == GR_COLORFORMAT_RGBA || format == GR_COLORFORMAT_BGRA;
}

bool is_origin(GrOriginLocation_t origin) {
  return origin == GR_ORIGIN_UPPER_LEFT || origin == GR_ORIGIN_LOWER_LEFT;
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grGlideInit(void) {
  auto &ctx = current();
  if (ctx.display.open) grSstWinClose();
  ctx.initialized = true;
}

void grGlideShutdown(void) {
  auto &ctx = current();
  if (ctx.display.open) grSstWinClose();
  ctx.initialized = false;
}

void grGlideGetVersion(char version[80]) {
  if (version == nullptr) {
    current().report(GLIDESHIM_ERR_NULL_POINTER, "grGlideGetVersion: version is NULL");
    return;
  }
  std::strncpy(version, "Glide Version 2.46 (glideshadows shim over OpenGL)", 79);
  version[79] = '\0';
}

FxBool grSstQueryBoards(GrHwConfiguration *hwconfig) {
  if (hwconfig == nullptr) {
    current().report(GLIDESHIM_ERR_NULL_POINTER, "grSstQueryBoards: hwconfig is NULL");
    return FXFALSE;
  }
  std::memset(hwconfig, 0, sizeof *hwconfig);
  hwconfig->num_sst = 1;
  return FXTRUE;
}

FxBool grSstQueryHardware(GrHwConfiguration *hwconfig) {
  auto &ctx = current();
  if (hwconfig == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grSstQueryHardware: hwconfig is NULL");
    return FXFALSE;
  }
  if (!ctx.initialized) {
    ctx.report(GLIDESHIM_ERR_NOT_INITIALIZED, "grSstQueryHardware: call grGlideInit first");
    return FXFALSE;
  }
  std::memset(hwconfig, 0, sizeof *hwconfig);
  hwconfig->num_sst = 1;
  hwconfig->SSTs[0].type = GR_SSTTYPE_VOODOO;
  GrVoodooConfig_t &voodoo = hwconfig->SSTs[0].sstBoard.VoodooConfig;
  voodoo.fbRam = 2;  // MB of frame buffer: two 640x480x16 colour buffers and the aux buffer
  voodoo.fbiRev = 2;
  voodoo.nTexelfx = 1;
  voodoo.sliDetect = FXFALSE;
  voodoo.tmuConfig[0].tmuRev = 1;
  voodoo.tmuConfig[0].tmuRam = static_cast<int>(glide_shim::kTmuMemoryBytes >> 20);
  return FXTRUE;
}

void grSstSelect(int which_sst) {
  auto &ctx = current();
  if (which_sst != 0) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grSstSelect: board " + std::to_string(which_sst) + " does not exist (one board)");
  }
}

FxBool grSstWinOpen(FxU32 hWnd, GrScreenResolution_t screen_resolution,
                    GrScreenRefresh_t refresh_rate, GrColorFormat_t color_format,
                    GrOriginLocation_t origin_location, int nColBuffers, int nAuxBuffers) {
  (void)hWnd;  // headless: there is no window to attach to
  (void)refresh_rate;
  auto &ctx = current();
  if (!ctx.initialized) {
    ctx.report(GLIDESHIM_ERR_NOT_INITIALIZED, "grSstWinOpen: call grGlideInit first");
    return FXFALSE;
  }
  if (ctx.display.open) {
    ctx.report(GLIDESHIM_ERR_INCONSISTENT, "grSstWinOpen: a window is already open");
    return FXFALSE;
  }
  Resolution size{};
  if (!resolution_size(screen_resolution, size)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grSstWinOpen: unknown screen resolution " +
                                               std::to_string(screen_resolution));
    return FXFALSE;
  }
  if (!is_color_format(color_format)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grSstWinOpen: unknown colour format " + std::to_string(color_format));
    return FXFALSE;
  }
  if (!is_origin(origin_location)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grSstWinOpen: origin must be GR_ORIGIN_UPPER_LEFT or GR_ORIGIN_LOWER_LEFT");
    return FXFALSE;
  }
  if (nColBuffers < 2 || nColBuffers > 3 || nAuxBuffers < 0 || nAuxBuffers > 1) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grSstWinOpen: nColBuffers must be 2 or 3 and nAuxBuffers 0 or 1");
    return FXFALSE;
  }
  glide_shim::BackendKind kind{};
  std::string error;
  if (!glide_shim::backend_from_environment(kind, error)) {
    ctx.report(GLIDESHIM_ERR_BACKEND, "grSstWinOpen: " + error);
    return FXFALSE;
  }
  auto renderer = glide_shim::GlRenderer::create(ctx, kind, size.width, size.height, error);
  if (!renderer) {
    ctx.report(GLIDESHIM_ERR_BACKEND, "grSstWinOpen: " + error);
    return FXFALSE;
  }
  ctx.load_window_defaults(size.width, size.height, color_format, origin_location);
  ctx.renderer = std::move(renderer);
  glide_shim::close_window_at_exit();
  return FXTRUE;
}

void grSstWinClose(void) {
  auto &ctx = current();
  if (!ctx.display.open) return;  // closing twice is harmless, as in Glide
  ctx.flush();
  glide_shim::hold_last_frame(ctx);
  ctx.renderer.reset();
  ctx.plain_gl = false;  // a GL context lent by glideShimBeginGL is gone with the window
  ctx.display.open = false;
  ctx.tmu.memory.clear();
  ctx.tmu.memory.shrink_to_fit();
}

void grSstIdle(void) {
  auto &ctx = current();
  if (!ctx.require_open("grSstIdle")) return;
  ctx.flush();
  ctx.renderer->gl().glFinish();
}

void glideShimFlush(void) {
  auto &ctx = current();
  if (!ctx.require_open("glideShimFlush")) return;
  ctx.flush();
  ctx.renderer->gl().glFlush();
}

FxU32 grSstScreenWidth(void) {
  auto &ctx = current();
  if (!ctx.require_open("grSstScreenWidth")) return 0;
  return static_cast<FxU32>(ctx.display.width);
}

FxU32 grSstScreenHeight(void) {
  auto &ctx = current();
  if (!ctx.require_open("grSstScreenHeight")) return 0;
  return static_cast<FxU32>(ctx.display.height);
}

// Every draw has finished by the time a Glide call returns to the program (the GL work is
// flushed on demand), so the board is never busy and there is no scan-out to wait for.
FxBool grSstIsBusy(void) {
  auto &ctx = current();
  if (!ctx.require_open("grSstIsBusy")) return FXFALSE;
  return FXFALSE;
}

FxBool grSstVRetraceOn(void) {
  auto &ctx = current();
  if (!ctx.require_open("grSstVRetraceOn")) return FXFALSE;
  return FXTRUE;  // headless: always in the vertical blank, so retrace waits end at once
}

FxU32 grSstVideoLine(void) {
  auto &ctx = current();
  if (!ctx.require_open("grSstVideoLine")) return 0;
  return 0;  // the beam is in the vertical blank, at line 0
}

FxU32 grSstStatus(void) {
  auto &ctx = current();
  if (!ctx.require_open("grSstStatus")) return 0;
  // SST-1 status register: PCI FIFO free (bits 5:0, all 0x3F free), vertical retrace (bit 6),
  // FBI/TMU/SST busy (bits 7-9, all idle), the displayed buffer (bits 11:10), memory FIFO free
  // (bits 27:12, all free) and swaps pending (bits 30:28, none).
  const FxU32 displayed = static_cast<FxU32>(ctx.renderer->buffer_index(GR_BUFFER_FRONTBUFFER));
  return 0x3Fu | (1u << 6) | (displayed << 10) | (0xFFFFu << 12);
}

FxBool grSstControl(FxU32 code) {
  auto &ctx = current();
  if (!ctx.require_open("grSstControl")) return FXFALSE;
  if (code < GR_CONTROL_ACTIVATE || code > GR_CONTROL_MOVE) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grSstControl: unknown code " + std::to_string(code));
    return FXFALSE;
  }
  return FXTRUE;  // activating, hiding, resizing or moving a window: nothing to do headless
}

void grCheckForRoom(FxI32 n) {
  (void)n;  // the command FIFO is the shim's queue, which always has room
}

void grSplash(float x, float y, float width, float height, FxU32 frame) {
  // The 3dfx start-up animation is not part of the shim: a harmless no-op, as when the splash
  // is disabled (FX_GLIDE_NO_SPLASH).
  (void)x, (void)y, (void)width, (void)height, (void)frame;
}

void grGlideShamelessPlug(const FxBool on) {
  (void)on;  // the 3dfx logo overlay is not drawn
}

void grSstOrigin(GrOriginLocation_t origin) {
  auto &ctx = current();
  if (!ctx.require_open("grSstOrigin")) return;
  if (!is_origin(origin)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grSstOrigin: unknown origin " + std::to_string(origin));
    return;
  }
  if (origin == ctx.raster.origin) return;
  ctx.flush();
  ctx.raster.origin = origin;
}

void grHints(GrHint_t type, FxU32 hintMask) {
  auto &ctx = current();
  if (!ctx.require_open("grHints")) return;
  if (type == GR_HINT_ALLOW_MIPMAP_DITHER) {
    // Read by the next grTexMipMapMode, as the driver does: it alone sets the LOD dither bit.
    ctx.tmu.allow_lod_dither = hintMask != 0;
    return;
  }
  if (type != GR_HINT_STWHINT) {
    // FIFO hints tune the hardware; they change no pixel here.
    if (type > GR_HINTTYPE_MAX) {
      ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grHints: unknown hint type " + std::to_string(type));
    }
    return;
  }
  if (hintMask == ctx.raster.stw_hint) return;
  ctx.flush();
  ctx.raster.stw_hint = hintMask;
}

const char *glideShimBackendName(void) {
  auto &ctx = current();
  return ctx.renderer ? ctx.renderer->backend_name() : "";
}

FxBool glideShimSetWindowSize(int width, int height) {
  auto &ctx = current();
  if (width < 1 || height < 1 || width > glide_shim::kMaxScreenSide ||
      height > glide_shim::kMaxScreenSide) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "glideShimSetWindowSize: " + std::to_string(width) + "x" + std::to_string(height) +
                   " is outside 1..2048 per side");
    return FXFALSE;
  }
  ctx.display.none_width = width;
  ctx.display.none_height = height;
  return FXTRUE;
}

}  // namespace glide_shim_api
