// Opening, resetting and reusing the window between inputs (window.h).
#include "glide_api/window.h"

#include "glide_api/arguments.h"
#include "glide_api/checks.h"
#include "gl/gl_renderer.h"

#include <glide_shim.h>

namespace glide_api_fuzz {

bool g_renderer_counts = false;

WindowRequest window_request(FuzzedDataProvider &in) {
  WindowRequest r{};
  // One input in 32 asks for a size of its own (a new GL context); the others share the run's.
  const bool own_size = in.ConsumeIntegralInRange(0, 31) == 0;
  r.width = own_size ? in.ConsumeIntegralInRange(1, 96) : kUsualWidth;
  r.height = own_size ? in.ConsumeIntegralInRange(1, 96) : kUsualHeight;
  // Valid arguments seven times in eight, so that most inputs get to their calls.
  const bool careless = in.ConsumeIntegralInRange(0, 7) == 0;
  r.format = careless ? enum_value(in, GR_COLORFORMAT_ARGB, GR_COLORFORMAT_BGRA)
                      : in.ConsumeIntegralInRange(GR_COLORFORMAT_ARGB, GR_COLORFORMAT_BGRA);
  r.origin = careless ? enum_value(in, GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT)
                      : in.ConsumeIntegralInRange(GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT);
  r.color_buffers = careless ? in.ConsumeIntegralInRange(1, 4) : in.ConsumeIntegralInRange(2, 3);
  r.aux_buffers = careless ? in.ConsumeIntegralInRange(-1, 2) : in.ConsumeIntegralInRange(0, 1);
  r.valid = r.format >= GR_COLORFORMAT_ARGB && r.format <= GR_COLORFORMAT_BGRA &&
            (r.origin == GR_ORIGIN_UPPER_LEFT || r.origin == GR_ORIGIN_LOWER_LEFT) &&
            r.color_buffers >= 2 && r.color_buffers <= 3 && r.aux_buffers >= 0 &&
            r.aux_buffers <= 1;
  return r;
}

bool open_window(const WindowRequest &r) {
  if (!glideShimSetWindowSize(r.width, r.height)) violated("glideShimSetWindowSize", "a valid size was refused");
  const bool already_open = glide_shim::current().display.open;
  const FxBool opened = grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, r.format, r.origin,
                                     r.color_buffers, r.aux_buffers);
  if (opened && (!r.valid || already_open)) violated("grSstWinOpen", "bad arguments were accepted");
  if (!opened && r.valid && !already_open && glide_shim::current().initialized)
    violated("grSstWinOpen", glideShimGetLastErrorMessage());
  if (opened && (grTexMinAddress(GR_TMU0) != 0 || glide_shim::current().display.width != r.width ||
                 glide_shim::current().display.height != r.height))
    violated("grSstWinOpen", "the window is not the size asked for");
  return opened != FXFALSE;
}

// Ends what the previous input left begun (plain GL, rendering to a texture, LFB locks), so
// that its queued work is drawn before the state is reset.
void finish_previous_input() {
  GlideContext &ctx = glide_shim::current();
  if (!ctx.display.open) return;
  if (ctx.plain_gl) glideShimEndGL();
  if (ctx.texture_target.active) glideShimRenderToFrameBuffer();
  if (ctx.lfb.write_locked) grLfbUnlock(GR_LFB_WRITE_ONLY, ctx.lfb.write_buffer);
  if (ctx.lfb.read_locked) grLfbUnlock(GR_LFB_READ_ONLY, GR_BUFFER_FRONTBUFFER);
  ctx.flush();
}

// The state reset between inputs that keep the run's window: every group back to what
// grSstWinOpen loads (GlideContext::load_window_defaults, the same function grSstWinOpen calls),
// the renderer's decoded textures dropped (TMU memory is zero again), guMPInit's multipass
// state, and both colour buffers and the depth buffer cleared. The renderer itself, with its
// compiled shaders, stays.
void reset_window(const WindowRequest &r) {
  GlideContext &ctx = glide_shim::current();
  ctx.load_window_defaults(r.width, r.height, r.format, r.origin);
  ctx.renderer->textures().invalidate(0, glide_shim::kTmuMemoryBytes);
  guMPInit();
  grDepthMask(FXTRUE);
  for (const GrBuffer_t buffer : {GR_BUFFER_FRONTBUFFER, GR_BUFFER_BACKBUFFER}) {
    grRenderBuffer(buffer);
    grBufferClear(0, 0, 0xFFFF);
  }
  grDepthMask(FXFALSE);  // back to the defaults: no depth writes, drawing to the back buffer
  grRenderBuffer(GR_BUFFER_BACKBUFFER);
  ctx.flush();
}


bool start_input(FuzzedDataProvider &in) {
  GlideContext &ctx = glide_shim::current();
  finish_previous_input();
  grErrorSetCallback(on_error);  // as set at start-up: the callback every check reads
  const WindowRequest r = window_request(in);
  if (!ctx.initialized) grGlideInit();
  const bool reusable = ctx.display.open && ctx.display.width == r.width &&
                        ctx.display.height == r.height && !g_renderer_counts;
  g_renderer_counts = false;
  if (reusable) {
    if (!r.valid) {
      // Careless arguments with the window open: refused as "already open".
      if (open_window(r)) violated("grSstWinOpen", "opened a second window");
    }
    WindowRequest usable = r;
    if (!r.valid) usable.format = GR_COLORFORMAT_ARGB, usable.origin = GR_ORIGIN_UPPER_LEFT;
    if (!glideShimSetWindowSize(r.width, r.height)) violated("glideShimSetWindowSize", "a valid size was refused");
    reset_window(usable);
    glideShimClearError();
    return true;
  }
  if (ctx.display.open) grSstWinClose();
  glideShimClearError();
  return open_window(r);
}

}  // namespace glide_api_fuzz
