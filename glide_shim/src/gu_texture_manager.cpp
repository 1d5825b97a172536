// Chapter "gu texture manager": guTexAllocateMemory hands out TMU memory from address 0 upwards
// and keeps one GrMipMapInfo record per mip map, with the tLOD and textureMode register values
// the SST-1 driver computes (digutex.c); guTexDownloadMipMap(Level) download through
// grTexDownloadMipMap(Level), and guTexSource selects a record through grTexSource and the
// record's clamp, filter, mip-map mode, LOD bias and NCC table (gutex.c). Memory is never freed
// one mip map at a time: guTexMemReset (and grSstWinOpen) free everything.
#include "context.h"
#include "texture_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

using glide_shim::current;

namespace {

// textureMode register bits (SST-1 sst.h).
constexpr FxU32 kModePerspective = 1u << 0;  // SST_TPERSP_ST
constexpr FxU32 kModeMinBilinear = 1u << 1;  // SST_TMINFILTER
constexpr FxU32 kModeMagBilinear = 1u << 2;  // SST_TMAGFILTER
constexpr FxU32 kModeClampW = 1u << 3;       // SST_TCLAMPW
constexpr FxU32 kModeLodDither = 1u << 4;    // SST_TLODDITHER
constexpr FxU32 kModeClampS = 1u << 6;       // SST_TCLAMPS
constexpr FxU32 kModeClampT = 1u << 7;       // SST_TCLAMPT
constexpr int kModeFormatShift = 8;          // SST_TFORMAT_SHIFT
constexpr FxU32 kModeTrilinear = 1u << 30;   // SST_TRILINEAR

// tLOD register fields: LODs in 4.2 fixed point, the bias in signed quarters.
constexpr int kLodFractionBits = 2;  // SST_LOD_FRACBITS
constexpr int kLodMinShift = 0;      // the largest level (smallest GR_LOD number)
constexpr int kLodMaxShift = 6;      // the smallest level the chain may use
constexpr int kLodBiasShift = 12;
constexpr FxU32 kLodOdd = 1u << 18;       // SST_LOD_ODD
constexpr FxU32 kLodSplit = 1u << 19;     // SST_LOD_TSPLIT
constexpr FxU32 kLodSIsWider = 1u << 20;  // SST_LOD_S_IS_WIDER
constexpr int kLodAspectShift = 21;

// _gr_evenOdd_xlate_table: a chain holding only even or odd levels is split across TMUs.
FxU32 even_odd_bits(FxU32 even_odd) {
  if (even_odd == GR_MIPMAPLEVELMASK_EVEN) return kLodSplit;
  if (even_odd == GR_MIPMAPLEVELMASK_ODD) return kLodSplit | kLodOdd;
  return 0;
}

// _gr_aspect_xlate_table: log2 of the ratio, and which of s and t is the longer side.
FxU32 aspect_bits(GrAspectRatio_t aspect) {
  const auto ratio_log2 = static_cast<FxU32>(std::abs(aspect - GR_ASPECT_1x1));
  return (ratio_log2 << kLodAspectShift) | (aspect < GR_ASPECT_1x1 ? kLodSIsWider : 0u);
}

// _grTexFloatLODToFixedLOD: (bias + 1/8) / (1/4) truncated, kept as 6-bit two's complement.
FxU32 bias_quarters(float bias) {
  return static_cast<FxU32>(static_cast<int>((bias + 0.125f) / 0.25f)) & 0x3Fu;
}

float bias_from_quarters(FxU32 quarters) {
  const int signed_quarters = quarters >= 32 ? static_cast<int>(quarters) - 64
                                             : static_cast<int>(quarters);
  return static_cast<float>(signed_quarters) / 4.0f;
}

// tLOD as guTexAllocateMemory and _guTexRebuildRegisterShadows build it, without the trilinear
// bits only the allocation adds. lod_max is the record's largest level (smallest GR_LOD).
FxU32 tlod_register(const GrMipMapInfo &record) {
  const GrLOD_t smallest_used =
      record.mipmap_mode == GR_MIPMAP_DISABLE ? record.lod_max : record.lod_min;
  return (static_cast<FxU32>(record.lod_max) << (kLodMinShift + kLodFractionBits)) |
         (static_cast<FxU32>(smallest_used) << (kLodMaxShift + kLodFractionBits)) |
         even_odd_bits(record.odd_even_mask) | aspect_bits(record.aspect_ratio) |
         (record.lod_bias << kLodBiasShift);
}

FxU32 texture_mode_register(const GrMipMapInfo &record) {
  FxU32 mode = (static_cast<FxU32>(record.format) << kModeFormatShift) | kModeClampW |
               kModePerspective;
  if (record.minfilter_mode == GR_TEXTUREFILTER_BILINEAR) mode |= kModeMinBilinear;
  if (record.magfilter_mode == GR_TEXTUREFILTER_BILINEAR) mode |= kModeMagBilinear;
  if (record.s_clamp_mode == GR_TEXTURECLAMP_CLAMP) mode |= kModeClampS;
  if (record.t_clamp_mode == GR_TEXTURECLAMP_CLAMP) mode |= kModeClampT;
  if (record.mipmap_mode == GR_MIPMAP_NEAREST_DITHER) mode |= kModeLodDither;
  if (record.trilinear) mode |= kModeTrilinear;
  return mode;
}

bool is_mipmap_mode(GrMipMapMode_t mode) {
  return mode == GR_MIPMAP_DISABLE || mode == GR_MIPMAP_NEAREST ||
         mode == GR_MIPMAP_NEAREST_DITHER;
}
bool is_clamp_mode(GrTextureClampMode_t mode) {
  return mode == GR_TEXTURECLAMP_WRAP || mode == GR_TEXTURECLAMP_CLAMP;
}
bool is_filter_mode(GrTextureFilterMode_t mode) {
  return mode == GR_TEXTUREFILTER_POINT_SAMPLED || mode == GR_TEXTUREFILTER_BILINEAR;
}
bool is_ncc_format(GrTextureFormat_t format) {
  return format == GR_TEXFMT_YIQ_422 || format == GR_TEXFMT_AYIQ_8422;
}

// Checks the enums a record holds besides LODs, aspect and format; reports the first bad one.
bool check_modes(const char *function, GrMipMapMode_t mipmap_mode, GrTextureClampMode_t s_clamp,
                 GrTextureClampMode_t t_clamp, GrTextureFilterMode_t min_filter,
                 GrTextureFilterMode_t mag_filter) {
  std::string problem;
  if (!is_mipmap_mode(mipmap_mode)) problem = "unknown mip-map mode " + std::to_string(mipmap_mode);
  else if (!is_clamp_mode(s_clamp) || !is_clamp_mode(t_clamp)) problem = "unknown clamp mode";
  else if (!is_filter_mode(min_filter) || !is_filter_mode(mag_filter)) problem = "unknown filter mode";
  if (problem.empty()) return true;
  current().report(GLIDESHIM_ERR_INVALID_ENUM, std::string(function) + ": " + problem);
  return false;
}

// Where the record's largest level starts in TMU memory: its chain base (where a 256 level
// would begin, below 0 for chains that start small) plus that level's offset in a full chain,
// as guTexDownloadMipMapLevel computes it. Signed, so a changed record can be checked.
std::int64_t start_address(const GrMipMapInfo &record) {
  const auto base = static_cast<std::int64_t>(static_cast<std::int32_t>(record.tmu_base_address));
  return base + glide_shim::level_offset(record.lod_max, GR_LOD_256, record.aspect_ratio,
                                         record.format, record.odd_even_mask);
}

// The record of `id`, or nullptr after reporting that `id` is not an allocated mip map.
GrMipMapInfo *find_record(const char *function, GrMipMapId_t id) {
  auto &gu = current().gu_textures;
  if (id < gu.next_id) return &gu.records[id];
  current().report(GLIDESHIM_ERR_OUT_OF_RANGE,
                   std::string(function) + ": mip map id " +
                       (id == GR_NULL_MIPMAP_HANDLE ? std::string("GR_NULL_MIPMAP_HANDLE")
                                                    : std::to_string(id)) +
                       " is not allocated (" + std::to_string(gu.next_id) +
                       " ids are, from 0; guTexAllocateMemory hands them out)");
  return nullptr;
}

}  // namespace

namespace glide_shim {

void GuTextureManager::reset() {
  // The table keeps its storage, so pointers from guTexGetMipMapInfo stay valid (and empty).
  if (records.size() != MAX_MIPMAPS_PER_SST) records.resize(MAX_MIPMAPS_PER_SST);
  std::fill(records.begin(), records.end(), GrMipMapInfo{});
  next_id = 0;
  free_base = 0;
  current = GR_NULL_MIPMAP_HANDLE;
  ncc_owner[0] = ncc_owner[1] = GR_NULL_MIPMAP_HANDLE;
  next_ncc_table = GR_NCCTABLE_NCC0;
}

}  // namespace glide_shim

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

GrMipMapId_t guTexAllocateMemory(GrChipID_t tmu, FxU8 odd_even_mask, int width, int height,
                                 GrTextureFormat_t fmt, GrMipMapMode_t mm_mode,
                                 GrLOD_t smallest_lod, GrLOD_t largest_lod,
                                 GrAspectRatio_t aspect, GrTextureClampMode_t s_clamp_mode,
                                 GrTextureClampMode_t t_clamp_mode,
                                 GrTextureFilterMode_t minfilter_mode,
                                 GrTextureFilterMode_t magfilter_mode, float lod_bias,
                                 FxBool trilinear) {
  const char *name = "guTexAllocateMemory";
  auto &ctx = current();
  if (!ctx.require_open(name) || !glide_shim::check_tmu(name, tmu)) return GR_NULL_MIPMAP_HANDLE;
  if (!glide_shim::is_even_odd(odd_even_mask)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, std::string(name) + ": unknown odd_even_mask " +
                                               std::to_string(odd_even_mask));
    return GR_NULL_MIPMAP_HANDLE;
  }
  if (!glide_shim::check_texture_info(name, smallest_lod, largest_lod, aspect, fmt) ||
      !check_modes(name, mm_mode, s_clamp_mode, t_clamp_mode, minfilter_mode, magfilter_mode)) {
    return GR_NULL_MIPMAP_HANDLE;
  }
  if (!std::isfinite(lod_bias) || lod_bias < -8.0f || lod_bias > 7.75f) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, std::string(name) + ": LOD bias " +
                                               std::to_string(lod_bias) + " is outside -8..7.75");
    return GR_NULL_MIPMAP_HANDLE;
  }
  auto &gu = ctx.gu_textures;
  const FxU32 bytes =
      glide_shim::mipmap_bytes(smallest_lod, largest_lod, aspect, fmt, odd_even_mask);
  // The driver also moves a chain that would straddle the 2 MB boundary to 2 MB; with one
  // 2 MB TMU such a chain does not fit at all, so that rule is this check.
  if (bytes > glide_shim::kTmuMemoryBytes - gu.free_base) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               std::string(name) + ": the mip map needs " + std::to_string(bytes) +
                   " bytes of TMU memory; " +
                   std::to_string(glide_shim::kTmuMemoryBytes - gu.free_base) +
                   " are free (guTexMemReset frees all)");
    return GR_NULL_MIPMAP_HANDLE;
  }
  if (gu.next_id >= MAX_MIPMAPS_PER_SST) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               std::string(name) + ": all " + std::to_string(MAX_MIPMAPS_PER_SST) +
                   " mip map ids are in use (guTexMemReset frees them)");
    return GR_NULL_MIPMAP_HANDLE;
  }
  const GrMipMapId_t id = gu.next_id++;
  GrMipMapInfo &record = gu.records[id];
  record = GrMipMapInfo{};
  record.sst = 0;
  record.valid = FXTRUE;
  record.width = width;
  record.height = height;
  record.aspect_ratio = aspect;
  record.format = fmt;
  record.mipmap_mode = mm_mode;
  record.magfilter_mode = magfilter_mode;
  record.minfilter_mode = minfilter_mode;
  record.s_clamp_mode = s_clamp_mode;
  record.t_clamp_mode = t_clamp_mode;
  record.lod_bias = bias_quarters(lod_bias);
  record.lod_min = smallest_lod;
  record.lod_max = largest_lod;
  record.tmu = tmu;
  record.odd_even_mask = odd_even_mask;
  record.trilinear = trilinear != FXFALSE ? FXTRUE : FXFALSE;
  // The chain base in the driver's unsigned arithmetic: below address 0 it wraps around.
  record.tmu_base_address = static_cast<FxU32>(
      glide_shim::chain_base(gu.free_base, largest_lod, aspect, fmt, odd_even_mask));
  record.tTextureMode = texture_mode_register(record);
  record.tLOD = tlod_register(record);
  if (record.trilinear) {
    // Only the allocation adds these (the driver's rebuild after guTexChangeAttributes does not).
    if ((odd_even_mask & GR_MIPMAPLEVELMASK_ODD) != 0) record.tLOD |= kLodOdd;
    if (odd_even_mask != GR_MIPMAPLEVELMASK_BOTH) record.tLOD |= kLodSplit;
  }
  gu.free_base += bytes;
  return id;
}

FxBool guTexChangeAttributes(GrMipMapId_t mmid, int width, int height, GrTextureFormat_t fmt,
                             GrMipMapMode_t mm_mode, GrLOD_t smallest_lod, GrLOD_t largest_lod,
                             GrAspectRatio_t aspect, GrTextureClampMode_t s_clamp_mode,
                             GrTextureClampMode_t t_clamp_mode,
                             GrTextureFilterMode_t minFilterMode,
                             GrTextureFilterMode_t magFilterMode) {
  const char *name = "guTexChangeAttributes";
  auto &ctx = current();
  if (!ctx.require_open(name)) return FXFALSE;
  GrMipMapInfo *record = find_record(name, mmid);
  if (record == nullptr) return FXFALSE;
  // -1 keeps an attribute. The changed record is checked whole before it replaces the old one.
  GrMipMapInfo changed = *record;
  if (fmt != -1) changed.format = fmt;
  if (mm_mode != -1) changed.mipmap_mode = mm_mode;
  if (smallest_lod != -1) changed.lod_min = smallest_lod;
  if (largest_lod != -1) changed.lod_max = largest_lod;
  if (minFilterMode != -1) changed.minfilter_mode = minFilterMode;
  if (magFilterMode != -1) changed.magfilter_mode = magFilterMode;
  if (s_clamp_mode != -1) changed.s_clamp_mode = s_clamp_mode;
  if (t_clamp_mode != -1) changed.t_clamp_mode = t_clamp_mode;
  if (aspect != -1) changed.aspect_ratio = aspect;
  if (width != -1) changed.width = width;
  if (height != -1) changed.height = height;
  if (!glide_shim::check_texture_info(name, changed.lod_min, changed.lod_max,
                                      changed.aspect_ratio, changed.format) ||
      !check_modes(name, changed.mipmap_mode, changed.s_clamp_mode, changed.t_clamp_mode,
                   changed.minfilter_mode, changed.magfilter_mode)) {
    return FXFALSE;
  }
  // The base address stays (as in the driver), so a new size or format moves where the largest
  // level starts; guTexSource must still find the whole chain inside TMU memory.
  const std::int64_t start = start_address(changed);
  const FxU32 bytes = glide_shim::mipmap_bytes(changed.lod_min, changed.lod_max,
                                               changed.aspect_ratio, changed.format,
                                               changed.odd_even_mask);
  if (start < 0 || start % 8 != 0 ||
      start + static_cast<std::int64_t>(bytes) > glide_shim::kTmuMemoryBytes) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               std::string(name) + ": with these attributes mip map " + std::to_string(mmid) +
                   " would start at " + std::to_string(start) + " (" + std::to_string(bytes) +
                   " bytes): misaligned or outside TMU memory");
    return FXFALSE;
  }
  changed.tTextureMode = texture_mode_register(changed);
  changed.tLOD = tlod_register(changed);
  *record = changed;
  return FXTRUE;
}

void guTexDownloadMipMap(GrMipMapId_t mmid, const void *src, const GuNccTable *table) {
  const char *name = "guTexDownloadMipMap";
  auto &ctx = current();
  if (!ctx.require_open(name)) return;
  GrMipMapInfo *record = find_record(name, mmid);
  if (record == nullptr) return;
  if (src == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, std::string(name) + ": src is NULL");
    return;
  }
  if (is_ncc_format(record->format) && table == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER,
               std::string(name) + ": a YIQ mip map needs its NCC table, and it is NULL");
    return;
  }
  // The record keeps the data pointer and (for YIQ formats) a copy of the NCC table, which
  // guTexSource loads into the TMU.
  record->data = const_cast<void *>(src);
  if (is_ncc_format(record->format)) record->ncc_table = *table;
  GrTexInfo info{record->lod_min, record->lod_max, record->aspect_ratio, record->format,
                 record->data};
  grTexDownloadMipMap(record->tmu, static_cast<FxU32>(start_address(*record)),
                      record->odd_even_mask, &info);
}

void guTexDownloadMipMapLevel(GrMipMapId_t mmid, GrLOD_t lod, const void **src) {
  const char *name = "guTexDownloadMipMapLevel";
  auto &ctx = current();
  if (!ctx.require_open(name)) return;
  const GrMipMapInfo *record = find_record(name, mmid);
  if (record == nullptr) return;
  if (src == nullptr || *src == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, std::string(name) + ": src or *src is NULL");
    return;
  }
  if (lod < record->lod_max || lod > record->lod_min) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               std::string(name) + ": LOD " + std::to_string(lod) + " is not in mip map " +
                   std::to_string(mmid) + "'s chain (" + std::to_string(record->lod_max) +
                   ".." + std::to_string(record->lod_min) + ")");
    return;
  }
  grTexDownloadMipMapLevel(record->tmu, static_cast<FxU32>(start_address(*record)), lod,
                           record->lod_max, record->aspect_ratio, record->format,
                           record->odd_even_mask, const_cast<void *>(*src));
  // The caller's pointer moves past this level's texels (plain width x height, as packed in
  // host memory), whether or not the evenOdd mask kept the level.
  const glide_shim::LevelSize size = glide_shim::level_size(lod, record->aspect_ratio);
  *src = static_cast<const std::uint8_t *>(*src) +
         size.width * size.height * glide_shim::bytes_per_texel(record->format);
}

GrMipMapId_t guTexGetCurrentMipMap(GrChipID_t tmu) {
  auto &ctx = current();
  if (!ctx.require_open("guTexGetCurrentMipMap") ||
      !glide_shim::check_tmu("guTexGetCurrentMipMap", tmu)) {
    return GR_NULL_MIPMAP_HANDLE;
  }
  return ctx.gu_textures.current;
}

GrMipMapInfo *guTexGetMipMapInfo(GrMipMapId_t mmid) {
  const char *name = "guTexGetMipMapInfo";
  auto &ctx = current();
  if (!ctx.require_open(name)) return nullptr;
  if (GrMipMapInfo *record = find_record(name, mmid)) return record;
  // Like the driver, an id of the table that is not allocated yet gives its empty record
  // (valid == FXFALSE); the error above says so. Ids past the table give NULL.
  if (mmid < MAX_MIPMAPS_PER_SST) return &ctx.gu_textures.records[mmid];
  return nullptr;
}

FxU32 guTexMemQueryAvail(GrChipID_t tmu) {
  auto &ctx = current();
  if (!ctx.require_open("guTexMemQueryAvail") ||
      !glide_shim::check_tmu("guTexMemQueryAvail", tmu)) {
    return 0;
  }
  return glide_shim::kTmuMemoryBytes - ctx.gu_textures.free_base;
}

void guTexMemReset(void) {
  auto &ctx = current();
  if (!ctx.require_open("guTexMemReset")) return;
  ctx.gu_textures.reset();
}

void guTexSource(GrMipMapId_t mmid) {
  const char *name = "guTexSource";
  auto &ctx = current();
  if (!ctx.require_open(name)) return;
  const GrMipMapInfo *record = find_record(name, mmid);
  if (record == nullptr) return;
  // Every record is valid and inside TMU memory (guTexAllocateMemory and guTexChangeAttributes
  // check), so none of these calls can refuse.
  GrTexInfo info{record->lod_min, record->lod_max, record->aspect_ratio, record->format,
                 nullptr};
  grTexSource(record->tmu, static_cast<FxU32>(start_address(*record)), record->odd_even_mask,
              &info);
  // The record's tLOD replaces the register whole, so multibase addressing ends.
  grTexMultibase(record->tmu, FXFALSE);
  grTexClampMode(record->tmu, record->s_clamp_mode, record->t_clamp_mode);
  grTexFilterMode(record->tmu, record->minfilter_mode, record->magfilter_mode);
  grTexMipMapMode(record->tmu, record->mipmap_mode, record->trilinear);
  // The bias is already in quarters; grTexLodBiasValue would round negative ones again.
  ctx.flush();
  ctx.tmu.lod_bias = bias_from_quarters(record->lod_bias);
  auto &gu = ctx.gu_textures;
  GrNCCTable_t table = GR_NCCTABLE_NCC0;
  if (is_ncc_format(record->format)) {
    // The driver's choice of table: the one this id loaded before, else the least recently
    // loaded one. The table is loaded again even when it is there (the driver skips that), so
    // a program's own grTexDownloadTable in between cannot leave the wrong table in place.
    if (gu.ncc_owner[GR_NCCTABLE_NCC1] == mmid) {
      table = GR_NCCTABLE_NCC1;
    } else if (gu.ncc_owner[GR_NCCTABLE_NCC0] != mmid) {
      table = gu.next_ncc_table;
      gu.ncc_owner[table] = mmid;
      gu.next_ncc_table = table == GR_NCCTABLE_NCC0 ? GR_NCCTABLE_NCC1 : GR_NCCTABLE_NCC0;
    }
    GuNccTable ncc = record->ncc_table;
    grTexDownloadTable(record->tmu, table, &ncc);
  }
  // Other formats clear the NCC select bit: table 0.
  grTexNCCTable(record->tmu, table);
  gu.current = mmid;
}

}  // namespace glide_shim_api
