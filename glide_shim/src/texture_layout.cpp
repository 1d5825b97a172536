// Texture sizes and offsets in TMU memory (Glide 2.x LOD/aspect conventions).
#include "texture_layout.h"

#include <algorithm>
#include <cstdlib>

namespace glide_shim {

bool is_lod(GrLOD_t lod) { return lod >= GR_LOD_256 && lod <= GR_LOD_1; }
bool is_aspect(GrAspectRatio_t aspect) {
  return aspect >= GR_ASPECT_8x1 && aspect <= GR_ASPECT_1x8;
}

bool is_texture_format(GrTextureFormat_t format) {
  return format >= GR_TEXFMT_8BIT && format <= GR_TEXFMT_AP_88 && format != GR_TEXFMT_RSVD0 &&
         format != GR_TEXFMT_RSVD1;
}

bool is_decodable_format(GrTextureFormat_t format) {
  switch (format) {
    case GR_TEXFMT_RGB_332:
    case GR_TEXFMT_ALPHA_8:
    case GR_TEXFMT_INTENSITY_8:
    case GR_TEXFMT_ALPHA_INTENSITY_44:
    case GR_TEXFMT_ARGB_8332:
    case GR_TEXFMT_RGB_565:
    case GR_TEXFMT_ARGB_1555:
    case GR_TEXFMT_ARGB_4444:
    case GR_TEXFMT_ALPHA_INTENSITY_88: return true;
    default: return false;  // palette and NCC formats need their tables (not yet implemented)
  }
}

bool is_even_odd(FxU32 even_odd) {
  return even_odd == GR_MIPMAPLEVELMASK_EVEN || even_odd == GR_MIPMAPLEVELMASK_ODD ||
         even_odd == GR_MIPMAPLEVELMASK_BOTH;
}

int bytes_per_texel(GrTextureFormat_t format) { return format < GR_TEXFMT_16BIT ? 1 : 2; }

LevelSize level_size(GrLOD_t lod, GrAspectRatio_t aspect) {
  const int longer = 256 >> lod;
  // Aspect 8x1 (0) .. 1x1 (3) .. 1x8 (6): the shorter side is longer / 2^|aspect - 3|.
  const int ratio = 1 << std::abs(static_cast<int>(aspect) - GR_ASPECT_1x1);
  const int shorter = std::max(1, longer / ratio);
  if (aspect <= GR_ASPECT_1x1) return {longer, shorter};
  return {shorter, longer};
}

bool level_selected(GrLOD_t lod, FxU32 even_odd) {
  if (even_odd == GR_MIPMAPLEVELMASK_BOTH) return true;
  const bool even = (lod % 2) == 0;
  return even == (even_odd == GR_MIPMAPLEVELMASK_EVEN);
}

namespace {
// Texels a level occupies in TMU memory: SST-1 Glide's _grMipMapSize table (ditex.c), indexed
// by |aspect - 1x1| (1x8 takes as much as 8x1) and LOD. Narrow small levels are padded, and no
// level holds fewer than 4 texels, so this is not always width x height.
int level_footprint(GrLOD_t lod, GrAspectRatio_t aspect) {
  static const int kFootprint[4][9] = {
      {65536, 16384, 4096, 1024, 256, 64, 16, 4, 4},  // 1:1
      {32768, 8192, 2048, 512, 128, 32, 8, 4, 4},     // 2:1
      {16384, 4096, 1024, 256, 64, 16, 8, 4, 4},      // 4:1
      {8192, 2048, 512, 128, 32, 16, 8, 4, 4},        // 8:1
  };
  return kFootprint[std::abs(static_cast<int>(aspect) - GR_ASPECT_1x1)][lod];
}

FxU32 level_bytes(GrLOD_t lod, GrAspectRatio_t aspect, GrTextureFormat_t format) {
  return static_cast<FxU32>(level_footprint(lod, aspect) * bytes_per_texel(format));
}
}  // namespace

FxU32 level_offset(GrLOD_t lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                   GrTextureFormat_t format, FxU32 even_odd) {
  FxU32 offset = 0;
  for (GrLOD_t level = large_lod; level < lod; ++level) {
    if (level_selected(level, even_odd)) offset += level_bytes(level, aspect, format);
  }
  return offset;
}

FxU32 mipmap_bytes(GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                   GrTextureFormat_t format, FxU32 even_odd) {
  const FxU32 bytes = level_offset(small_lod + 1, large_lod, aspect, format, even_odd);
  return (bytes + 7u) & ~7u;
}

}  // namespace glide_shim
