/* interactive_glide: an interactive Glide 2.x program in the style of the SDK's test programs.
 * A Gouraud-shaded pinwheel turns over a textured floor; the keyboard steers it. Run it in a
 * window with GLIDESHIM_BACKEND=sdl; headless it renders a fixed number of frames. Everything
 * is plain Glide except the shim's keyboard queries (glideShimPollKey, glideShimWindowClosed,
 * which stand in for the SDK's tlKbHit/tlGetCH) and the optional glideShimWritePng.
 *   Esc or q: quit   space: pause   Left/Right: turn slower/faster   g: gamma 1.0 <-> 1.7
 * The animation advances by frame, not by clock, so frame N is the same on every run. */
#define _POSIX_C_SOURCE 199309L /* nanosleep under -std=c99 */

#include <glide.h>
#include <glide_shim.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { kBlades = 6 };
enum { kHeadlessFrames = 60 }; /* without -n, headless: no key can ever stop the loop */

static FxU16 checker[64 * 64];

typedef struct {
  int frames;          /* -n: stop after this many frames; 0 = until Esc or the window closes */
  int hold;            /* --hold: after the last frame, keep the window until Esc */
  const char *png;     /* --png: write the last frame shown */
  GrScreenResolution_t resolution;
  int width, height;
} Options;

typedef struct {
  float angle;  /* radians, of the first blade */
  float speed;  /* radians per frame */
  int paused;
  float gamma;
} Animation;

static int parse_resolution(const char *text, Options *options) {
  static const struct {
    const char *name;
    GrScreenResolution_t resolution;
    int width, height;
  } kSizes[] = {{"512x384", GR_RESOLUTION_512x384, 512, 384},
                {"640x480", GR_RESOLUTION_640x480, 640, 480},
                {"800x600", GR_RESOLUTION_800x600, 800, 600}};
  size_t i;
  for (i = 0; i < sizeof kSizes / sizeof kSizes[0]; ++i) {
    if (strcmp(text, kSizes[i].name) == 0) {
      options->resolution = kSizes[i].resolution;
      options->width = kSizes[i].width;
      options->height = kSizes[i].height;
      return 1;
    }
  }
  return 0;
}

static int parse_options(int argc, char **argv, Options *options) {
  int i;
  options->frames = 0;
  options->hold = 0;
  options->png = NULL;
  parse_resolution("640x480", options);
  for (i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "-n") == 0 && i + 1 < argc) {
      char *end = NULL;
      long n = strtol(argv[++i], &end, 10);
      if (*end != '\0' || n < 1 || n > 1000000) {
        fprintf(stderr, "interactive_glide: -n needs a frame count 1..1000000\n");
        return 0;
      }
      options->frames = (int)n;
    } else if (strcmp(argv[i], "-r") == 0 && i + 1 < argc) {
      if (!parse_resolution(argv[++i], options)) {
        fprintf(stderr, "interactive_glide: -r takes 512x384, 640x480 or 800x600\n");
        return 0;
      }
    } else if (strcmp(argv[i], "--png") == 0 && i + 1 < argc) {
      options->png = argv[++i];
    } else if (strcmp(argv[i], "--hold") == 0) {
      options->hold = 1;
    } else {
      fprintf(stderr, "interactive_glide: unknown argument '%s'\n", argv[i]);
      return 0;
    }
  }
  return 1;
}

static void set_vertex(GrVertex *v, float x, float y, float w) {
  memset(v, 0, sizeof *v);
  v->x = x;
  v->y = y;
  v->oow = 1.0f / w;
}

static void draw_floor(const Options *options) {
  GrVertex a, b, c, d;
  const float width = (float)options->width, height = (float)options->height;
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  /* A floor receding to w = 8 at 55% of the screen height; s,t repeat the checker 16 times. */
  set_vertex(&a, 0.05f * width, 0.98f * height, 1.0f);
  set_vertex(&b, 0.95f * width, 0.98f * height, 1.0f);
  set_vertex(&c, 0.70f * width, 0.55f * height, 8.0f);
  set_vertex(&d, 0.30f * width, 0.55f * height, 8.0f);
  a.tmuvtx[0].sow = 0.0f;
  a.tmuvtx[0].tow = 0.0f;
  b.tmuvtx[0].sow = 1024.0f * b.oow;
  b.tmuvtx[0].tow = 0.0f;
  c.tmuvtx[0].sow = 1024.0f * c.oow;
  c.tmuvtx[0].tow = 1024.0f * c.oow;
  d.tmuvtx[0].sow = 0.0f;
  d.tmuvtx[0].tow = 1024.0f * d.oow;
  grDrawTriangle(&a, &b, &c);
  grDrawTriangle(&a, &c, &d);
}

static void draw_pinwheel(const Options *options, float angle) {
  const float cx = 0.5f * (float)options->width, cy = 0.42f * (float)options->height;
  const float radius = 0.3f * (float)options->height;
  GrVertex centre, tip, edge;
  int blade;
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  set_vertex(&centre, cx, cy, 0.5f);
  centre.r = centre.g = centre.b = 255.0f;
  for (blade = 0; blade < kBlades; ++blade) {
    const float a0 = angle + (float)blade * 6.2831853f / kBlades;
    const float a1 = a0 + 0.6f;
    set_vertex(&tip, cx + radius * cosf(a0), cy + radius * sinf(a0), 0.5f);
    set_vertex(&edge, cx + 0.6f * radius * cosf(a1), cy + 0.6f * radius * sinf(a1), 0.5f);
    tip.r = (blade % 3 == 0) ? 255.0f : 40.0f;
    tip.g = (blade % 3 == 1) ? 255.0f : 40.0f;
    tip.b = (blade % 3 == 2) ? 255.0f : 40.0f;
    edge.r = 0.5f * tip.r;
    edge.g = 0.5f * tip.g;
    edge.b = 0.5f * tip.b;
    /* Culling is off, so the winding of the blades does not matter. */
    grDrawTriangle(&centre, &tip, &edge);
  }
}

static void render_frame(const Options *options, const Animation *animation) {
  grBufferClear(0x00402010, 0, GR_WDEPTHVALUE_FARTHEST);
  draw_floor(options);
  draw_pinwheel(options, animation->angle);
  grBufferSwap(1);
}

/* Applies one key; returns 0 when the key asks to quit. */
static int handle_key(int key, Animation *animation) {
  printf("interactive_glide: key %d\n", key);
  fflush(stdout);
  switch (key) {
    case GLIDESHIM_KEY_ESCAPE:
    case 'q': return 0;
    case ' ': animation->paused = !animation->paused; break;
    case GLIDESHIM_KEY_LEFT: animation->speed -= 0.01f; break;
    case GLIDESHIM_KEY_RIGHT: animation->speed += 0.01f; break;
    case 'g':
      animation->gamma = animation->gamma == 1.0f ? 1.7f : 1.0f;
      grGammaCorrectionValue(animation->gamma);
      break;
    default: break;
  }
  return 1;
}

/* Reads every queued key; returns 0 when one of them, or the window's close button, quits. */
static int handle_input(Animation *animation) {
  int key;
  while ((key = glideShimPollKey()) != GLIDESHIM_KEY_NONE) {
    if (!handle_key(key, animation)) return 0;
  }
  return !glideShimWindowClosed();
}

static void setup_texture(void) {
  GrTexInfo info;
  int i;
  for (i = 0; i < 64 * 64; ++i) {
    checker[i] = (((i % 64) / 8 + (i / 64) / 8) % 2) ? 0x7BEF : 0x2945;
  }
  info.smallLod = GR_LOD_64;
  info.largeLod = GR_LOD_64;
  info.aspectRatio = GR_ASPECT_1x1;
  info.format = GR_TEXFMT_RGB_565;
  info.data = checker;
  grTexDownloadMipMap(GR_TMU0, grTexMinAddress(GR_TMU0), GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, grTexMinAddress(GR_TMU0), GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP);
}

int main(int argc, char **argv) {
  Options options;
  Animation animation = {0.0f, 0.03f, 0, 1.0f};
  GrHwConfiguration hw;
  int frame = 0, running = 1, windowed;
  const struct timespec poll_pause = {0, 10 * 1000 * 1000}; /* 10 ms between key polls */

  if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
    printf("usage: interactive_glide [-n FRAMES] [-r 512x384|640x480|800x600] [--png OUT.png] "
           "[--hold]\nRun with GLIDESHIM_BACKEND=sdl for a window. Keys: Esc/q quit, space "
           "pause, Left/Right speed, g gamma.\n");
    return 0;
  }
  if (!parse_options(argc, argv, &options)) return 2;
  grGlideInit();
  if (!grSstQueryHardware(&hw)) {
    fprintf(stderr, "interactive_glide: no Voodoo found: %s\n", glideShimGetLastErrorMessage());
    return 1;
  }
  grSstSelect(0);
  if (!grSstWinOpen(0, options.resolution, GR_REFRESH_60Hz, GR_COLORFORMAT_ABGR,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    fprintf(stderr, "interactive_glide: grSstWinOpen failed: %s\n",
            glideShimGetLastErrorMessage());
    return 1;
  }
  windowed = strcmp(glideShimBackendName(), "sdl") == 0;
  if (!windowed && options.frames == 0) options.frames = kHeadlessFrames;
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grCullMode(GR_CULL_DISABLE);
  setup_texture();

  while (running && (options.frames == 0 || frame < options.frames)) {
    render_frame(&options, &animation);
    ++frame;
    if (!animation.paused) animation.angle += animation.speed;
    running = handle_input(&animation);
  }
  if (options.png != NULL && !glideShimWritePng(GR_BUFFER_FRONTBUFFER, options.png)) {
    fprintf(stderr, "interactive_glide: %s\n", glideShimGetLastErrorMessage());
    grGlideShutdown();
    return 1;
  }
  printf("interactive_glide: %d frames at %dx%d (backend %s)\n", frame, options.width,
         options.height, glideShimBackendName());
  if (running && options.hold && windowed) {
    /* The last frame stays on screen; keys are still read and reported until Esc. */
    printf("interactive_glide: holding\n");
    fflush(stdout);
    while (handle_input(&animation)) nanosleep(&poll_pause, NULL);
  }
  grGlideShutdown();
  return 0;
}
