/* palette_texture: one 64x64 P_8 texture drawn four times: with a rainbow palette; after a new
 * grey palette is downloaded (later draws see it); after grTexDownloadTablePartial turns
 * entries 64..127 red; and as AP_88 (alpha rising left to right) blended over a Gouraud bar. */
#include "sdk_common.h"

static FxU8 indices[64 * 64];
static FxU16 alpha_indices[64 * 64];
static GuTexPalette rainbow, grey, red;

static void build(void) {
  int i, x, y;
  for (i = 0; i < 256; ++i) {
    const int phase = i % 85 * 3;
    const FxU32 r = i < 85 ? 255 - phase : i < 170 ? 0 : phase;
    const FxU32 g = i < 85 ? phase : i < 170 ? 255 - phase : 0;
    const FxU32 b = i < 85 ? 0 : i < 170 ? phase : 255 - phase;
    rainbow.data[i] = (r << 16) | (g << 8) | b;
    grey.data[i] = (FxU32)(255 - i) * 0x010101u;
    red.data[i] = 0xFF2010;
  }
  for (y = 0; y < 64; ++y) {
    for (x = 0; x < 64; ++x) {
      const int index = ((x - 32) * (x - 32) + (y - 32) * (y - 32)) / 8 & 0xFF;
      indices[y * 64 + x] = (FxU8)index;
      alpha_indices[y * 64 + x] = (FxU16)((x * 4) << 8 | index);
    }
  }
}

static void quad(float x0, float y0, float size) {
  GrVertex v[4];
  const float xs[4] = {x0, x0 + size, x0 + size, x0}, ys[4] = {y0, y0, y0 + size, y0 + size};
  const float ss[4] = {0, 256, 256, 0}, ts[4] = {0, 0, 256, 256};
  int k;
  for (k = 0; k < 4; ++k) {
    v[k] = sdk_vertex(xs[k], ys[k], 1, 255, 255, 255, 255);
    v[k].tmuvtx[0].sow = ss[k];
    v[k].tmuvtx[0].tow = ts[k];
  }
  grDrawTriangle(&v[0], &v[1], &v[2]);
  grDrawTriangle(&v[0], &v[2], &v[3]);
}

static void load(GrTextureFormat_t format, void *data, FxU32 address) {
  GrTexInfo info;
  info.smallLod = GR_LOD_64;
  info.largeLod = GR_LOD_64;
  info.aspectRatio = GR_ASPECT_1x1;
  info.format = format;
  info.data = data;
  grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info);
}

int main(int argc, char **argv) {
  int frame, frames;
  if (!sdk_open("palette_texture", argc, argv, &frames)) return 1;
  build();
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  for (frame = 0; frame < frames; ++frame) {
    grBufferClear(0x00301010, 0, 0);
    /* A Gouraud bar behind the fourth texture. */
    guColorCombineFunction(GR_COLORCOMBINE_ITRGB);
    grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
    {
      GrVertex a = sdk_vertex(236, 70, 1, 0, 0, 255, 255), b = sdk_vertex(316, 70, 1, 0, 255, 0, 255);
      GrVertex c = sdk_vertex(316, 170, 1, 255, 255, 0, 255), d = sdk_vertex(236, 170, 1, 255, 0, 0, 255);
      grDrawTriangle(&a, &b, &c);
      grDrawTriangle(&a, &c, &d);
    }
    guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
    grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &rainbow);
    load(GR_TEXFMT_P_8, indices, 0);
    quad(4, 84, 72);
    grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &grey);
    quad(82, 84, 72);
    grTexDownloadTablePartial(GR_TMU0, GR_TEXTABLE_PALETTE, &red, 64, 127);
    quad(160, 84, 72);
    /* AP_88 through the rainbow palette, alpha from the texel, blended over the bar. */
    grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &rainbow);
    load(GR_TEXFMT_AP_88, alpha_indices, 8192);
    guAlphaSource(GR_ALPHASOURCE_TEXTURE_ALPHA);
    grAlphaBlendFunction(GR_BLEND_SRC_ALPHA, GR_BLEND_ONE_MINUS_SRC_ALPHA, GR_BLEND_ONE,
                         GR_BLEND_ZERO);
    quad(240, 84, 72);
    grBufferSwap(1);
  }
  return sdk_close();
}
