// The second half of the call menu: the rest of the public entry points (anti-aliased draws,
// board queries, texture downloads by level, part and RLE, the gu manager, fog generators,
// movies, the shim's own functions, state save and restore, window changes).
#include "glide_api/arguments.h"
#include "glide_api/calls.h"
#include "glide_api/checks.h"
#include "glide_api/window.h"

#include <glide_shim.h>
#include <glideutl.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace glide_api_fuzz {

void more_calls(FuzzedDataProvider &in, float span) {
  GlideContext &ctx = glide_shim::current();
  switch (in.ConsumeIntegralInRange(0, 42)) {
    case 0: {
      const GrVertex v = vertex(in, span);
      checked("grAADrawPoint", [&] { grAADrawPoint(in.ConsumeIntegralInRange(0, 31) == 0 ? nullptr : &v); });
      break;
    }
    case 1: {
      const GrVertex a = vertex(in, span), b = vertex(in, span);
      checked("grAADrawLine", [&] { grAADrawLine(&a, &b); });
      break;
    }
    case 2: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      checked("guAADrawTriangleWithClip", [&] { guAADrawTriangleWithClip(&a, &b, &c); });
      break;
    }
    case 3:
      getters();
      break;
    case 4: {
      GrHwConfiguration config{};
      const bool null = in.ConsumeIntegralInRange(0, 7) == 0;
      checked("grSstQueryBoards", [&] { grSstQueryBoards(null ? nullptr : &config); });
      checked("grSstQueryHardware", [&] { grSstQueryHardware(null ? nullptr : &config); });
      break;
    }
    case 5: {
      const int board = enum_value(in, 0, 0);
      checked("grSstSelect", [&] { grSstSelect(board); });
      break;
    }
    case 6: {
      const FxU32 code = small_or_any(in, GR_CONTROL_MOVE + 1);
      checked("grSstControl", [&] { grSstControl(code); });
      break;
    }
    case 7: {
      const GrChipID_t chip = enum_value(in, GR_TMU0, GR_FBI);
      const int reg = in.ConsumeIntegral<int>();
      const FxU32 value = in.ConsumeIntegral<FxU32>();
      checked("grSstConfigPipeline", [&] { grSstConfigPipeline(chip, reg, value); });
      break;
    }
    case 8: {
      GrSstPerfStats_t stats{};
      const bool null = in.ConsumeIntegralInRange(0, 7) == 0;
      checked("grSstPerfStats", [&] { grSstPerfStats(null ? nullptr : &stats); });
      if (in.ConsumeBool()) checked("grSstResetPerfStats", [] { grSstResetPerfStats(); });
      break;
    }
    case 9: {
      FxU32 processed = 0, drawn = 0;
      checked("grTriStats", [&] { grTriStats(&processed, &drawn); });
      if (drawn > processed) violated("grTriStats", "more triangles drawn than processed");
      if (in.ConsumeBool()) checked("grResetTriStats", [] { grResetTriStats(); });
      break;
    }
    case 10:
      checked("grDisableAllEffects", [] { grDisableAllEffects(); });
      break;
    case 11: {
      char version[80];
      checked("grGlideGetVersion", [&] { grGlideGetVersion(in.ConsumeIntegralInRange(0, 15) == 0 ? nullptr : version); });
      const float x = coordinate(in, span), y = coordinate(in, span);
      checked("grSplash", [&] { grSplash(x, y, span, span, in.ConsumeIntegral<FxU32>()); });
      checked("grGlideShamelessPlug", [&] { grGlideShamelessPlug(boolean(in)); });
      checked("grCheckForRoom", [&] { grCheckForRoom(in.ConsumeIntegral<FxI32>()); });
      break;
    }
    case 12: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxBool enable = boolean(in);
      checked("grTexMultibase", [&] { grTexMultibase(tmu, enable); });
      break;
    }
    case 13: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int range = enum_value(in, GR_TEXBASE_256, GR_TEXBASE_32_TO_1);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8) & ~7u;
      const FxU32 even_odd = small_or_any(in, 4);
      GrTexInfo info = texture_info(in);
      const bool null_info = in.ConsumeIntegralInRange(0, 15) == 0;
      checked("grTexMultibaseAddress",
              [&] { grTexMultibaseAddress(tmu, range, address, even_odd, null_info ? nullptr : &info); });
      break;
    }
    case 14: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8);
      const GrLOD_t this_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrLOD_t large_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrAspectRatio_t aspect = enum_value(in, GR_ASPECT_8x1, GR_ASPECT_1x8);
      const GrTextureFormat_t format = enum_value(in, GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
      const FxU32 even_odd = small_or_any(in, 4);
      const int start = in.ConsumeIntegralInRange(-1, 257), end = in.ConsumeIntegralInRange(-1, 257);
      // The whole level: rows start..end of it are read from the pointer's first row.
      std::vector<std::uint8_t> data = texel_data(in, host_chain_bytes(this_lod, this_lod, aspect, format));
      checked("grTexDownloadMipMapLevelPartial", kMemory, [&] {
        grTexDownloadMipMapLevelPartial(tmu, address, this_lod, large_lod, aspect, format,
                                        even_odd, data.data(), start, end);
      });
      break;
    }
    case 15: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const GrTexTable_t type = enum_value(in, GR_TEXTABLE_NCC0, GR_TEXTABLE_PALETTE);
      GuTexTable table{};
      const std::vector<std::uint8_t> bytes = in.ConsumeBytes<std::uint8_t>(sizeof table);
      if (!bytes.empty()) std::memcpy(&table, bytes.data(), bytes.size());
      const int start = in.ConsumeIntegralInRange(-1, 257), end = in.ConsumeIntegralInRange(-1, 257);
      checked("grTexDownloadTablePartial", [&] { grTexDownloadTablePartial(tmu, type, &table, start, end); });
      break;
    }
    case 16: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8) & ~7u;
      const GrLOD_t this_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrLOD_t large_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrAspectRatio_t aspect = enum_value(in, GR_ASPECT_8x1, GR_ASPECT_1x8);
      const GrTextureFormat_t format = enum_value(in, GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
      const FxU32 even_odd = small_or_any(in, 4);
      const long rows = in.ConsumeIntegralInRange<long>(0, 8);
      std::vector<FxU8> bitmap = rle_bitmap(in, rows);
      const long bm_h = in.ConsumeIntegralInRange(0, 15) == 0 ? in.ConsumeIntegralInRange<long>(-2, 300) : rows;
      const FxU32 u0 = small_or_any(in, 16), v0 = small_or_any(in, 8);
      const FxU32 width = small_or_any(in, 32), height = small_or_any(in, 8);
      const FxU32 dest_width = small_or_any(in, 257), dest_height = small_or_any(in, 9);
      std::vector<FxU16> tlut(256);
      for (std::size_t i = 0; i < tlut.size(); ++i) tlut[i] = static_cast<FxU16>(i * 0x0821u);
      // A bitmap height beyond its rows would make the shim read rows that do not exist (the
      // C API cannot tell), so only fewer rows than written are claimed.
      const long claimed = std::min(bm_h, rows);
      checked("ConvertAndDownloadRle", kMemory, [&] {
        ConvertAndDownloadRle(tmu, address, this_lod, large_lod, aspect, format, even_odd,
                              bitmap.data(), claimed, u0, v0, width, height, dest_width,
                              dest_height, tlut.data());
      });
      break;
    }
    case 17:
    case 18:
      gu_allocate(in);
      break;
    case 19:
      gu_change(in);
      break;
    case 20:
    case 21:
      gu_download(in);
      break;
    case 22: {
      const GrMipMapId_t id = mip_map_id(in);
      checked("guTexSource", kGuRecords, [&] { guTexSource(id); });
      break;
    }
    case 23: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const GrMipMapId_t id = mip_map_id(in);
      GrMipMapId_t current = 0;
      GrMipMapInfo *info = nullptr;
      FxU32 avail = 0;
      checked("guTexGetCurrentMipMap", [&] { current = guTexGetCurrentMipMap(tmu); });
      checked("guTexGetMipMapInfo", [&] { info = guTexGetMipMapInfo(id); });
      checked("guTexMemQueryAvail", [&] { avail = guTexMemQueryAvail(tmu); });
      if (ctx.display.open && !ctx.plain_gl && tmu == GR_TMU0) {
        if (avail + ctx.gu_textures.free_base != glide_shim::kTmuMemoryBytes)
          violated("guTexMemQueryAvail", "free memory and the free pointer do not add up");
        if (current != ctx.gu_textures.current) violated("guTexGetCurrentMipMap", "not the current id");
      }
      // An id of the table not allocated yet gives its empty record, as the driver's does.
      if (info != nullptr && id >= ctx.gu_textures.next_id && info->valid != FXFALSE)
        violated("guTexGetMipMapInfo", "a valid record for an id never allocated");
      break;
    }
    case 24:
      checked("guTexMemReset", kGuRecords, [] { guTexMemReset(); });
      break;
    case 25:
      lfb_layout(in);
      break;
    case 26: {
      // RLE16 of a small image: first the size (dst NULL), then into a buffer of that size.
      const FxU32 width = in.ConsumeIntegralInRange<FxU32>(0, 24);
      const FxU32 height = in.ConsumeIntegralInRange<FxU32>(0, 24);
      std::vector<FxU16> image(static_cast<std::size_t>(width) * height + 1);
      const FxU16 a = in.ConsumeIntegral<FxU16>(), b = in.ConsumeIntegral<FxU16>();
      for (std::size_t i = 0; i < image.size(); ++i) image[i] = in.ConsumeBool() ? a : b;
      int bytes = -1;
      checked("guEncodeRLE16", [&] { bytes = guEncodeRLE16(nullptr, image.data(), width, height); });
      if (bytes < 0 || static_cast<std::size_t>(bytes) > 4 * (image.size() - 1))
        violated("guEncodeRLE16", "more bytes than one run per pixel");
      std::vector<std::uint8_t> out(static_cast<std::size_t>(bytes) + 1);
      int again = -1;
      checked("guEncodeRLE16", [&] { again = guEncodeRLE16(out.data(), image.data(), width, height); });
      if (again != bytes) violated("guEncodeRLE16", "counting and encoding disagree");
      checked("guEncodeRLE16", [&] { guEncodeRLE16(nullptr, nullptr, width, height); });
      break;
    }
    case 27: {
      FxU16 *mipmap = nullptr;
      checked("guTexCreateColorMipMap", [&] { mipmap = guTexCreateColorMipMap(); });
      if (mipmap == nullptr) violated("guTexCreateColorMipMap", "no mip map");
      GrTexInfo info{GR_LOD_1, GR_LOD_256, GR_ASPECT_1x1, GR_TEXFMT_RGB_565, mipmap};
      if (in.ConsumeBool())
        checked("grTexDownloadMipMap", kMemory,
                [&] { grTexDownloadMipMap(GR_TMU0, 0, GR_MIPMAPLEVELMASK_BOTH, &info); });
      std::free(mipmap);
      break;
    }
    case 28: {
      GrFog_t table[GR_FOG_TABLE_SIZE];
      float w = 0.0f;
      checked("guFogTableIndexToW", [&] { w = guFogTableIndexToW(in.ConsumeIntegralInRange(-2, 66)); });
      (void)w;
      const float density = coordinate(in, 1.0f);
      switch (in.ConsumeIntegralInRange(0, 2)) {
        case 0: checked("guFogGenerateExp", [&] { guFogGenerateExp(table, density); }); break;
        case 1: checked("guFogGenerateExp2", [&] { guFogGenerateExp2(table, density); }); break;
        default: {
          const float near_z = coordinate(in, 1000.0f), far_z = coordinate(in, 1000.0f);
          checked("guFogGenerateLinear", [&] { guFogGenerateLinear(table, near_z, far_z); });
          break;
        }
      }
      if (glideShimGetLastError() == GLIDESHIM_OK) checked("grFogTable", [&] { grFogTable(table); });
      break;
    }
    case 29: {
      const FxU32 word = in.ConsumeIntegral<FxU32>();
      const FxU16 half = in.ConsumeIntegral<FxU16>();
      FxU32 swapped = 0;
      FxU16 swapped_half = 0;
      checked("guEndianSwapWords", [&] { swapped = guEndianSwapWords(word); });
      checked("guEndianSwapBytes", [&] { swapped_half = guEndianSwapBytes(half); });
      if (guEndianSwapWords(swapped) != word || guEndianSwapBytes(swapped_half) != half)
        violated("guEndianSwap*", "swapping twice is not the identity");
      break;
    }
    case 30:
    case 31:
      multipass(in, span);
      break;
    case 32: {
      std::vector<FxU16> pixels(16 * 16);
      const int x = in.ConsumeIntegral<int>(), y = in.ConsumeIntegral<int>();
      checked("guFbReadRegion", [&] { guFbReadRegion(x, y, 16, 16, pixels.data(), 32); });
      checked("guFbWriteRegion", [&] { guFbWriteRegion(x, y, 16, 16, pixels.data(), 32); });
      checked("guMovieSetName", [&] { guMovieSetName(in.ConsumeBool() ? nullptr : "movie"); });
      checked("guMovieStart", [] { guMovieStart(); });
      checked("guMovieStop", [] { guMovieStop(); });
      break;
    }
    case 33:
      three_df(in);
      break;
    case 34: {
      int key = -1;
      FxBool closed = FXTRUE;
      checked("glideShimPollKey", [&] { key = glideShimPollKey(); });
      checked("glideShimWindowClosed", [&] { closed = glideShimWindowClosed(); });
      if (key != 0 || closed != FXFALSE) violated("glideShimPollKey", "keys or a close request headless");
      const char *backend = nullptr;
      checked("glideShimBackendName", [&] { backend = glideShimBackendName(); });
      if (backend == nullptr) violated("glideShimBackendName", "NULL");
      static const char *const kNames[] = {"glClear", "glDrawArrays", "glNoSuchFunction", "", nullptr};
      const char *name = kNames[in.ConsumeIntegralInRange(0, 4)];
      checked("glideShimGetProcAddress", [&] { glideShimGetProcAddress(name); });
      // Values past the last kind give "unknown"; only 0..15 fit the C++ enum's range (a C
      // caller's -1 would be undefined on the C++ side, before any code of the shim runs).
      const char *error_name = glideShimErrorName(static_cast<GlideShimError>(in.ConsumeIntegralInRange(0, 15)));
      if (error_name == nullptr || *error_name == '\0') violated("glideShimErrorName", "no name");
      break;
    }
    case 35: {
      // A PNG of a colour buffer (rare: it loads OpenImageIO), to a file, a directory or NULL.
      if (in.ConsumeIntegralInRange(0, 7) != 0) break;
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      const int where = in.ConsumeIntegralInRange(0, 3);
      const std::string path = where == 0 ? g_scratch : g_scratch + "/frame.png";
      checked("glideShimWritePng", [&] { glideShimWritePng(buffer, where == 1 ? nullptr : path.c_str()); });
      break;
    }
    case 36: {
      FxU32 pixels = 0;
      checked("glideShimPixelsWritten", [&] { pixels = glideShimPixelsWritten(); });
      (void)pixels;
      // Counting makes every later flush of the renderer wait for an occlusion query, and no
      // call stops it: rare, and the next input gets a new GL context.
      if (in.ConsumeIntegralInRange(0, 15) == 0) {
        checked("glideShimResetPixelsWritten", [] { glideShimResetPixelsWritten(); });
        g_renderer_counts = true;
      }
      break;
    }
    case 37:
      // Save now, restore later in the same input (after other changes): the restored groups
      // must be the saved ones, which saving again shows byte for byte.
      if (!g_have_saved_state || in.ConsumeBool()) {
        checked("grGlideGetState", [&] { grGlideGetState(&g_saved_state); });
        g_have_saved_state = glideShimGetLastError() == GLIDESHIM_OK;
      } else {
        checked("grGlideSetState", [&] { grGlideSetState(&g_saved_state); });
        if (glideShimGetLastError() == GLIDESHIM_OK) {
          GrState again{};
          checked("grGlideGetState", [&] { grGlideGetState(&again); });
          if (glideShimGetLastError() == GLIDESHIM_OK &&
              std::memcmp(&again, &g_saved_state, sizeof again) != 0)
            violated("grGlideSetState", "the state saved after a restore differs from the one restored");
        }
      }
      break;
    case 38:
      close_and_reopen(in);
      break;
    case 39: {
      GrTexInfo info = texture_info(in);
      const FxU32 even_odd = small_or_any(in, 4);
      checked("grTexTextureMemRequired", [&] { grTexTextureMemRequired(even_odd, in.ConsumeIntegralInRange(0, 15) == 0 ? nullptr : &info); });
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      checked("grTexMinAddress", [&] { grTexMinAddress(tmu); });
      checked("grTexMaxAddress", [&] { grTexMaxAddress(tmu); });
      break;
    }
    case 40:
    case 41:
      textured_draw(in, span);
      break;
    default: {
      const int width = in.ConsumeIntegralInRange(-2, glide_shim::kMaxScreenSide + 2);
      const int height = in.ConsumeIntegralInRange(-2, glide_shim::kMaxScreenSide + 2);
      checked("glideShimSetWindowSize", [&] { glideShimSetWindowSize(width, height); });
      break;
    }
  }
}

}  // namespace glide_api_fuzz
