/* load_3df: textures read from .3df files in the working directory, as the SDK's programs read
 * theirs: yiq_mipmap.3df (YIQ_422 with its NCC table, a 64..1 mip-map chain) on a receding
 * floor with mip-mapping, and p8_stripes.3df (P_8 with its palette, 64x32) flat on top. */
#include "sdk_common.h"

/* gu3dfGetInfo, a buffer of mem_required bytes, gu3dfLoad; 0 on failure. */
static int read_3df(const char *file, Gu3dfInfo *info) {
  if (!gu3dfGetInfo(file, info)) {
    fprintf(stderr, "load_3df: cannot read the header of %s\n", file);
    return 0;
  }
  info->data = malloc(info->mem_required);
  if (info->data == NULL || !gu3dfLoad(file, info)) {
    fprintf(stderr, "load_3df: cannot load %s\n", file);
    return 0;
  }
  return 1;
}

static void texture_from(Gu3dfInfo *info, FxU32 address) {
  GrTexInfo tex;
  tex.smallLod = info->header.small_lod;
  tex.largeLod = info->header.large_lod;
  tex.aspectRatio = info->header.aspect_ratio;
  tex.format = info->header.format;
  tex.data = info->data;
  if (tex.format == GR_TEXFMT_YIQ_422 || tex.format == GR_TEXFMT_AYIQ_8422) {
    grTexDownloadTable(GR_TMU0, GR_TEXTABLE_NCC0, &info->table.nccTable);
    grTexNCCTable(GR_TMU0, GR_NCCTABLE_NCC0);
  } else if (tex.format == GR_TEXFMT_P_8 || tex.format == GR_TEXFMT_AP_88) {
    grTexDownloadTable(GR_TMU0, GR_TEXTABLE_PALETTE, &info->table.palette);
  }
  grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &tex);
  grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &tex);
}

int main(int argc, char **argv) {
  Gu3dfInfo yiq, stripes;
  int frame, frames;
  if (!sdk_open("load_3df", argc, argv, &frames)) return 1;
  if (!read_3df("yiq_mipmap.3df", &yiq) || !read_3df("p8_stripes.3df", &stripes)) return 1;
  guTexCombineFunction(GR_TMU0, GR_TEXTURECOMBINE_DECAL);
  guColorCombineFunction(GR_COLORCOMBINE_DECAL_TEXTURE);
  grTexClampMode(GR_TMU0, GR_TEXTURECLAMP_WRAP, GR_TEXTURECLAMP_WRAP);
  grTexFilterMode(GR_TMU0, GR_TEXTUREFILTER_BILINEAR, GR_TEXTUREFILTER_BILINEAR);
  for (frame = 0; frame < frames; ++frame) {
    grBufferClear(0x00000000, 0, 0);
    {
      const float xs[4] = {10, 310, 310, 10}, ys[4] = {90, 90, 235, 235}, ws[4] = {16, 16, 1, 1};
      const float ss[4] = {0, 768, 768, 0}, ts[4] = {0, 0, 2048, 2048};
      texture_from(&yiq, 0);
      grTexMipMapMode(GR_TMU0, GR_MIPMAP_NEAREST, FXFALSE);
      sdk_textured_quad(xs, ys, ws, ss, ts);
    }
    {
      /* 64x32 texels: s 0..256, t 0..128, drawn at 2x over 128x64 pixels. */
      const float xs[4] = {96, 224, 224, 96}, ys[4] = {10, 10, 74, 74}, ws[4] = {1, 1, 1, 1};
      const float ss[4] = {0, 256, 256, 0}, ts[4] = {0, 0, 128, 128};
      texture_from(&stripes, 65536);
      grTexMipMapMode(GR_TMU0, GR_MIPMAP_DISABLE, FXFALSE);
      sdk_textured_quad(xs, ys, ws, ss, ts);
    }
    grBufferSwap(1);
  }
  free(yiq.data);
  free(stripes.data);
  return sdk_close();
}
