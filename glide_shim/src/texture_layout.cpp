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

std::int64_t chain_base(FxU32 start, GrLOD_t large_lod, GrAspectRatio_t aspect,
                        GrTextureFormat_t format, FxU32 even_odd) {
  return static_cast<std::int64_t>(start) -
         static_cast<std::int64_t>(level_offset(large_lod, GR_LOD_256, aspect, format, even_odd));
}

int multibase_range(GrLOD_t lod) { return lod < GR_TEXBASE_32_TO_1 ? lod : GR_TEXBASE_32_TO_1; }

std::int64_t level_address(const std::int64_t base[4], bool multibase, GrLOD_t lod,
                           GrAspectRatio_t aspect, GrTextureFormat_t format, FxU32 even_odd) {
  const std::int64_t chain = base[multibase ? multibase_range(lod) : 0];
  return chain +
         static_cast<std::int64_t>(level_offset(lod, GR_LOD_256, aspect, format, even_odd));
}

}  // namespace glide_shim
