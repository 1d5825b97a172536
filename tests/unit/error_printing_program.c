/* A Glide program that makes bad calls, for error_printing_test.cpp: which lines the shim
 * prints to stderr with and without an error callback. Its own output is only its callback's,
 * one "callback: <message>" line on stdout per error; it exits 1 if a call did not record the
 * error it should have, 2 on a bad command line. */
#include <glide.h>
#include <glide_shim.h>

#include <stdio.h>
#include <string.h>

static void print_error(const char *message, FxBool fatal) {
  printf("callback: %s%s\n", message, fatal ? " (fatal)" : "");
}

/* Three bad clip windows (one message), two bad blend factors (another): five errors. */
static int repeated_errors(void) {
  int i, recorded = 0;
  for (i = 0; i < 3; ++i) {
    glideShimClearError();
    grClipWindow(0, 0, 5000, 10);
    recorded += glideShimGetLastError() == GLIDESHIM_ERR_OUT_OF_RANGE;
  }
  for (i = 0; i < 2; ++i) {
    glideShimClearError();
    grAlphaBlendFunction(99, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
    recorded += glideShimGetLastError() == GLIDESHIM_ERR_INVALID_ENUM;
  }
  return recorded == 5;
}

/* 100 clip windows, each out of the screen by a different amount: 100 different messages. */
static int many_errors(void) {
  FxU32 i;
  for (i = 0; i < 100; ++i) grClipWindow(0, 0, 1000 + i, 10);
  return glideShimGetLastError() == GLIDESHIM_ERR_OUT_OF_RANGE;
}

/* Two swaps: with GLIDESHIM_DUMP_DIR set, each tries to write a frame. */
static int swaps(void) {
  grBufferClear(0, 0, 0);
  grBufferSwap(1);
  grBufferClear(0, 0, 0);
  grBufferSwap(1);
  return 1;
}

int main(int argc, char **argv) {
  int ok;
  const char *mode = argc > 2 ? argv[2] : "";
  if (argc != 3) return 2;
  grGlideInit();
  if (strcmp(argv[1], "callback") == 0) {
    grErrorSetCallback(print_error);
  } else if (strcmp(argv[1], "no-callback") != 0) {
    return 2;
  }
  glideShimSetWindowSize(64, 64);
  if (!grSstWinOpen(0, GR_RESOLUTION_NONE, GR_REFRESH_60Hz, GR_COLORFORMAT_ARGB,
                    GR_ORIGIN_UPPER_LEFT, 2, 1))
    return 1;
  if (strcmp(mode, "repeated") == 0) {
    ok = repeated_errors();
  } else if (strcmp(mode, "many") == 0) {
    ok = many_errors();
  } else if (strcmp(mode, "swaps") == 0) {
    ok = swaps();
  } else {
    return 2;
  }
  grGlideShutdown();
  return ok ? 0 : 1;
}
