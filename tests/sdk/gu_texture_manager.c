/* gu_texture_manager: two mip maps placed by the gu texture manager. Left: the SDK's colour mip
 * map (guTexCreateColorMipMap: red, green, blue, white, black, ... per level, 256..1) on a
 * receding floor, nearest mip-mapping with point sampling, so each band is one LOD. Right: a
 * 64x32 RGB565 checkerboard chain (64x32..8x4), bilinear and clamped at the top; below, the same
 * mip map after guTexChangeAttributes to point sampling with wrapping, repeated twice. */
#include "sdk_common.h"

#define CHECKER_TEXELS (64 * 32 + 32 * 16 + 16 * 8 + 8 * 4)

static FxU16 checker[CHECKER_TEXELS];

static void build_checker(void) {
  static const FxU16 tint[4] = {0xFD20, 0x07FF, 0xF81F, 0xFFE0};
  int width = 64, height = 32, level, x, y;
  FxU16 *texel = checker;
  for (level = 0; level < 4; ++level, width /= 2, height /= 2) {
    for (y = 0; y < height; ++y) {
      for (x = 0; x < width; ++x) {
        *texel++ = (FxU16)(((x * 8 / width + y * 4 / height) % 2) ? tint[level] : 0x2104);
      }
    }
  }
}

/* A quad over [x0, x1) x [y0, y1) with w from w_top to w_bottom and s, t up to s1, t1. */
static void quad(float x0, float y0, float x1, float y1, float w_top, float w_bottom, float s1,
                 float t1) {
  const float xs[4] = {x0, x1, x1, x0}, ys[4] = {y0, y0, y1, y1};
  const float ws[4] = {w_top, w_top, w_bottom, w_bottom};
  const float ss[4] = {0, s1, s1, 0}, ts[4] = {0, 0, t1, t1};
  sdk_textured_quad(xs, ys, ws, ss, ts);
}

int main(int argc, char **argv) {
  GrMipMapId_t colors, board;
  GrTexInfo colors_info, board_info;
  FxU16 *color_levels;
  int frame, frames;
  if (!sdk_open("gu_texture_manager", argc, argv, &frames)) return 1;
  build_checker();
  color_levels = guTexCreateColorMipMap();
  if (color_levels == NULL) return 1;

  guTexMemReset();
  colors = guTexAllocateMemory(GR_TMU0, GR_MIPMAPLEVELMASK_BOTH, 256, 256, GR_TEXFMT_RGB_565,
                               GR_MIPMAP_NEAREST, GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1,
                               GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP,
                               GR_TEXTUREFILTER_POINT_SAMPLED, GR_TEXTUREFILTER_POINT_SAMPLED,
                               0.0f, FXFALSE);
  board = guTexAllocateMemory(GR_TMU0, GR_MIPMAPLEVELMASK_BOTH, 64, 32, GR_TEXFMT_RGB_565,
                              GR_MIPMAP_NEAREST, GR_LOD_8, GR_LOD_64, GR_ASPECT_2x1,
                              GR_TEXTURECLAMP_CLAMP, GR_TEXTURECLAMP_CLAMP,
                              GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR, 0.0f, FXFALSE);
  if (colors == GR_NULL_MIPMAP_HANDLE || board == GR_NULL_MIPMAP_HANDLE) {
    fprintf(stderr, "gu_texture_manager: guTexAllocateMemory failed\n");
    return 1;
  }
  /* The manager hands out memory from the bottom: what is left is the rest of the TMU. */
  colors_info.smallLod = GR_LOD_1, colors_info.largeLod = GR_LOD_256;
  colors_info.aspectRatio = GR_ASPECT_1x1, colors_info.format = GR_TEXFMT_RGB_565;
  board_info.smallLod = GR_LOD_8, board_info.largeLod = GR_LOD_64;
  board_info.aspectRatio = GR_ASPECT_2x1, board_info.format = GR_TEXFMT_RGB_565;
  if (guTexMemQueryAvail(GR_TMU0) !=
      grTexMaxAddress(GR_TMU0) + 8 -
          grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &colors_info) -
          grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &board_info)) {
    fprintf(stderr, "gu_texture_manager: unexpected free texture memory %lu\n",
            (unsigned long)guTexMemQueryAvail(GR_TMU0));
    return 1;
  }
  guTexDownloadMipMap(colors, color_levels, NULL);
  guTexDownloadMipMap(board, checker, NULL);
  free(color_levels);

  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  for (frame = 0; frame < frames; ++frame) {
    grBufferClear(0x00303030, 0, 0);
    guTexSource(colors);
    quad(8, 20, 152, 230, 16, 1, 256, 1024);
    guTexChangeAttributes(board, -1, -1, -1, -1, -1, -1, -1, GR_TEXTURECLAMP_CLAMP,
                          GR_TEXTURECLAMP_CLAMP, GR_TEXTUREFILTER_BILINEAR,
                          GR_TEXTUREFILTER_BILINEAR);
    guTexSource(board);
    quad(168, 20, 312, 92, 1, 1, 256, 128);
    guTexChangeAttributes(board, -1, -1, -1, -1, -1, -1, -1, GR_TEXTURECLAMP_WRAP,
                          GR_TEXTURECLAMP_WRAP, GR_TEXTUREFILTER_POINT_SAMPLED,
                          GR_TEXTUREFILTER_POINT_SAMPLED);
    guTexSource(board);
    quad(168, 110, 312, 230, 1, 1, 512, 256);
    if (guTexGetCurrentMipMap(GR_TMU0) != board) {
      fprintf(stderr, "gu_texture_manager: guTexGetCurrentMipMap is not the last source\n");
      return 1;
    }
    grBufferSwap(1);
  }
  return sdk_close();
}
