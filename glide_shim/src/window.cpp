// The shim's window extension (glide_shim.h): what a window backend shows at each swap, and
// the keyboard and close queries an interactive program polls. Glide 2.x itself has neither.
#include "window.h"

#include "context.h"
#include "frame_export.h"
#include "gl/gl_renderer.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
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

void hold_last_frame(GlideContext &context) {
  const char *hold = std::getenv("GLIDESHIM_HOLD");
  if (hold == nullptr || std::strcmp(hold, "1") != 0) return;
  Backend &backend = context.renderer->backend();
  if (!backend.shows_window()) return;
  std::fprintf(stderr, "glideshim: holding the last frame (GLIDESHIM_HOLD=1): press a key in "
                       "the window or close it\n");
  std::fflush(stderr);
  // Keys typed while the program ran, which it never read, do not end the hold.
  backend.pump_events();
  while (backend.next_key() != 0) {
  }
  const timespec poll_interval{0, 20 * 1000 * 1000};
  for (;;) {
    backend.pump_events();
    if (backend.next_key() != 0 || backend.close_requested()) return;
    nanosleep(&poll_interval, nullptr);
  }
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

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

int glideShimPollKey(void) {
  glide_shim::Backend *backend = window_backend();
  return backend != nullptr ? backend->next_key() : GLIDESHIM_KEY_NONE;
}

FxBool glideShimWindowClosed(void) {
  glide_shim::Backend *backend = window_backend();
  return backend != nullptr && backend->close_requested() ? FXTRUE : FXFALSE;
}

}  // namespace glide_shim_api
