// The first half of the call menu: state setters, texture sources and downloads, draws, clears
// and swaps, LFB locks and regions, render-to-texture and the plain-GL brackets. Its case numbers
// decide which call an input's byte makes, so the seed corpus relies on them.
#include "glide_api/arguments.h"
#include "glide_api/calls.h"
#include "glide_api/checks.h"

#include <glide_shim.h>
#include <glideutl.h>

#include <algorithm>
#include <cstring>
#include <vector>

namespace glide_api_fuzz {

void one_call(FuzzedDataProvider &in, float span) {
  switch (in.ConsumeIntegralInRange(0, 99)) {
    case 0: {
      const int f = enum_value(in, 0, 0x10), k = enum_value(in, 0, 0xd);
      const int l = enum_value(in, 0, 2), o = enum_value(in, 0, 2);
      const FxBool invert = boolean(in);
      checked("grColorCombine", [&] { grColorCombine(f, k, l, o, invert); });
      break;
    }
    case 1: {
      const int f = enum_value(in, 0, 0x10), k = enum_value(in, 0, 0xd);
      const int l = enum_value(in, 0, 2), o = enum_value(in, 0, 2);
      const FxBool invert = boolean(in);
      checked("grAlphaCombine", [&] { grAlphaCombine(f, k, l, o, invert); });
      break;
    }
    case 2: {
      const int a = enum_value(in, 0, 0xf), b = enum_value(in, 0, 0xf);
      const int c = enum_value(in, 0, 0xf), d = enum_value(in, 0, 0xf);
      checked("grAlphaBlendFunction", [&] { grAlphaBlendFunction(a, b, c, d); });
      break;
    }
    case 3: {
      const int function = enum_value(in, GR_CMP_NEVER, GR_CMP_ALWAYS);
      checked("grAlphaTestFunction", [&] { grAlphaTestFunction(function); });
      const GrAlpha_t reference = in.ConsumeIntegral<GrAlpha_t>();
      checked("grAlphaTestReferenceValue", [&] { grAlphaTestReferenceValue(reference); });
      break;
    }
    case 4: {
      const int mode = enum_value(in, GR_CHROMAKEY_DISABLE, GR_CHROMAKEY_ENABLE);
      checked("grChromakeyMode", [&] { grChromakeyMode(mode); });
      const GrColor_t value = in.ConsumeIntegral<GrColor_t>();
      checked("grChromakeyValue", [&] { grChromakeyValue(value); });
      break;
    }
    case 5: {
      const auto side = static_cast<FxU32>(span);
      const FxU32 a = small_or_any(in, side + 2), b = small_or_any(in, side + 2);
      const FxU32 c = small_or_any(in, side + 2), d = small_or_any(in, side + 2);
      checked("grClipWindow", [&] { grClipWindow(a, b, c, d); });
      break;
    }
    case 6: {
      const FxBool rgb = boolean(in), alpha = boolean(in);
      checked("grColorMask", [&] { grColorMask(rgb, alpha); });
      break;
    }
    case 7: {
      const GrColor_t value = in.ConsumeIntegral<GrColor_t>();
      checked("grConstantColorValue", [&] { grConstantColorValue(value); });
      break;
    }
    case 8: {
      const int mode = enum_value(in, GR_CULL_DISABLE, GR_CULL_POSITIVE);
      checked("grCullMode", [&] { grCullMode(mode); });
      break;
    }
    case 9: {
      const auto level = in.ConsumeIntegral<FxI16>();
      checked("grDepthBiasLevel", [&] { grDepthBiasLevel(level); });
      break;
    }
    case 10: {
      const int function = enum_value(in, GR_CMP_NEVER, GR_CMP_ALWAYS);
      checked("grDepthBufferFunction", [&] { grDepthBufferFunction(function); });
      break;
    }
    case 11: {
      const int mode = enum_value(in, GR_DEPTHBUFFER_DISABLE, GR_DEPTHBUFFER_WBUFFER_COMPARE_TO_BIAS);
      checked("grDepthBufferMode", [&] { grDepthBufferMode(mode); });
      break;
    }
    case 12: {
      const FxBool mask = boolean(in);
      checked("grDepthMask", [&] { grDepthMask(mask); });
      break;
    }
    case 13: {
      const int mode = enum_value(in, GR_DITHER_DISABLE, GR_DITHER_4x4);
      checked("grDitherMode", [&] { grDitherMode(mode); });
      break;
    }
    case 14: {
      const float gamma = coordinate(in, 3.0f);
      checked("grGammaCorrectionValue", [&] { grGammaCorrectionValue(gamma); });
      break;
    }
    case 15: {
      const int type = enum_value(in, GR_HINT_STWHINT, GR_HINT_ALLOW_MIPMAP_DITHER);
      const FxU32 mask = small_or_any(in, 0x7f);
      checked("grHints", [&] { grHints(type, mask); });
      break;
    }
    case 16: {
      const int origin = enum_value(in, GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT);
      checked("grSstOrigin", [&] { grSstOrigin(origin); });
      break;
    }
    case 17: {
      const int buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_TRIPLEBUFFER);
      checked("grRenderBuffer", [&] { grRenderBuffer(buffer); });
      break;
    }
    case 18: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int s = enum_value(in, 0, 1), t = enum_value(in, 0, 1);
      checked("grTexClampMode", [&] { grTexClampMode(tmu, s, t); });
      break;
    }
    case 19: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int min = enum_value(in, 0, 1), mag = enum_value(in, 0, 1);
      checked("grTexFilterMode", [&] { grTexFilterMode(tmu, min, mag); });
      break;
    }
    case 20: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int mode = enum_value(in, GR_MIPMAP_DISABLE, GR_MIPMAP_NEAREST_DITHER);
      const FxBool blend = boolean(in);
      checked("grTexMipMapMode", [&] { grTexMipMapMode(tmu, mode, blend); });
      break;
    }
    case 21: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const float bias = coordinate(in, 8.0f);
      checked("grTexLodBiasValue", [&] { grTexLodBiasValue(tmu, bias); });
      break;
    }
    case 22: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int rf = enum_value(in, 0, 0x10), rk = enum_value(in, 0, 0xd);
      const int af = enum_value(in, 0, 0x10), ak = enum_value(in, 0, 0xd);
      const FxBool ri = boolean(in), ai = boolean(in);
      checked("grTexCombine", [&] { grTexCombine(tmu, rf, rk, af, ak, ri, ai); });
      break;
    }
    case 23: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int function = enum_value(in, GR_TEXTURECOMBINE_ZERO, GR_TEXTURECOMBINE_ONE);
      checked("guTexCombineFunction", [&] { guTexCombineFunction(tmu, function); });
      break;
    }
    case 24: {
      const int function = enum_value(in, GR_COLORCOMBINE_ZERO, GR_COLORCOMBINE_ONE);
      checked("guColorCombineFunction", [&] { guColorCombineFunction(function); });
      break;
    }
    case 25: {
      const int source = enum_value(in, GR_ALPHASOURCE_CC_ALPHA,
                                    GR_ALPHASOURCE_TEXTURE_ALPHA_TIMES_ITERATED_ALPHA);
      checked("guAlphaSource", [&] { guAlphaSource(source); });
      break;
    }
    case 26: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8) & ~7u;
      const FxU32 even_odd = small_or_any(in, 4);
      GrTexInfo info = texture_info(in);
      const bool null_info = in.ConsumeIntegralInRange(0, 15) == 0;
      checked("grTexSource",
              [&] { grTexSource(tmu, address, even_odd, null_info ? nullptr : &info); });
      break;
    }
    case 27: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8);
      const FxU32 even_odd = small_or_any(in, 4);
      GrTexInfo info = texture_info(in);
      std::vector<std::uint8_t> data =
          texel_data(in, host_chain_bytes(info.smallLod, info.largeLod, info.aspectRatio, info.format));
      info.data = in.ConsumeIntegralInRange(0, 15) == 0 ? nullptr : data.data();
      checked("grTexDownloadMipMap", kMemory, [&] { grTexDownloadMipMap(tmu, address, even_odd, &info); });
      break;
    }
    case 28: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8);
      const GrLOD_t this_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrLOD_t large_lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      const GrAspectRatio_t aspect = enum_value(in, GR_ASPECT_8x1, GR_ASPECT_1x8);
      const GrTextureFormat_t format = enum_value(in, GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
      const FxU32 even_odd = small_or_any(in, 4);
      std::vector<std::uint8_t> data =
          texel_data(in, host_chain_bytes(this_lod, this_lod, aspect, format));
      checked("grTexDownloadMipMapLevel", kMemory, [&] {
        grTexDownloadMipMapLevel(tmu, address, this_lod, large_lod, aspect, format, even_odd,
                                 data.data());
      });
      break;
    }
    case 29: {
      const GrVertex v = vertex(in, span);
      checked("grDrawPoint", [&] { grDrawPoint(&v); });
      break;
    }
    case 30: {
      const GrVertex a = vertex(in, span), b = vertex(in, span);
      checked("grDrawLine", [&] { grDrawLine(&a, &b); });
      break;
    }
    case 31:
    case 32: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      checked("grDrawTriangle", [&] { grDrawTriangle(&a, &b, &c); });
      break;
    }
    case 33: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      checked("guDrawTriangleWithClip", [&] { guDrawTriangleWithClip(&a, &b, &c); });
      break;
    }
    case 34: {
      const GrColor_t color = in.ConsumeIntegral<GrColor_t>();
      const GrAlpha_t alpha = in.ConsumeIntegral<GrAlpha_t>();
      const FxU16 depth = in.ConsumeIntegral<FxU16>();
      checked("grBufferClear", [&] { grBufferClear(color, alpha, depth); });
      break;
    }
    case 35: {
      const int interval = enum_value(in, 0, 2);
      checked("grBufferSwap", [&] { grBufferSwap(interval); });
      break;
    }
    case 36: {
      const GrLock_t type = enum_value(in, GR_LFB_READ_ONLY, GR_LFB_WRITE_ONLY) |
                            (in.ConsumeBool() ? GR_LFB_NOIDLE : 0);
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      // Every write mode (reserved ones and junk now and then), through the pixel pipeline
      // or not.
      static constexpr GrLfbWriteMode_t kModes[] = {
          GR_LFBWRITEMODE_565,       GR_LFBWRITEMODE_555,       GR_LFBWRITEMODE_1555,
          GR_LFBWRITEMODE_888,       GR_LFBWRITEMODE_8888,      GR_LFBWRITEMODE_565_DEPTH,
          GR_LFBWRITEMODE_555_DEPTH, GR_LFBWRITEMODE_1555_DEPTH, GR_LFBWRITEMODE_ZA16,
          GR_LFBWRITEMODE_ANY};
      const GrLfbWriteMode_t mode = in.ConsumeIntegralInRange(0, 7) == 0
                                        ? enum_value(in, 0, 0xff)
                                        : kModes[in.ConsumeIntegralInRange<std::size_t>(0, 9)];
      const GrOriginLocation_t origin = enum_value(in, GR_ORIGIN_UPPER_LEFT, GR_ORIGIN_LOWER_LEFT);
      const FxBool pipeline = in.ConsumeBool() ? FXTRUE : (in.ConsumeIntegralInRange(0, 7) == 0 ? 2 : FXFALSE);
      GrLfbInfo_t info{};
      info.size = in.ConsumeIntegralInRange(0, 15) == 0 ? 0 : static_cast<int>(sizeof info);
      FxBool locked = FXFALSE;
      checked("grLfbLock", [&] { locked = grLfbLock(type, buffer, mode, origin, pipeline, &info); });
      if (locked && (type & GR_LFB_WRITE_ONLY) != 0) {
        // Write as the program would: anywhere inside stride x height, through the pointer.
        const GlideContext &ctx = glide_shim::current();
        auto *words = static_cast<FxU16 *>(info.lfbPtr);
        const std::size_t stride = info.strideInBytes / 2;
        const std::size_t count = stride * static_cast<std::size_t>(ctx.display.height);
        const int writes = in.ConsumeIntegralInRange(0, 64);
        for (int i = 0; i < writes && count > 0; ++i)
          words[in.ConsumeIntegralInRange<std::size_t>(0, count - 1)] = in.ConsumeIntegral<FxU16>();
      } else if (locked) {
        const GlideContext &ctx = glide_shim::current();
        const auto *words = static_cast<const FxU16 *>(info.lfbPtr);
        const std::size_t count =
            info.strideInBytes / 2 * static_cast<std::size_t>(ctx.display.height);
        unsigned sum = 0;
        for (std::size_t i = 0; i < count; ++i) sum += words[i];  // every word must be readable
        (void)sum;
      }
      break;
    }
    case 37: {
      const GrLock_t type = enum_value(in, GR_LFB_READ_ONLY, GR_LFB_WRITE_ONLY);
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      checked("grLfbUnlock", [&] { grLfbUnlock(type, buffer); });
      break;
    }
    case 38: {
      // Any region, with a buffer of exactly stride x height: a correct shim refuses what does
      // not fit the screen before it writes a byte.
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      const auto side = static_cast<FxU32>(span);
      const FxU32 x = small_or_any(in, side), y = small_or_any(in, side);
      const FxU32 w = small_or_any(in, side + 1), h = small_or_any(in, side + 1);
      const FxU32 stride = in.ConsumeIntegralInRange<FxU32>(0, 2 * side + 8);
      std::vector<std::uint8_t> data(std::min<std::size_t>(
          static_cast<std::size_t>(stride) * std::min<FxU32>(h, 2 * side + 8), 1u << 20) + 1);
      checked("grLfbReadRegion", [&] { grLfbReadRegion(buffer, x, y, w, h, stride, data.data()); });
      break;
    }
    case 39: {
      const GrBuffer_t buffer = enum_value(in, GR_BUFFER_FRONTBUFFER, GR_BUFFER_AUXBUFFER);
      const GrLfbSrcFmt_t format = enum_value(in, GR_LFB_SRC_FMT_565, GR_LFB_SRC_FMT_ZA16);
      const auto side = static_cast<FxU32>(span);
      const FxU32 x = small_or_any(in, side), y = small_or_any(in, side);
      const FxU32 w = small_or_any(in, side + 1), h = small_or_any(in, side + 1);
      const FxI32 stride = in.ConsumeIntegralInRange<FxI32>(-4, static_cast<FxI32>(4 * side + 8));
      std::vector<std::uint8_t> data(std::min<std::size_t>(
          static_cast<std::size_t>(std::max<FxI32>(stride, 0)) * std::min<FxU32>(h, 2 * side + 8),
          1u << 20) + 1);
      checked("grLfbWriteRegion",
              [&] { grLfbWriteRegion(buffer, x, y, format, w, h, stride, data.data()); });
      break;
    }
    case 40:
      lfb_round_trip(in);
      break;
    case 41:
      texture_memory_round_trip(in);
      break;
    case 42: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const FxU32 address = small_or_any(in, glide_shim::kTmuMemoryBytes + 8);
      const GrLOD_t lod = enum_value(in, GR_LOD_256, GR_LOD_1);
      checked("glideShimRenderToTexture", kMemory, [&] { glideShimRenderToTexture(tmu, address, lod); });
      break;
    }
    case 43:
      checked("glideShimRenderToFrameBuffer", kMemory, [] { glideShimRenderToFrameBuffer(); });
      break;
    case 44:
      checked("glideShimBeginGL", [] { glideShimBeginGL(); });
      break;
    case 45:
      checked("glideShimEndGL", [] { glideShimEndGL(); });
      break;
    case 46:
      checked("grSstIdle", [] { grSstIdle(); });
      break;
    case 47:
    case 48:
      polygon(in, span);
      break;
    case 49: {
      const GrVertex a = vertex(in, span), b = vertex(in, span), c = vertex(in, span);
      const FxBool ab = boolean(in), bc = boolean(in), ca = boolean(in);
      checked("grAADrawTriangle", [&] { grAADrawTriangle(&a, &b, &c, ab, bc, ca); });
      break;
    }
    case 50: {
      const int mode = in.ConsumeBool() ? enum_value(in, GR_FOG_DISABLE, GR_FOG_WITH_ITERATED_Z)
                                        : in.ConsumeIntegral<int>();
      checked("grFogMode", [&] { grFogMode(mode); });
      const GrColor_t color = in.ConsumeIntegral<GrColor_t>();
      checked("grFogColorValue", [&] { grFogColorValue(color); });
      break;
    }
    case 51: {
      std::vector<GrFog_t> table = in.ConsumeBytes<GrFog_t>(GR_FOG_TABLE_SIZE);
      table.resize(GR_FOG_TABLE_SIZE);
      checked("grFogTable", [&] { grFogTable(table.data()); });
      break;
    }
    case 52: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const GrTexTable_t type = enum_value(in, GR_TEXTABLE_NCC0, GR_TEXTABLE_PALETTE);
      GuTexTable table{};  // the larger of a palette and an NCC table
      const std::vector<std::uint8_t> bytes = in.ConsumeBytes<std::uint8_t>(sizeof table);
      if (!bytes.empty()) std::memcpy(&table, bytes.data(), bytes.size());
      checked("grTexDownloadTable", [&] { grTexDownloadTable(tmu, type, &table); });
      const GrNCCTable_t ncc = enum_value(in, GR_NCCTABLE_NCC0, GR_NCCTABLE_NCC1);
      checked("grTexNCCTable", [&] { grTexNCCTable(tmu, ncc); });
      break;
    }
    case 53: {
      const GrAlpha_t alpha = in.ConsumeIntegral<GrAlpha_t>();
      checked("grLfbConstantAlpha", [&] { grLfbConstantAlpha(alpha); });
      const FxU16 depth = in.ConsumeIntegral<FxU16>();
      checked("grLfbConstantDepth", [&] { grLfbConstantDepth(depth); });
      break;
    }
    case 54:
      state_round_trip();
      break;
    case 55: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int bias = enum_value(in, -32, 31);
      const FxU8 scale = in.ConsumeIntegral<FxU8>();
      const float max = coordinate(in, 1.0f);
      checked("grTexDetailControl", [&] { grTexDetailControl(tmu, bias, scale, max); });
      break;
    }
    case 56: {
      const FxBool enable = boolean(in);
      checked("grAlphaControlsITRGBLighting", [&] { grAlphaControlsITRGBLighting(enable); });
      break;
    }
    case 57: {
      const float a = coordinate(in, 255.0f), r = coordinate(in, 255.0f),
                  g = coordinate(in, 255.0f), b = coordinate(in, 255.0f);
      checked("grConstantColorValue4", [&] { grConstantColorValue4(a, r, g, b); });
      break;
    }
    case 58: {
      const GrChipID_t tmu = enum_value(in, GR_TMU0, GR_TMU0);
      const int function = enum_value(in, GR_TEXTURECOMBINE_ZERO, GR_TEXTURECOMBINE_ONE);
      checked("grTexCombineFunction", [&] { grTexCombineFunction(tmu, function); });
      break;
    }
    default:
      more_calls(in, span);
      break;
  }
}

}  // namespace glide_api_fuzz
