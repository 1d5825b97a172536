// glide_api_fuzz: decodes its input into a sequence of Glide 2.x calls with random arguments
// and after every call checks what must hold whatever the arguments were:
//   - a call that reported an error left every state group of the context as it was;
//   - an error is never reported without a message, and the callback saw the same message;
//   - the open window's groups stay in range (clip inside the target, TMU memory whole, LFB
//     copies the screen's size);
//   - round trips: 565 words written with grLfbWriteRegion read back unchanged,
//     grTexTextureMemRequired agrees with grTexCalcMemRequired for the same texture, restoring
//     grGlideGetState's block changes nothing, and grSstScreenWidth/Height give the window's size;
//   - a polygon with a vertex count far beyond its array (over 65,536) is refused unread;
//   - the gu texture manager never hands out memory past the TMU's end or an id twice.
// Any violation aborts, which libFuzzer reports as a crash with the input that caused it.
//
// Speed: one window (GL context) serves the whole run. Between inputs the context is reset to
// what grSstWinOpen loads (reset_window below), so the renderer and its compiled shaders are
// kept; only an input that asks for another window size, or that closes the window, pays for a
// new GL context. Every public entry point of glide.h, glideutl.h and glide_shim.h is called
// (entry point table in fuzz/README.md).
//
// The harness is in glide_api/: checks.h (the rules after every call), snapshot.h (the state
// compared), arguments.h, window.h, calls.h (the call menu).
#include "glide_api/calls.h"
#include "glide_api/checks.h"
#include "glide_api/window.h"

#include <fuzzer/FuzzedDataProvider.h>
#include <glide.h>
#include <glide_shim.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <string>

using namespace glide_api_fuzz;

extern "C" int LLVMFuzzerInitialize(int *argc, char ***argv) {
  (void)argc, (void)argv;
  grErrorSetCallback(on_error);
  // Files the calls read and write (.3df inputs, PNGs) go beside the binary, in the build tree.
  char exe[4096] = {};
  const ssize_t length = readlink("/proc/self/exe", exe, sizeof exe - 1);
  std::string dir = length > 0 ? std::string(exe, static_cast<std::size_t>(length)) : std::string("./x");
  dir = dir.substr(0, dir.rfind('/'));
  g_scratch = dir + "/glide_api_fuzz.files";
  mkdir(g_scratch.c_str(), 0755);
  // The run's window, opened before the first input; the shim closes it at exit.
  grGlideInit();
  WindowRequest usual{kUsualWidth, kUsualHeight, GR_COLORFORMAT_ARGB, GR_ORIGIN_UPPER_LEFT, 2, 1, true};
  if (!open_window(usual)) violated("grSstWinOpen", "the run's window did not open");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  g_thorough = in.ConsumeIntegralInRange(0, 7) == 0 ? kAll : kSmall;
  g_have_saved_state = false;
  if (!start_input(in)) return 0;
  // Sides of the drawable area, for arguments near the screen's edges.
  const float span = static_cast<float>(std::max(glide_shim::current().display.width,
                                                 glide_shim::current().display.height));
  for (int calls = 0; calls < 48 && in.remaining_bytes() > 0; ++calls) one_call(in, span);
  return 0;
}
