/* crate_3df: a Glide 2.x program in the style of the 3dfx SDK's test programs. It opens the
 * screen at 640x480 with ABGR colours, reads its textures from .3df files, and draws a lit crate
 * turning over a fogged, mip-mapped tile floor, with an alpha-blended logo in the corner, for
 * `-n` frames. Plain Glide 2.x C: <glide.h> and <glideutl.h> only, nothing of the shim's own
 * (no glide_shim.h), as an old program would be.
 *
 *   crate_3df [-n FRAMES] [-d TEXTURE_DIR]
 *
 * The textures (crate.3df RGB565 mip-mapped, floor.3df P8 mip-mapped with its palette,
 * logo.3df ARGB4444) are made by examples/data/make_textures.py. Frame N is the same on every run:
 * the animation advances by frame, not by clock. Run it in a window with GLIDESHIM_BACKEND=sdl
 * (GLIDESHIM_HOLD=1 keeps the last frame up until a key), or headless with GLIDESHIM_DUMP_DIR
 * set to keep every frame as a PNG. */
#include <glide.h>
#include <glideutl.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kWidth = 640, kHeight = 480 };
enum { kDefaultFrames = 600 };

/* Camera space: the eye at the origin looking down +z, y up, in crate half-widths. */
static const float kFocal = 480.0f;              /* pixels per unit of x/z */
static const float kFloorY = -1.8f;              /* the floor plane */
static const float kFloorNear = 2.5f, kFloorFar = 40.0f, kFloorHalfWidth = 14.0f;
static const float kTileSize = 2.0f;             /* world units per repeat of floor.3df */
static const float kCrateZ = 7.5f;               /* the crate's centre */
static const GrColor_t kFogColor = 0x00b09070;   /* ABGR: a pale blue haze */

static int glide_errors = 0;

static void on_glide_error(const char *message, FxBool fatal) {
  fprintf(stderr, "crate_3df: glide error%s: %s\n", fatal ? " (fatal)" : "", message);
  ++glide_errors;
}

typedef struct {
  int frames;
  const char *texture_dir;
} Options;

static int parse_options(int argc, char **argv, Options *options) {
  int i;
  options->frames = kDefaultFrames;
  options->texture_dir = ".";
  for (i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "-n") == 0 && i + 1 < argc) {
      char *end;
      long frames = strtol(argv[++i], &end, 10);
      if (*end != '\0' || frames < 1 || frames > 1000000) {
        fprintf(stderr, "crate_3df: -n takes a frame count from 1 to 1000000, not '%s'\n", argv[i]);
        return 0;
      }
      options->frames = (int)frames;
    } else if (strcmp(argv[i], "-d") == 0 && i + 1 < argc) {
      options->texture_dir = argv[++i];
    } else {
      return 0;
    }
  }
  return 1;
}

/* A texture read from TEXTURE_DIR/name, downloaded at `*address`, which then moves past it. */
typedef struct {
  Gu3dfInfo file;
  GrTexInfo info;
  FxU32 address;
} Texture;

static int load_texture(const char *dir, const char *name, FxU32 *address, Texture *texture) {
  char path[1024];
  if (snprintf(path, sizeof path, "%s/%s", dir, name) >= (int)sizeof path) {
    fprintf(stderr, "crate_3df: the texture path %s/%s is too long\n", dir, name);
    return 0;
  }
  if (!gu3dfGetInfo(path, &texture->file)) {
    fprintf(stderr, "crate_3df: cannot read %s (make it with examples/data/make_textures.py, or "
                    "give its directory with -d)\n", path);
    return 0;
  }
  texture->file.data = malloc(texture->file.mem_required);
  if (texture->file.data == NULL || !gu3dfLoad(path, &texture->file)) {
    fprintf(stderr, "crate_3df: cannot load %s\n", path);
    return 0;
  }
  texture->info.smallLod = texture->file.header.small_lod;
  texture->info.largeLod = texture->file.header.large_lod;
  texture->info.aspectRatio = texture->file.header.aspect_ratio;
  texture->info.format = texture->file.header.format;
  texture->info.data = texture->file.data;
  texture->address = *address;
  if (texture->info.format == GR_TEXFMT_P_8) {
    grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &texture->file.table.palette);
  }
  grTexDownloadMipMap(GR_TMU0, texture->address, GR_MIPMAPLEVELMASK_BOTH, &texture->info);
  *address += grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &texture->info);
  return 1;
}

/* Camera space to a Glide vertex: screen position (upper-left origin), 1/w, and the texture
 * coordinates (in texels of the largest level, 0..256 across it) divided by w as the TMU
 * iterates them. Colour and alpha are the caller's. */
static GrVertex project(float x, float y, float z, float s, float t) {
  GrVertex v;
  memset(&v, 0, sizeof v);
  v.oow = 1.0f / z;
  v.x = kWidth / 2 + kFocal * x * v.oow;
  v.y = kHeight / 2 - kFocal * y * v.oow;
  v.tmuvtx[0].sow = s * v.oow;
  v.tmuvtx[0].tow = t * v.oow;
  v.tmuvtx[0].oow = v.oow;
  return v;
}

static void use_texture(Texture *texture, GrMipMapMode_t mipmap) {
  grTexSource(GR_TMU0, texture->address, GR_MIPMAPLEVELMASK_BOTH, &texture->info);
  grTexMipMapMode(GR_TMU0, mipmap, FXFALSE);
}

/* The floor, Y = kFloorY from kFloorNear to kFloorFar: a 4x8 grid of quads, each split in two
 * and clipped to the screen by guDrawTriangleWithClip (its near edge projects far outside). */
static void draw_floor(Texture *floor) {
  enum { kAcross = 4, kDeep = 8 };
  int i, j;
  use_texture(floor, GR_MIPMAP_NEAREST);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  for (j = 0; j < kDeep; ++j) {
    const float z0 = kFloorNear + (kFloorFar - kFloorNear) * (float)j / kDeep;
    const float z1 = kFloorNear + (kFloorFar - kFloorNear) * (float)(j + 1) / kDeep;
    for (i = 0; i < kAcross; ++i) {
      const float x0 = -kFloorHalfWidth + 2 * kFloorHalfWidth * (float)i / kAcross;
      const float x1 = -kFloorHalfWidth + 2 * kFloorHalfWidth * (float)(i + 1) / kAcross;
      const float texels = 256.0f / kTileSize;
      GrVertex a = project(x0, kFloorY, z0, x0 * texels, z0 * texels);
      GrVertex b = project(x1, kFloorY, z0, x1 * texels, z0 * texels);
      GrVertex c = project(x1, kFloorY, z1, x1 * texels, z1 * texels);
      GrVertex d = project(x0, kFloorY, z1, x0 * texels, z1 * texels);
      guDrawTriangleWithClip(&a, &b, &c);
      guDrawTriangleWithClip(&a, &c, &d);
    }
  }
}

/* The crate: a cube of half-width 1 turned `angle` radians about y and tilted about x, each face
 * lit once by a directional light (Lambert plus ambient, in the vertex colour that multiplies the
 * texture). Faces turned away are culled by grCullMode. */
static void draw_crate(Texture *crate, float angle, float height) {
  /* Per face: the outward normal and two edge directions, so corners are n +- u +- v. */
  static const float kFaces[6][3][3] = {
      {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, 1}, {-1, 0, 0}, {0, 1, 0}},
      {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   {{-1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}}};
  static const float kCorners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const float light[3] = {-0.45f, 0.75f, -0.48f}; /* towards the light, camera space, unit */
  const float tilt = 0.35f;
  const float cy = cosf(angle), sy = sinf(angle), cx = cosf(tilt), sx = sinf(tilt);
  int f, k;
  use_texture(crate, GR_MIPMAP_NEAREST);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  guColorCombineFunction(GR_COLORCOMBINE_TEXTURE_TIMES_ITRGB);
  grCullMode(GR_CULL_NEGATIVE);
  for (f = 0; f < 6; ++f) {
    GrVertex v[4];
    float normal[3], shade;
    /* Object space to camera space: turn about y, then tilt about x, then move out to the
     * crate's centre. */
    const float *n = kFaces[f][0];
    const float nx = cy * n[0] + sy * n[2], nz0 = -sy * n[0] + cy * n[2];
    normal[0] = nx;
    normal[1] = cx * n[1] - sx * nz0;
    normal[2] = sx * n[1] + cx * nz0;
    shade = normal[0] * light[0] + normal[1] * light[1] + normal[2] * light[2];
    shade = 0.3f + 0.7f * (shade > 0 ? shade : 0);
    for (k = 0; k < 4; ++k) {
      const float *u = kFaces[f][1], *w = kFaces[f][2];
      const float p[3] = {n[0] + kCorners[k][0] * u[0] + kCorners[k][1] * w[0],
                          n[1] + kCorners[k][0] * u[1] + kCorners[k][1] * w[1],
                          n[2] + kCorners[k][0] * u[2] + kCorners[k][1] * w[2]};
      const float x = cy * p[0] + sy * p[2], z0 = -sy * p[0] + cy * p[2];
      const float y = cx * p[1] - sx * z0, z = sx * p[1] + cx * z0;
      v[k] = project(x, y + height, z + kCrateZ, (kCorners[k][0] + 1) * 128.0f,
                     (1 - kCorners[k][1]) * 128.0f);
      v[k].r = v[k].g = v[k].b = 255.0f * shade;
    }
    grDrawTriangle(&v[0], &v[1], &v[2]);
    grDrawTriangle(&v[0], &v[2], &v[3]);
  }
  grCullMode(GR_CULL_DISABLE);
}

/* The logo, 64x32 texels at twice their size in the upper-left corner, blended by its alpha
 * over whatever is there, with no depth test and no fog. */
static void draw_logo(Texture *logo) {
  const float x0 = 16, y0 = 16, x1 = x0 + 128, y1 = y0 + 64;
  GrVertex v[4];
  int k;
  const float xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
  const float ss[4] = {0, 256, 256, 0}, ts[4] = {0, 0, 128, 128};
  use_texture(logo, GR_MIPMAP_DISABLE);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  guAlphaSource(GR_ALPHASOURCE_TEXTURE_ALPHA);
  grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                       GR_BLEND_ZERO);
  grFogMode(GR_FOG_DISABLE);
  grDepthBufferFunction(GR_CMP_ALWAYS);
  grDepthMask(FXFALSE);
  for (k = 0; k < 4; ++k) {
    memset(&v[k], 0, sizeof v[k]);
    v[k].x = xs[k], v[k].y = ys[k], v[k].oow = 1.0f;
    v[k].tmuvtx[0].sow = ss[k], v[k].tmuvtx[0].tow = ts[k], v[k].tmuvtx[0].oow = 1.0f;
  }
  grDrawTriangle(&v[0], &v[1], &v[2]);
  grDrawTriangle(&v[0], &v[2], &v[3]);
}

/* Depth, fog and blending for the 3D part of the frame. */
static void scene_state(GrFog_t *fog_table) {
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  guAlphaSource(GR_ALPHASOURCE_CC_ALPHA);
  grFogColorValue(kFogColor);
  grFogTable(fog_table);
  grFogMode(GR_FOG_WITH_TABLE);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
}

int main(int argc, char **argv) {
  Options options;
  GrHwConfiguration hardware;
  GrFog_t fog_table[GR_FOG_TABLE_SIZE];
  Texture crate, floor, logo;
  FxU32 address;
  int frame;
  if (!parse_options(argc, argv, &options)) {
    fprintf(stderr,
            "usage: crate_3df [-n FRAMES] [-d TEXTURE_DIR]\n"
            "  -n FRAMES       frames to draw (default %d)\n"
            "  -d TEXTURE_DIR  where crate.3df, floor.3df and logo.3df are (default .)\n"
            "A window with GLIDESHIM_BACKEND=sdl; headless, GLIDESHIM_DUMP_DIR=DIR keeps each "
            "frame as DIR/frame_NNNNN.png.\n",
            kDefaultFrames);
    return 2;
  }
  grGlideInit();
  grErrorSetCallback(on_glide_error);
  if (!grSstQueryHardware(&hardware)) {
    fprintf(stderr, "crate_3df: no Voodoo found\n");
    return 1;
  }
  grSstSelect(0);
  if (!grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ABGR,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    fprintf(stderr, "crate_3df: grSstWinOpen failed\n");
    return 1;
  }
  address = grTexMinAddress(GR_TMU0);
  if (!load_texture(options.texture_dir, "crate.3df", &address, &crate) ||
      !load_texture(options.texture_dir, "floor.3df", &address, &floor) ||
      !load_texture(options.texture_dir, "logo.3df", &address, &logo)) {
    grGlideShutdown();
    return 1;
  }
  guFogGenerateExp(fog_table, 0.045f);
  for (frame = 0; frame < options.frames; ++frame) {
    const float angle = 0.05f * (float)frame;
    const float height = 0.25f * sinf(0.08f * (float)frame);
    scene_state(fog_table);
    grBufferClear(kFogColor, 0, GR_WDEPTHVALUE_FARTHEST);
    draw_floor(&floor);
    draw_crate(&crate, angle, height);
    draw_logo(&logo);
    grBufferSwap(1);
  }
  grGlideShutdown();
  free(crate.file.data);
  free(floor.file.data);
  free(logo.file.data);
  printf("crate_3df: %d frames at %dx%d\n", options.frames, kWidth, kHeight);
  return glide_errors == 0 ? 0 : 1;
}
