/* hello_glide: a Glide 2.x program in the style of the SDK's test programs. It opens a 640x480
 * window, draws a Gouraud triangle over a textured, W-buffered floor quad, and writes the frame
 * as PNG. Nothing in it is specific to the shim except the final glideShimWritePng call. */
#include <glide.h>
#include <glide_shim.h>

#include <stdio.h>
#include <string.h>

static FxU16 checker[64 * 64];

static void set_vertex(GrVertex *v, float x, float y, float w, float s, float t) {
  memset(v, 0, sizeof *v);
  v->x = x;
  v->y = y;
  v->oow = 1.0f / w;
  v->tmuvtx[0].sow = s * v->oow;
  v->tmuvtx[0].tow = t * v->oow;
}

int main(int argc, char **argv) {
  const char *out = argc > 1 ? argv[1] : "hello_glide.png";
  GrHwConfiguration hw;
  GrTexInfo info;
  GrVertex a, b, c, d;
  int i;

  if (argc > 1 && (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)) {
    printf("usage: hello_glide [OUT.png]\nRenders one Glide frame headless and writes it as PNG "
           "(default hello_glide.png).\n");
    return 0;
  }
  grGlideInit();
  if (!grSstQueryHardware(&hw)) {
    fprintf(stderr, "hello_glide: no Voodoo found: %s\n", glideShimGetLastErrorMessage());
    return 1;
  }
  grSstSelect(0);
  if (!grSstWinOpen(0, GR_RESOLUTION_640x480, GR_REFRESH_60Hz, GR_COLORFORMAT_ABGR,
                    GR_ORIGIN_UPPER_LEFT, 2, 1)) {
    fprintf(stderr, "hello_glide: grSstWinOpen failed: %s\n", glideShimGetLastErrorMessage());
    return 1;
  }
  grDepthBufferMode(GR_DEPTHBUFFER_WBUFFER);
  grDepthBufferFunction(GR_CMP_LESS);
  grDepthMask(FXTRUE);
  grBufferClear(0x00402010, 0, GR_WDEPTHVALUE_FARTHEST);

  /* A 64x64 RGB565 checkerboard, downloaded to address 0 and drawn perspective-correct. */
  for (i = 0; i < 64 * 64; ++i) {
    checker[i] = (((i % 64) / 8 + (i / 64) / 8) % 2) ? 0xFFE0 : 0x001F;
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
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);

  set_vertex(&a, 40.0f, 470.0f, 1.0f, 0.0f, 0.0f);
  set_vertex(&b, 600.0f, 470.0f, 1.0f, 1024.0f, 0.0f);
  set_vertex(&c, 420.0f, 250.0f, 8.0f, 1024.0f, 1024.0f);
  set_vertex(&d, 220.0f, 250.0f, 8.0f, 0.0f, 1024.0f);
  grDrawTriangle(&a, &b, &c);
  grDrawTriangle(&a, &c, &d);

  /* A Gouraud triangle in front of the floor. */
  guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
  set_vertex(&a, 320.0f, 40.0f, 0.5f, 0, 0);
  a.r = 255.0f;
  set_vertex(&b, 520.0f, 380.0f, 0.5f, 0, 0);
  b.g = 255.0f;
  set_vertex(&c, 120.0f, 380.0f, 0.5f, 0, 0);
  c.b = 255.0f;
  grDrawTriangle(&a, &b, &c);

  grBufferSwap(1);
  if (!glideShimWritePng(GR_BUFFER_FRONTBUFFER, out)) {
    fprintf(stderr, "hello_glide: %s\n", glideShimGetLastErrorMessage());
    grGlideShutdown();
    return 1;
  }
  printf("hello_glide: wrote %s (640x480, backend %s)\n", out, glideShimBackendName());
  grGlideShutdown();
  return 0;
}
