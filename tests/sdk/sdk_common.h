/* sdk_common.h: the start-up and shut-down the one-feature test programs share, as the Glide
 * SDK's test programs share tlib.c. Plain Glide 2.x: only <glide.h> and <glideutl.h>.
 * Each program opens 320x240 ABGR with the origin at the upper left, draws its frame `-n N`
 * times (default 1) with a buffer swap after each, and exits non-zero if Glide reported an
 * error through grErrorSetCallback. Frames are captured outside the program (for the tests,
 * by the shim's GLIDESHIM_DUMP_DIR). */
#ifndef SDK_COMMON_H
#define SDK_COMMON_H

#include <glide.h>
#include <glideutl.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int sdk_errors = 0;

static void sdk_on_error(const char *message, FxBool fatal) {
  fprintf(stderr, "glide error%s: %s\n", fatal ? " (fatal)" : "", message);
  ++sdk_errors;
}

/* Parses -n FRAMES, starts Glide and opens the window; 0 on failure. */
static int sdk_open(const char *name, int argc, char **argv, int *frames) {
  GrHwConfiguration hw;
  int i;
  *frames = 1;
  for (i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "-n") == 0 && i + 1 < argc) {
      *frames = atoi(argv[++i]);
    } else {
      fprintf(stderr, "usage: %s [-n FRAMES]\n", name);
      return 0;
    }
  }
  grGlideInit();
  grErrorSetCallback(sdk_on_error);
  if (!grSstQueryHardware(&hw)) {
    fprintf(stderr, "%s: no Voodoo found\n", name);
    return 0;
  }
  grSstSelect(0);
  if (!grSstWinOpen(0, GR_RESOLUTION_320x240, GR_REFRESH_60Hz, GR_COLORFORMAT_ABGR,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    fprintf(stderr, "%s: grSstWinOpen failed\n", name);
    return 0;
  }
  return 1;
}

/* A vertex with screen position, 1/w and colour; every other field zero. */
static GrVertex sdk_vertex(float x, float y, float w, float r, float g, float b, float a) {
  GrVertex v;
  memset(&v, 0, sizeof v);
  v.x = x, v.y = y, v.oow = 1.0f / w;
  v.r = r, v.g = g, v.b = b, v.a = a;
  return v;
}

/* A textured quad from its four corners (screen x, y; w; s and t in texels of the largest level,
 * 0..256 across it), drawn as two triangles with s/w and t/w as the TMU iterates them. */
static inline void sdk_textured_quad(const float *xs, const float *ys, const float *ws,
                                     const float *ss, const float *ts) {
  GrVertex v[4];
  int k;
  for (k = 0; k < 4; ++k) {
    v[k] = sdk_vertex(xs[k], ys[k], ws[k], 0, 0, 0, 255);
    v[k].tmuvtx[0].sow = ss[k] * v[k].oow;
    v[k].tmuvtx[0].tow = ts[k] * v[k].oow;
  }
  grDrawTriangle(&v[0], &v[1], &v[2]);
  grDrawTriangle(&v[0], &v[2], &v[3]);
}

static int sdk_close(void) {
  grGlideShutdown();
  return sdk_errors == 0 ? 0 : 1;
}

#endif
