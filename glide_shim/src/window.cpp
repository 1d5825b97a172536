// The shim's window extension (glide_shim.h): what a window backend shows at each swap, and
// the keyboard and close queries an interactive program polls. Glide 2.x itself has neither.
#include "window.h"

#include "context.h"
#include "frame_export.h"
#include "gl_renderer.h"

#include <cstdint>
#include <vector>

using glide_shim::current;

namespace glide_shim {

void show_front_buffer(GlideContext &context, int swap_interval) {
  Backend &backend = context.renderer->backend();
  if (!backend.shows_window()) return;
  const int w = context.display.width, h = context.display.height;
  std::vector<std::uint16_t> pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  GlRenderer &renderer = *context.renderer;
  renderer.read_color(renderer.buffer_index(GR_BUFFER_FRONTBUFFER), 0, 0, w, h, pixels.data(),
                      static_cast<std::size_t>(w) * 2);
  backend.set_swap_interval(swap_interval);
  backend.present(scan_out(pixels, context.display.gamma), w, h);
}

}  // namespace glide_shim

namespace {

// The open window's backend, with its pending events read; null headless or with no window.
glide_shim::Backend *window_backend() {
  auto &ctx = current();
  if (!ctx.display.open || !ctx.renderer) return nullptr;
  glide_shim::Backend &backend = ctx.renderer->backend();
  if (!backend.shows_window()) return nullptr;
  backend.pump_events();
  return &backend;
}

}  // namespace

extern "C" {

int glideShimPollKey(void) {
  glide_shim::Backend *backend = window_backend();
  return backend != nullptr ? backend->next_key() : GLIDESHIM_KEY_NONE;
}

FxBool glideShimWindowClosed(void) {
  glide_shim::Backend *backend = window_backend();
  return backend != nullptr && backend->close_requested() ? FXTRUE : FXFALSE;
}

}  // extern "C"
