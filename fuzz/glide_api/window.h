// The window each input draws in: the run's, reset between inputs (so that its GL context and
// compiled shaders are kept), or a new one when the input asks for another size.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>
#include <glide.h>

namespace glide_api_fuzz {

// The size most inputs use, so that their GL context (and its compiled shaders) is the run's.
constexpr int kUsualWidth = 64, kUsualHeight = 48;

struct WindowRequest {
  int width, height;
  GrColorFormat_t format;
  GrOriginLocation_t origin;
  int color_buffers, aux_buffers;
  bool valid;
};

WindowRequest window_request(FuzzedDataProvider &in);

// Set when an input started the renderer's pixel counting (glideShimResetPixelsWritten), which
// nothing turns off: the next input then opens a new window instead of resetting this one.
extern bool g_renderer_counts;

// grSstWinOpen with the request's arguments, checking that it opens exactly when it should.
bool open_window(const WindowRequest &r);

// Gives the input a window as it asks: the run's, reset, when it has that size, else a new one.
// False when the input's (careless) arguments were refused and no window is open.
bool start_input(FuzzedDataProvider &in);

}  // namespace glide_api_fuzz
