// How Glide lays out a texture in TMU memory: level sizes from LOD and aspect, bytes per texel
// by format, and where each level of a mip-map chain starts (largest level first). Levels take
// their SST-1 footprint in memory, which pads narrow small levels (see level_footprint).
#pragma once

#include <glide.h>

#include <cstdint>

namespace glide_shim {

struct LevelSize {
  int width, height;  // texels
};

bool is_lod(GrLOD_t lod);
bool is_aspect(GrAspectRatio_t aspect);
bool is_texture_format(GrTextureFormat_t format);   // any format Glide 2.x defines
bool is_even_odd(FxU32 even_odd);

int bytes_per_texel(GrTextureFormat_t format);
bool level_selected(GrLOD_t lod, FxU32 even_odd);  // by GR_MIPMAPLEVELMASK_EVEN/ODD/BOTH
LevelSize level_size(GrLOD_t lod, GrAspectRatio_t aspect);
// Bytes of the levels large_lod..small_lod that `even_odd` selects, rounded up to 8 bytes.
FxU32 mipmap_bytes(GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                   GrTextureFormat_t format, FxU32 even_odd);
// Byte offset of `lod` from the start of a chain whose largest level is `large_lod`.
FxU32 level_offset(GrLOD_t lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                   GrTextureFormat_t format, FxU32 even_odd);

// The texBaseAddr value for a chain downloaded at `start` whose largest level is `large_lod`:
// where its 256 level would begin (possibly before address 0), as _grTexCalcBaseAddress finds.
std::int64_t chain_base(FxU32 start, GrLOD_t large_lod, GrAspectRatio_t aspect,
                        GrTextureFormat_t format, FxU32 even_odd);
// The multibase range (GR_TEXBASE_256, _128, _64 or _32_TO_1) a level is read through.
int multibase_range(GrLOD_t lod);
// Byte address of level `lod` in TMU memory, from the per-range bases (TmuState::base).
std::int64_t level_address(const std::int64_t base[4], bool multibase, GrLOD_t lod,
                           GrAspectRatio_t aspect, GrTextureFormat_t format, FxU32 even_odd);

// Argument checks shared by the texture entry points (texture.cpp): each reports the first bad
// field as an error naming `function` and returns false.
bool check_texture_info(const char *function, GrLOD_t small_lod, GrLOD_t large_lod,
                        GrAspectRatio_t aspect, GrTextureFormat_t format);
bool check_tmu(const char *function, GrChipID_t tmu);

// grTexLodBiasValue's bias as the tLOD register holds it: quarters, rounded as the driver does.
float fixed_lod_bias(float bias);

}  // namespace glide_shim
