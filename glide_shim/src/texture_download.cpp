// Chapter "texture download": copying texel data into TMU memory, byte for byte, and the
// palette and NCC tables into the TMU's look-up registers. The format in GrTexInfo only sizes
// the copy; how the bytes are read is decided later by grTexSource, which is what lets the
// article download 565 frame-buffer words as an ARGB_4444 texture.
#include "context.h"
#include "gl/gl_renderer.h"
#include "texture_layout.h"

#include <cstring>
#include <string>

using glide_shim::current;

namespace {

// True when [address, address + bytes) lies in TMU memory; otherwise reports and returns false.
bool fits_in_memory(const char *function, FxU32 address, FxU32 bytes) {
  if (address <= glide_shim::kTmuMemoryBytes && bytes <= glide_shim::kTmuMemoryBytes - address) {
    return true;
  }
  current().report(GLIDESHIM_ERR_OUT_OF_RANGE,
                   std::string(function) + ": " + std::to_string(bytes) + " bytes at address " +
                       std::to_string(address) + " run past the end of TMU memory (" +
                       std::to_string(glide_shim::kTmuMemoryBytes) + " bytes)");
  return false;
}

void write_memory(FxU32 address, const void *data, FxU32 bytes) {
  auto &ctx = current();
  ctx.flush();  // draws already queued must still see the old texels
  std::memcpy(ctx.tmu.memory.data() + address, data, bytes);
  ctx.renderer->textures().invalidate(address, address + bytes);
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grTexDownloadMipMap(GrChipID_t tmu, FxU32 startAddress, FxU32 evenOdd, GrTexInfo *info) {
  auto &ctx = current();
  if (!ctx.require_open("grTexDownloadMipMap") || !glide_shim::check_tmu("grTexDownloadMipMap", tmu))
    return;
  if (info == nullptr || info->data == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grTexDownloadMipMap: info or info->data is NULL");
    return;
  }
  if (!glide_shim::is_even_odd(evenOdd)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grTexDownloadMipMap: unknown evenOdd mask");
    return;
  }
  if (!glide_shim::check_texture_info("grTexDownloadMipMap", info->smallLod, info->largeLod,
                                      info->aspectRatio, info->format)) {
    return;
  }
  if (startAddress % 8 != 0) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "grTexDownloadMipMap: start address " +
                                               std::to_string(startAddress) +
                                               " is not 8-byte aligned");
    return;
  }
  // GrTexInfo.data packs every level largest first at its plain texel count; TMU memory holds
  // the levels evenOdd selects at their SST-1 footprints (texture_layout.h), so copy by level.
  const auto *source = static_cast<const std::uint8_t *>(info->data);
  const FxU32 stored = glide_shim::mipmap_bytes(info->smallLod, info->largeLod,
                                                info->aspectRatio, info->format, evenOdd);
  if (!fits_in_memory("grTexDownloadMipMap", startAddress, stored)) return;
  FxU32 from = 0;
  for (GrLOD_t lod = info->largeLod; lod <= info->smallLod; ++lod) {
    const glide_shim::LevelSize size = glide_shim::level_size(lod, info->aspectRatio);
    const auto bytes = static_cast<FxU32>(size.width * size.height *
                                          glide_shim::bytes_per_texel(info->format));
    if (glide_shim::level_selected(lod, evenOdd)) {
      const FxU32 to = glide_shim::level_offset(lod, info->largeLod, info->aspectRatio,
                                                info->format, evenOdd);
      write_memory(startAddress + to, source + from, bytes);
    }
    from += bytes;
  }
}

}  // namespace glide_shim_api

namespace {

// Rows start..end of one level; `name` is the entry point the program called, for errors.
void download_rows(const char *name, GrChipID_t tmu, FxU32 startAddress, GrLOD_t thisLod,
                   GrLOD_t largeLod, GrAspectRatio_t aspectRatio, GrTextureFormat_t format,
                   FxU32 evenOdd, const void *data, int start, bool whole_level_end, int end) {
  auto &ctx = current();
  if (!ctx.require_open(name) || !glide_shim::check_tmu(name, tmu)) return;
  if (data == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, std::string(name) + ": data is NULL");
    return;
  }
  if (!glide_shim::is_even_odd(evenOdd)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, std::string(name) + ": unknown evenOdd mask");
    return;
  }
  if (!glide_shim::check_texture_info(name, thisLod, largeLod, aspectRatio, format)) return;
  if (startAddress % 8 != 0) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, std::string(name) + ": start address " +
                                               std::to_string(startAddress) +
                                               " is not 8-byte aligned");
    return;
  }
  const glide_shim::LevelSize size = glide_shim::level_size(thisLod, aspectRatio);
  if (whole_level_end) end = size.height - 1;
  if (start < 0 || end < start || end >= size.height) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               std::string(name) + ": rows " + std::to_string(start) + ".." +
                   std::to_string(end) + " are not inside the level's 0.." +
                   std::to_string(size.height - 1));
    return;
  }
  const FxU32 offset = glide_shim::level_offset(thisLod, largeLod, aspectRatio, format, evenOdd);
  const auto row_bytes =
      static_cast<FxU32>(size.width * glide_shim::bytes_per_texel(format));
  const FxU32 level_bytes = row_bytes * static_cast<FxU32>(size.height);
  // A whole chain is at most ~175 KB, so offset + level_bytes cannot overflow.
  if (!fits_in_memory(name, startAddress, offset + level_bytes)) return;
  // The driver skips a level the evenOdd mask leaves out (it lives on the other TMU).
  if (!glide_shim::level_selected(thisLod, evenOdd)) return;
  const FxU32 first_row = static_cast<FxU32>(start);
  write_memory(startAddress + offset + first_row * row_bytes, data,
               row_bytes * static_cast<FxU32>(end - start + 1));
}

void download_table(const char *name, GrChipID_t tmu, GrTexTable_t type, const void *data,
                    int start, bool whole_table_end, int end) {
  auto &ctx = current();
  if (!ctx.require_open(name) || !glide_shim::check_tmu(name, tmu)) return;
  if (type != GR_TEXTABLE_NCC0 && type != GR_TEXTABLE_NCC1 && type != GR_TEXTABLE_PALETTE) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               std::string(name) + ": unknown table type " + std::to_string(type));
    return;
  }
  if (data == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, std::string(name) + ": data is NULL");
    return;
  }
  // A palette has 256 entries; an NCC table is 12 packed words (GuNccTable.packed_data).
  const int entries = type == GR_TEXTABLE_PALETTE ? 256 : 12;
  if (whole_table_end) end = entries - 1;
  if (start < 0 || end < start || end >= entries) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               std::string(name) + ": entries " + std::to_string(start) + ".." +
                   std::to_string(end) + " are outside the table's 0.." +
                   std::to_string(entries - 1));
    return;
  }
  ctx.flush();  // draws already queued decode with the old table
  glide_shim::TextureTables &tables = ctx.tmu.tables;
  const auto first = static_cast<std::size_t>(start);
  const auto count = static_cast<std::size_t>(end - start + 1);
  if (type == GR_TEXTABLE_PALETTE) {
    const auto *palette = static_cast<const GuTexPalette *>(data);
    std::memcpy(tables.palette + first, palette->data + first, count * sizeof(FxU32));
  } else {
    const auto *ncc = static_cast<const GuNccTable *>(data);
    std::memcpy(tables.ncc[type] + first, ncc->packed_data + first, count * sizeof(FxU32));
  }
  ++tables.generation;
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grTexDownloadMipMapLevelPartial(GrChipID_t tmu, FxU32 startAddress, GrLOD_t thisLod,
                                     GrLOD_t largeLod, GrAspectRatio_t aspectRatio,
                                     GrTextureFormat_t format, FxU32 evenOdd, void *data,
                                     int start, int end) {
  download_rows("grTexDownloadMipMapLevelPartial", tmu, startAddress, thisLod, largeLod,
                aspectRatio, format, evenOdd, data, start, false, end);
}

void grTexDownloadMipMapLevel(GrChipID_t tmu, FxU32 startAddress, GrLOD_t thisLod,
                              GrLOD_t largeLod, GrAspectRatio_t aspectRatio,
                              GrTextureFormat_t format, FxU32 evenOdd, void *data) {
  download_rows("grTexDownloadMipMapLevel", tmu, startAddress, thisLod, largeLod, aspectRatio,
                format, evenOdd, data, 0, true, 0);
}

void grTexDownloadTablePartial(GrChipID_t tmu, GrTexTable_t type, void *data, int start,
                               int end) {
  download_table("grTexDownloadTablePartial", tmu, type, data, start, false, end);
}

void grTexDownloadTable(GrChipID_t tmu, GrTexTable_t type, void *data) {
  download_table("grTexDownloadTable", tmu, type, data, 0, true, 0);
}

}  // namespace glide_shim_api
