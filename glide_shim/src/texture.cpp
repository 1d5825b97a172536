// Chapter "texture mapping": which texture TMU0 reads and how (clamp or wrap, point or
// bilinear, mip-mapping, LOD bias, multibase addresses, which NCC table), and the memory queries
// programs use to place textures in TMU memory.
#include "context.h"
#include "texture_layout.h"

#include <cmath>
#include <string>

using glide_shim::current;

namespace glide_shim {

// Shared by grTexSource and the downloads: reports the first bad field and returns false.
bool check_texture_info(const char *function, GrLOD_t small_lod, GrLOD_t large_lod,
                        GrAspectRatio_t aspect, GrTextureFormat_t format) {
  auto &ctx = current();
  std::string problem;
  if (!is_lod(small_lod) || !is_lod(large_lod)) problem = "LOD outside GR_LOD_256..GR_LOD_1";
  else if (small_lod < large_lod) problem = "smallLod is larger than largeLod";
  else if (!is_aspect(aspect)) problem = "unknown aspect ratio " + std::to_string(aspect);
  else if (!is_texture_format(format)) problem = "unknown texture format " + std::to_string(format);
  if (!problem.empty()) {
    ctx.report(small_lod < large_lod && is_lod(small_lod) && is_lod(large_lod)
                   ? GLIDESHIM_ERR_INCONSISTENT
                   : GLIDESHIM_ERR_INVALID_ENUM,
               std::string(function) + ": " + problem);
    return false;
  }
  return true;
}

float fixed_lod_bias(float bias) {
  // _grTexFloatLODToFixedLOD: quarters, (bias + 1/8) / (1/4) truncated towards zero, kept as a
  // 6-bit two's complement field (so -0.5 becomes -0.25, as on the hardware).
  const int quarters = static_cast<int>((bias + 0.125f) / 0.25f) & 0x3F;
  return static_cast<float>(quarters >= 32 ? quarters - 64 : quarters) / 4.0f;
}

bool check_tmu(const char *function, GrChipID_t tmu) {
  if (tmu == GR_TMU0) return true;
  current().report(GLIDESHIM_ERR_OUT_OF_RANGE, std::string(function) + ": TMU " +
                                                   std::to_string(tmu) +
                                                   " does not exist (one TMU)");
  return false;
}

}  // namespace glide_shim

using glide_shim::check_texture_info;
using glide_shim::check_tmu;

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

FxU32 grTexMinAddress(GrChipID_t tmu) {
  if (!check_tmu("grTexMinAddress", tmu)) return 0;
  return 0;
}

FxU32 grTexMaxAddress(GrChipID_t tmu) {
  if (!check_tmu("grTexMaxAddress", tmu)) return 0;
  // The highest start address: room for the smallest texture (8 bytes) at the very end.
  return glide_shim::kTmuMemoryBytes - 8;
}

FxU32 grTexCalcMemRequired(GrLOD_t smallLod, GrLOD_t largeLod, GrAspectRatio_t aspect,
                           GrTextureFormat_t format) {
  if (!check_texture_info("grTexCalcMemRequired", smallLod, largeLod, aspect, format)) return 0;
  return glide_shim::mipmap_bytes(smallLod, largeLod, aspect, format, GR_MIPMAPLEVELMASK_BOTH);
}

FxU32 grTexTextureMemRequired(FxU32 evenOdd, GrTexInfo *info) {
  auto &ctx = current();
  if (info == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grTexTextureMemRequired: info is NULL");
    return 0;
  }
  if (!glide_shim::is_even_odd(evenOdd)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grTexTextureMemRequired: unknown evenOdd mask");
    return 0;
  }
  if (!check_texture_info("grTexTextureMemRequired", info->smallLod, info->largeLod,
                          info->aspectRatio, info->format)) {
    return 0;
  }
  return glide_shim::mipmap_bytes(info->smallLod, info->largeLod, info->aspectRatio,
                                  info->format, evenOdd);
}

void grTexSource(GrChipID_t tmu, FxU32 startAddress, FxU32 evenOdd, GrTexInfo *info) {
  auto &ctx = current();
  if (!ctx.require_open("grTexSource") || !check_tmu("grTexSource", tmu)) return;
  if (info == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grTexSource: info is NULL");
    return;
  }
  if (!glide_shim::is_even_odd(evenOdd)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grTexSource: unknown evenOdd mask");
    return;
  }
  if (!check_texture_info("grTexSource", info->smallLod, info->largeLod, info->aspectRatio,
                          info->format)) {
    return;
  }
  const FxU32 size = glide_shim::mipmap_bytes(info->smallLod, info->largeLod, info->aspectRatio,
                                              info->format, evenOdd);
  if (startAddress % 8 != 0 || startAddress > glide_shim::kTmuMemoryBytes - size) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grTexSource: texture at " + std::to_string(startAddress) + " (" +
                   std::to_string(size) + " bytes) is misaligned or beyond TMU memory");
    return;
  }
  ctx.flush();
  ctx.tmu.source = {true,          startAddress,      info->smallLod, info->largeLod,
                    info->aspectRatio, info->format, evenOdd};
  // Like the driver, grTexSource writes texBaseAddr, the base of the 256 range.
  ctx.tmu.base[GR_TEXBASE_256] = glide_shim::chain_base(startAddress, info->largeLod,
                                                        info->aspectRatio, info->format, evenOdd);
}

void grTexClampMode(GrChipID_t tmu, GrTextureClampMode_t s_clampmode,
                    GrTextureClampMode_t t_clampmode) {
  auto &ctx = current();
  if (!ctx.require_open("grTexClampMode") || !check_tmu("grTexClampMode", tmu)) return;
  auto valid = [](GrTextureClampMode_t m) {
    return m == GR_TEXTURECLAMP_WRAP || m == GR_TEXTURECLAMP_CLAMP;
  };
  if (!valid(s_clampmode) || !valid(t_clampmode)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grTexClampMode: unknown clamp mode");
    return;
  }
  ctx.flush();
  ctx.tmu.clamp_s = s_clampmode;
  ctx.tmu.clamp_t = t_clampmode;
}

void grTexFilterMode(GrChipID_t tmu, GrTextureFilterMode_t minfilter_mode,
                     GrTextureFilterMode_t magfilter_mode) {
  auto &ctx = current();
  if (!ctx.require_open("grTexFilterMode") || !check_tmu("grTexFilterMode", tmu)) return;
  auto valid = [](GrTextureFilterMode_t m) {
    return m == GR_TEXTUREFILTER_POINT_SAMPLED || m == GR_TEXTUREFILTER_BILINEAR;
  };
  if (!valid(minfilter_mode) || !valid(magfilter_mode)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grTexFilterMode: unknown filter mode");
    return;
  }
  ctx.flush();
  ctx.tmu.min_filter = minfilter_mode;
  ctx.tmu.mag_filter = magfilter_mode;
}

void grTexMipMapMode(GrChipID_t tmu, GrMipMapMode_t mode, FxBool lodBlend) {
  auto &ctx = current();
  if (!ctx.require_open("grTexMipMapMode") || !check_tmu("grTexMipMapMode", tmu)) return;
  if (mode != GR_MIPMAP_DISABLE && mode != GR_MIPMAP_NEAREST && mode != GR_MIPMAP_NEAREST_DITHER) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grTexMipMapMode: unknown mode " + std::to_string(mode));
    return;
  }
  ctx.flush();
  ctx.tmu.mipmap_mode = mode;
  ctx.tmu.lod_blend = lodBlend != FXFALSE;
  // The driver sets the LOD dither bit only if GR_HINT_ALLOW_MIPMAP_DITHER was given before.
  ctx.tmu.lod_dither = mode == GR_MIPMAP_NEAREST_DITHER && ctx.tmu.allow_lod_dither;
}

void grTexLodBiasValue(GrChipID_t tmu, float bias) {
  auto &ctx = current();
  if (!ctx.require_open("grTexLodBiasValue") || !check_tmu("grTexLodBiasValue", tmu)) return;
  if (!std::isfinite(bias) || bias < -8.0f || bias > 7.75f) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grTexLodBiasValue: bias " + std::to_string(bias) + " is outside -8..7.75");
    return;
  }
  ctx.flush();
  ctx.tmu.lod_bias = glide_shim::fixed_lod_bias(bias);
}

void grTexDetailControl(GrChipID_t tmu, int lod_bias, FxU8 detail_scale, float detail_max) {
  auto &ctx = current();
  if (!ctx.require_open("grTexDetailControl") || !check_tmu("grTexDetailControl", tmu)) return;
  // The driver's checks (ditex.c): tDetail holds a 6-bit signed bias, a 3-bit scale and an
  // 8-bit maximum.
  std::string problem;
  if (lod_bias < -32 || lod_bias > 31) {
    problem = "lod_bias " + std::to_string(lod_bias) + " is outside -32..31";
  } else if (detail_scale > 7) {
    problem = "detail_scale " + std::to_string(detail_scale) + " is outside 0..7";
  } else if (!(detail_max >= 0.0f && detail_max <= 1.0f)) {
    problem = "detail_max " + std::to_string(detail_max) + " is outside 0..1";
  }
  if (!problem.empty()) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "grTexDetailControl: " + problem);
    return;
  }
  ctx.flush();
  ctx.tmu.detail_bias = lod_bias;
  ctx.tmu.detail_scale = detail_scale;
  ctx.tmu.detail_max = static_cast<int>(detail_max * 255.0f);  // (FxU32)(detail_max * 255.0f)
}

void grTexNCCTable(GrChipID_t tmu, GrNCCTable_t table) {
  auto &ctx = current();
  if (!ctx.require_open("grTexNCCTable") || !check_tmu("grTexNCCTable", tmu)) return;
  if (table != GR_NCCTABLE_NCC0 && table != GR_NCCTABLE_NCC1) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grTexNCCTable: table " + std::to_string(table) + " is not NCC0 or NCC1");
    return;
  }
  if (table == ctx.tmu.tables.ncc_select) return;
  ctx.flush();
  ctx.tmu.tables.ncc_select = table;
  ++ctx.tmu.tables.generation;
}

void grTexMultibase(GrChipID_t tmu, FxBool enable) {
  auto &ctx = current();
  if (!ctx.require_open("grTexMultibase") || !check_tmu("grTexMultibase", tmu)) return;
  ctx.flush();
  ctx.tmu.multibase = enable != FXFALSE;
}

void grTexMultibaseAddress(GrChipID_t tmu, GrTexBaseRange_t range, FxU32 startAddress,
                           FxU32 evenOdd, GrTexInfo *info) {
  auto &ctx = current();
  if (!ctx.require_open("grTexMultibaseAddress") || !check_tmu("grTexMultibaseAddress", tmu))
    return;
  if (range > GR_TEXBASE_32_TO_1) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grTexMultibaseAddress: unknown range " + std::to_string(range));
    return;
  }
  if (info == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grTexMultibaseAddress: info is NULL");
    return;
  }
  if (!glide_shim::is_even_odd(evenOdd)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grTexMultibaseAddress: unknown evenOdd mask");
    return;
  }
  if (!check_texture_info("grTexMultibaseAddress", info->smallLod, info->largeLod,
                          info->aspectRatio, info->format)) {
    return;
  }
  // The range's own levels, from its top LOD (256, 128, 64 or 32) down to its bottom (32..1
  // holds six), start at startAddress as grTexDownloadMipMapLevel placed them.
  const GrLOD_t top = static_cast<GrLOD_t>(range);
  const GrLOD_t bottom = range == GR_TEXBASE_32_TO_1 ? GR_LOD_1 : top;
  const FxU32 bytes = glide_shim::mipmap_bytes(bottom, top, info->aspectRatio, info->format,
                                               evenOdd);
  if (startAddress % 8 != 0 || startAddress > glide_shim::kTmuMemoryBytes ||
      bytes > glide_shim::kTmuMemoryBytes - startAddress) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grTexMultibaseAddress: levels at " + std::to_string(startAddress) + " (" +
                   std::to_string(bytes) + " bytes) are misaligned or beyond TMU memory");
    return;
  }
  ctx.flush();
  ctx.tmu.base[range] =
      glide_shim::chain_base(startAddress, top, info->aspectRatio, info->format, evenOdd);
}

}  // namespace glide_shim_api
