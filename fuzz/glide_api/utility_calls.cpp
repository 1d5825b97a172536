// The calls of the utility library and the shim's additions that take several steps: .3df files,
// RLE bitmaps, the gu texture manager, multipass, status queries, closing and reopening, and a
// textured draw set up as a program sets one up.
#include "glide_api/arguments.h"
#include "glide_api/calls.h"
#include "glide_api/checks.h"
#include "glide_api/window.h"

#include <glideutl.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace glide_api_fuzz {

std::string g_scratch;
GrState g_saved_state;
bool g_have_saved_state = false;

namespace {

const char *const kFormatLines[] = {"rgb565", "argb1555", "argb4444", "i8",  "a8",   "ai44", "yiq",
                                    "rgb332", "argb8332", "ayiq8422", "ai88", "p8", "ap88", "bogus"};

// Bytes for a .3df file: mostly a plausible header (any format, LOD range and aspect) followed
// by fuzzed bytes, sometimes only fuzzed bytes.
std::string three_df_bytes(FuzzedDataProvider &in) {
  std::string text;
  if (in.ConsumeIntegralInRange(0, 7) != 0) {
    const int small_side = 1 << in.ConsumeIntegralInRange(0, 9);
    const int large_side = 1 << in.ConsumeIntegralInRange(0, 9);
    text = std::string(in.ConsumeBool() ? "3df v1.1\n" : "3df v1.0\n") +
           kFormatLines[in.ConsumeIntegralInRange<std::size_t>(0, 13)] + "\nlod range: " +
           std::to_string(small_side) + " " + std::to_string(large_side) + "\naspect ratio: " +
           std::to_string(1 << in.ConsumeIntegralInRange(0, 4)) + " " +
           std::to_string(1 << in.ConsumeIntegralInRange(0, 4)) + "\n";
  }
  const std::size_t body = in.ConsumeIntegralInRange<std::size_t>(0, 4096);
  const std::vector<std::uint8_t> bytes = in.ConsumeBytes<std::uint8_t>(std::min<std::size_t>(body, 256));
  for (std::size_t i = 0; i < body; ++i)
    text.push_back(static_cast<char>(bytes.empty() ? i : bytes[i % bytes.size()]));
  return text;
}


}  // namespace

void three_df(FuzzedDataProvider &in) {
  const std::string path = g_scratch + "/input.3df";
  const std::string bytes = three_df_bytes(in);
  if (FILE *file = std::fopen(path.c_str(), "wb")) {
    std::fwrite(bytes.data(), 1, bytes.size(), file);
    std::fclose(file);
  }
  const bool missing = in.ConsumeIntegralInRange(0, 15) == 0;
  const std::string name = missing ? g_scratch + "/no_such.3df" : path;
  Gu3dfInfo info{};
  FxBool ok = FXFALSE;
  checked("gu3dfGetInfo", [&] { ok = gu3dfGetInfo(in.ConsumeIntegralInRange(0, 31) == 0 ? nullptr : name.c_str(), &info); });
  if (!ok) return;
  if (info.mem_required > (1u << 20)) violated("gu3dfGetInfo", "mem_required is beyond any .3df chain");
  std::vector<std::uint8_t> data(info.mem_required + 1);
  info.data = data.data();
  checked("gu3dfLoad", [&] { ok = gu3dfLoad(name.c_str(), &info); });
  if (ok && info.data != data.data()) violated("gu3dfLoad", "moved the caller's data pointer");
  // Download what was loaded, as a program would.
  if (ok) {
    GrTexInfo tex{info.header.small_lod, info.header.large_lod, info.header.aspect_ratio,
                  info.header.format, info.data};
    checked("grTexDownloadMipMap", kMemory,
            [&] { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &tex); });
  }
}

// An RLE bitmap as ConvertAndDownloadRle reads it: 4 skipped bytes, one length byte per row,
// then the rows, each normally ending in a run of 0 (with a corrupt row now and then).
std::vector<FxU8> rle_bitmap(FuzzedDataProvider &in, long rows) {
  std::vector<std::vector<FxU8>> row_bytes(static_cast<std::size_t>(rows));
  for (auto &row : row_bytes) {
    const int codes = in.ConsumeIntegralInRange(0, 12);
    for (int i = 0; i < codes; ++i) {
      if (in.ConsumeBool()) {
        row.push_back(static_cast<FxU8>(0xE0 | in.ConsumeIntegralInRange(1, 31)));
        row.push_back(in.ConsumeIntegral<FxU8>());
      } else {
        row.push_back(static_cast<FxU8>(in.ConsumeIntegralInRange(0, 0xDF)));
      }
    }
    if (in.ConsumeIntegralInRange(0, 15) != 0) row.push_back(0xE0);  // the end code
    if (row.size() > 255) row.resize(255);
  }
  std::vector<FxU8> bitmap(4, 0);
  for (const auto &row : row_bytes) bitmap.push_back(static_cast<FxU8>(row.size()));
  for (const auto &row : row_bytes) bitmap.insert(bitmap.end(), row.begin(), row.end());
  return bitmap;
}

// A gu mip map id: mostly one the manager handed out, sometimes any value.
GrMipMapId_t mip_map_id(FuzzedDataProvider &in) {
  const FxU32 next = glide_shim::current().gu_textures.next_id;
  if (next > 0 && in.ConsumeIntegralInRange(0, 7) != 0) return in.ConsumeIntegralInRange<FxU32>(0, next - 1);
  return in.ConsumeBool() ? GR_NULL_MIPMAP_HANDLE : small_or_any(in, MAX_MIPMAPS_PER_SST + 2);
}

// The host bytes of mip map `id`'s whole chain, or 0 when it is no allocated id.
std::size_t mip_map_bytes(GrMipMapId_t id) {
  const GlideContext &ctx = glide_shim::current();
  if (id >= ctx.gu_textures.next_id || id >= ctx.gu_textures.records.size()) return 0;
  const GrMipMapInfo &r = ctx.gu_textures.records[id];
  return host_chain_bytes(r.lod_min, r.lod_max, r.aspect_ratio, r.format);
}

void gu_allocate(FuzzedDataProvider &in) {
  const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
  const FxU8 mask = static_cast<FxU8>(small_or_any(in, 4));
  GrTexInfo info = texture_info(in);
  const int mm = enum_value(in, GR_MIPMAP_DISABLE, GR_MIPMAP_NEAREST_DITHER);
  const int s = enum_value(in, 0, 1), t = enum_value(in, 0, 1);
  const int min = enum_value(in, 0, 1), mag = enum_value(in, 0, 1);
  const float bias = coordinate(in, 8.0f);
  const FxBool trilinear = boolean(in);
  const FxU32 free_before = glide_shim::current().gu_textures.free_base;
  GrMipMapId_t id = GR_NULL_MIPMAP_HANDLE;
  checked("guTexAllocateMemory", kGuRecords, [&] {
    id = guTexAllocateMemory(tmu, mask, 256, 256, info.format, mm, info.smallLod, info.largeLod,
                             info.aspectRatio, s, t, min, mag, bias, trilinear);
  });
  const GlideContext &ctx = glide_shim::current();
  if (id != GR_NULL_MIPMAP_HANDLE) {
    if (id >= ctx.gu_textures.next_id) violated("guTexAllocateMemory", "an id beyond the manager's count");
    // The driver (digutex.c) advances the free pointer by grTexTextureMemRequired of the mask's
    // levels: 0 bytes when the mask selects none of the chain's levels (one even level, odd mask).
    const FxU32 required = grTexTextureMemRequired(mask, &info);
    if (ctx.gu_textures.free_base - free_before != required ||
        ctx.gu_textures.free_base > glide_shim::kTmuMemoryBytes)
      violated("guTexAllocateMemory", "the free pointer did not advance by the chain's size inside TMU memory");
  }
}

void gu_change(FuzzedDataProvider &in) {
  const GrMipMapId_t id = mip_map_id(in);
  auto keep_or = [&](int lo, int hi) { return in.ConsumeBool() ? -1 : enum_value(in, lo, hi); };
  const int width = keep_or(1, 256), height = keep_or(1, 256);
  const int fmt = keep_or(GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
  const int mm = keep_or(GR_MIPMAP_DISABLE, GR_MIPMAP_NEAREST_DITHER);
  const int small = keep_or(GR_LOD_256, GR_LOD_1), large = keep_or(GR_LOD_256, GR_LOD_1);
  const int aspect = keep_or(GR_ASPECT_8x1, GR_ASPECT_1x8);
  const int s = keep_or(0, 1), t = keep_or(0, 1), min = keep_or(0, 1), mag = keep_or(0, 1);
  checked("guTexChangeAttributes", kGuRecords, [&] {
    guTexChangeAttributes(id, width, height, fmt, mm, small, large, aspect, s, t, min, mag);
  });
}

void gu_download(FuzzedDataProvider &in) {
  const GrMipMapId_t id = mip_map_id(in);
  std::vector<std::uint8_t> data = texel_data(in, mip_map_bytes(id));
  GuNccTable table{};
  const std::vector<std::uint8_t> bytes = in.ConsumeBytes<std::uint8_t>(sizeof table);
  if (!bytes.empty()) std::memcpy(&table, bytes.data(), bytes.size());
  const bool null_data = in.ConsumeIntegralInRange(0, 15) == 0;
  const bool null_table = in.ConsumeIntegralInRange(0, 7) == 0;
  if (in.ConsumeBool()) {
    checked("guTexDownloadMipMap", kAll, [&] {
      guTexDownloadMipMap(id, null_data ? nullptr : data.data(), null_table ? nullptr : &table);
    });
    return;
  }
  // One level at a time, as the caller's pointer advances.
  const GrLOD_t lod = enum_value(in, GR_LOD_256, GR_LOD_1);
  const GlideContext &ctx = glide_shim::current();
  std::vector<std::uint8_t> level;
  if (id < ctx.gu_textures.next_id) {
    const GrMipMapInfo &r = ctx.gu_textures.records[id];
    level = texel_data(in, host_chain_bytes(lod, lod, r.aspect_ratio, r.format));
  } else {
    level = texel_data(in, 0);
  }
  const void *src = null_data ? nullptr : level.data();
  checked("guTexDownloadMipMapLevel", kAll, [&] { guTexDownloadMipMapLevel(id, lod, &src); });
}

void lfb_layout(FuzzedDataProvider &in) {
  const FxBool swizzle = boolean(in), swap = boolean(in);
  checked("grLfbWriteColorSwizzle", [&] { grLfbWriteColorSwizzle(swizzle, swap); });
  const int format = enum_value(in, GR_COLORFORMAT_ARGB, GR_COLORFORMAT_BGRA);
  checked("grLfbWriteColorFormat", [&] { grLfbWriteColorFormat(format); });
}

void getters() {
  const GlideContext &ctx = glide_shim::current();
  int pending = -1;
  FxU32 status = 0, line = 1, width = 0, height = 0;
  FxBool busy = FXTRUE, retrace = FXFALSE;
  checked("grBufferNumPending", [&] { pending = grBufferNumPending(); });
  checked("grSstIsBusy", [&] { busy = grSstIsBusy(); });
  checked("grSstStatus", [&] { status = grSstStatus(); });
  checked("grSstVideoLine", [&] { line = grSstVideoLine(); });
  checked("grSstVRetraceOn", [&] { retrace = grSstVRetraceOn(); });
  checked("grSstScreenWidth", [&] { width = grSstScreenWidth(); });
  checked("grSstScreenHeight", [&] { height = grSstScreenHeight(); });
  if (ctx.display.open && !ctx.plain_gl) {
    if (pending < 0 || busy != FXFALSE || retrace == FXFALSE || line != 0 || (status & 0x3F) != 0x3F)
      violated("the status queries", "an idle board reported work or no retrace");
    if (width != static_cast<FxU32>(ctx.display.width) || height != static_cast<FxU32>(ctx.display.height))
      violated("grSstScreenWidth", "disagrees with the window");
  }
}

void multipass(FuzzedDataProvider &in, float span) {
  switch (in.ConsumeIntegralInRange(0, 3)) {
    case 0:
      checked("guMPInit", [] { guMPInit(); });
      break;
    case 1: {
      const FxU32 function = small_or_any(in, GR_MPTEXTURECOMBINE_SUBTRACT + 1);
      checked("guMPTexCombineFunction", [&] { guMPTexCombineFunction(function); });
      break;
    }
    case 2: {
      const GrChipID_t tmu = enum_value(in, 0, 1);
      const GrMipMapId_t id = mip_map_id(in);
      checked("guMPTexSource", kGuRecords, [&] { guMPTexSource(tmu, id); });
      break;
    }
    default: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      checked("guMPDrawTriangle", [&] { guMPDrawTriangle(&a, &b, &c); });
      break;
    }
  }
}

// Closing the window (or the library) and opening it again: the costly path of a new GL
// context, taken rarely so that the run stays fast.
void close_and_reopen(FuzzedDataProvider &in) {
  if (in.ConsumeIntegralInRange(0, 7) != 0) return;
  if (in.ConsumeBool()) {
    checked("grSstWinClose", [] { grSstWinClose(); });
    if (glide_shim::current().display.open) violated("grSstWinClose", "the window is still open");
  } else {
    checked("grGlideShutdown", [] { grGlideShutdown(); });
    if (glide_shim::current().display.open || glide_shim::current().initialized)
      violated("grGlideShutdown", "the library is still open");
    // Calls with no library open are refused, and change nothing.
    FxU32 width = 1;
    checked("grSstScreenWidth", [&] { width = grSstScreenWidth(); });
    if (width != 0) violated("grSstScreenWidth", "a size with no window open");
    checked("grGlideInit", [] { grGlideInit(); });
  }
  if (in.ConsumeBool()) {
    WindowRequest r = window_request(in);
    open_window(r);
  }
}

// A textured triangle as a program draws one: a valid mip map downloaded and made the source,
// a texture combine and colour combine that read it, random filtering, clamping and mip-mapping,
// so that draws go through the texture cache and every format's decoding.
void textured_draw(FuzzedDataProvider &in, float span) {
  static constexpr GrTextureFormat_t kFormats[] = {
      GR_TEXFMT_RGB_332,   GR_TEXFMT_YIQ_422,   GR_TEXFMT_ALPHA_8,          GR_TEXFMT_INTENSITY_8,
      GR_TEXFMT_ALPHA_INTENSITY_44, GR_TEXFMT_P_8, GR_TEXFMT_ARGB_8332,     GR_TEXFMT_AYIQ_8422,
      GR_TEXFMT_RGB_565,   GR_TEXFMT_ARGB_1555, GR_TEXFMT_ARGB_4444, GR_TEXFMT_ALPHA_INTENSITY_88,
      GR_TEXFMT_AP_88};
  GrTexInfo info{};
  info.largeLod = in.ConsumeIntegralInRange(GR_LOD_256, GR_LOD_1);
  info.smallLod = in.ConsumeIntegralInRange(info.largeLod, GR_LOD_1);
  info.aspectRatio = in.ConsumeIntegralInRange(GR_ASPECT_8x1, GR_ASPECT_1x8);
  info.format = kFormats[in.ConsumeIntegralInRange<std::size_t>(0, 12)];
  std::vector<std::uint8_t> data =
      texel_data(in, host_chain_bytes(info.smallLod, info.largeLod, info.aspectRatio, info.format));
  info.data = data.data();
  const FxU32 address = in.ConsumeIntegralInRange<FxU32>(0, 15) * 65536u;
  checked("grTexDownloadMipMap", kMemory,
          [&] { grTexDownloadMipMap(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info); });
  checked("grTexSource", [&] { grTexSource(GR_TMU0, address, GR_MIPMAPLEVELMASK_BOTH, &info); });
  const int texture_combine = in.ConsumeIntegralInRange(GR_TEXTURECOMBINE_DECAL, GR_TEXTURECOMBINE_ONE);
  checked("guTexCombineFunction", [&] { guTexCombineFunction(GR_TMU0, texture_combine); });
  const int color_combine = in.ConsumeIntegralInRange(GR_COLORCOMBINE_DECAL_TEXTURE,
                                                      GR_COLORCOMBINE_TEXTURE_TIMES_ALPHA_ADD_ITRGB);
  checked("guColorCombineFunction", [&] { guColorCombineFunction(color_combine); });
  const int filter = in.ConsumeIntegralInRange(0, 1), clamp = in.ConsumeIntegralInRange(0, 1);
  checked("grTexFilterMode", [&] { grTexFilterMode(GR_TMU0, filter, filter); });
  checked("grTexClampMode", [&] { grTexClampMode(GR_TMU0, clamp, clamp); });
  const int mipmap = in.ConsumeIntegralInRange(GR_MIPMAP_DISABLE, GR_MIPMAP_NEAREST_DITHER);
  checked("grTexMipMapMode", [&] { grTexMipMapMode(GR_TMU0, mipmap, FXFALSE); });
  const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
  checked("grDrawTriangle", [&] { grDrawTriangle(&a, &b, &c); });
}

}  // namespace glide_api_fuzz
