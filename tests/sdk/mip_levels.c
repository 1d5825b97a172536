/* mip_levels: a 64..1 RGB565 mip-map chain, each level a checkerboard in its own tint, on three
 * receding floors: nearest mip-mapping with point sampling, the same with a LOD bias of +1, and
 * dithered mip-mapping (GR_HINT_ALLOW_MIPMAP_DITHER) with bilinear filtering. */
#include "sdk_common.h"

#define CHAIN_TEXELS (64 * 64 + 32 * 32 + 16 * 16 + 8 * 8 + 4 * 4 + 2 * 2 + 1)

static FxU16 chain[CHAIN_TEXELS];

static void build_chain(void) {
  static const FxU16 tint[7] = {0xF800, 0x07E0, 0x001F, 0xFFE0, 0xF81F, 0x07FF, 0xFD20};
  int side, level = 0, x, y;
  FxU16 *texel = chain;
  for (side = 64; side >= 1; side /= 2, ++level) {
    const int cell = side >= 8 ? side / 8 : 1;
    for (y = 0; y < side; ++y) {
      for (x = 0; x < side; ++x) *texel++ = ((x / cell + y / cell) % 2) ? tint[level] : 0xFFFF;
    }
  }
}

/* A floor over columns [x0, x1): far edge (w = 24) at the top, near edge (w = 1) at the bottom;
 * s repeats the texture 4 times across and t 12 times along. */
static void floor_panel(float x0, float x1) {
  const float xs[4] = {x0, x1, x1, x0}, ys[4] = {20, 20, 230, 230}, ws[4] = {24, 24, 1, 1};
  const float ss[4] = {0, 1024, 1024, 0}, ts[4] = {0, 0, 3072, 3072};
  sdk_textured_quad(xs, ys, ws, ss, ts);
}

int main(int argc, char **argv) {
  GrTexInfo info;
  int frame, frames;
  if (!sdk_open("mip_levels", argc, argv, &frames)) return 1;
  build_chain();
  info.smallLod = GR_LOD_1;
  info.largeLod = GR_LOD_64;
  info.aspectRatio = GR_ASPECT_1x1;
  info.format = GR_TEXFMT_RGB_565;
  info.data = chain;
  grTexDownloadMipMap(GR_TMU0, grTexMinAddress(GR_TMU0), GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexSource(GR_TMU0, grTexMinAddress(GR_TMU0), GR_MIPMAPLEVELMASK_BOTH, &info);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP);
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  grHints(GR_HINT_ALLOW_MIPMAP_DITHER, 1);
  for (frame = 0; frame < frames; ++frame) {
    grBufferClear(0x00202020, 0, 0);
    grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_POINT_SAMPLED);
    grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
    grTexLodBiasValue(GR_TMU0, 0.0f);
    floor_panel(4, 104);
    grTexLodBiasValue(GR_TMU0, 1.0f);
    floor_panel(110, 210);
    grTexLodBiasValue(GR_TMU0, 0.0f);
    grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST_DITHER, FXFALSE);
    grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
    floor_panel(216, 316);
    grBufferSwap(1);
  }
  return sdk_close();
}
