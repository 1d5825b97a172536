// Chapter "texture download": copying texel data into TMU memory, byte for byte. The format in
// GrTexInfo only sizes the copy; how the bytes are read is decided later by grTexSource, which is
// what lets the article download 565 frame-buffer words as an ARGB_4444 texture.
#include "context.h"
#include "gl_renderer.h"
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

extern "C" {

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

void grTexDownloadMipMapLevel(GrChipID_t tmu, FxU32 startAddress, GrLOD_t thisLod,
                              GrLOD_t largeLod, GrAspectRatio_t aspectRatio,
                              GrTextureFormat_t format, FxU32 evenOdd, void *data) {
  auto &ctx = current();
  if (!ctx.require_open("grTexDownloadMipMapLevel") ||
      !glide_shim::check_tmu("grTexDownloadMipMapLevel", tmu))
    return;
  if (data == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grTexDownloadMipMapLevel: data is NULL");
    return;
  }
  if (!glide_shim::is_even_odd(evenOdd)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grTexDownloadMipMapLevel: unknown evenOdd mask");
    return;
  }
  if (!glide_shim::check_texture_info("grTexDownloadMipMapLevel", thisLod, largeLod, aspectRatio,
                                      format)) {
    return;
  }
  if (startAddress % 8 != 0) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "grTexDownloadMipMapLevel: start address " +
                                               std::to_string(startAddress) +
                                               " is not 8-byte aligned");
    return;
  }
  const FxU32 offset =
      glide_shim::level_offset(thisLod, largeLod, aspectRatio, format, evenOdd);
  const glide_shim::LevelSize size = glide_shim::level_size(thisLod, aspectRatio);
  const auto bytes =
      static_cast<FxU32>(size.width * size.height * glide_shim::bytes_per_texel(format));
  // A whole chain is at most ~175 KB, so offset + bytes cannot overflow.
  if (!fits_in_memory("grTexDownloadMipMapLevel", startAddress, offset + bytes)) return;
  write_memory(startAddress + offset, data, bytes);
}

}  // extern "C"
