// Calls checked beyond the general rules: what is written reads back (LFB regions, the saved
// state), sizes agree (texture memory), and absurd polygon vertex counts are refused unread.
#include "glide_api/arguments.h"
#include "glide_api/calls.h"
#include "glide_api/checks.h"

#include <glideutl.h>

#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace glide_api_fuzz {

void lfb_round_trip(FuzzedDataProvider &in) {
  const GlideContext &ctx = glide_shim::current();
  if (!ctx.display.open || ctx.plain_gl || ctx.lfb.write_locked || ctx.texture_target.active) return;
  // Byte swizzle and word swap (grLfbWriteColorSwizzle) move written 565 words on purpose, and
  // ABGR or BGRA lanes (grLfbWriteColorFormat) read their red and blue fields swapped.
  const glide_shim::LfbWriteLayout &layout = ctx.lfb.layout;
  if (layout.swizzle_bytes || layout.swap_words || layout.color_format == GR_COLORFORMAT_ABGR ||
      layout.color_format == GR_COLORFORMAT_BGRA)
    return;
  const auto width = static_cast<FxU32>(ctx.display.width);
  const auto height = static_cast<FxU32>(ctx.display.height);
  const FxU32 x = in.ConsumeIntegralInRange<FxU32>(0, width - 1);
  const FxU32 y = in.ConsumeIntegralInRange<FxU32>(0, height - 1);
  const FxU32 w = in.ConsumeIntegralInRange<FxU32>(1, width - x);
  const FxU32 h = in.ConsumeIntegralInRange<FxU32>(1, height - y);
  const GrBuffer_t buffer = in.ConsumeBool() ? GR_BUFFER_BACKBUFFER : GR_BUFFER_FRONTBUFFER;
  std::vector<FxU16> written(static_cast<std::size_t>(w) * h), read(written.size());
  const FxU16 seed = in.ConsumeIntegral<FxU16>();
  for (std::size_t i = 0; i < written.size(); ++i)
    written[i] = static_cast<FxU16>(seed * 31u + i * 2654435761u);
  bool ok = false;
  checked("grLfbWriteRegion", [&] {
    ok = grLfbWriteRegion(buffer, x, y, GR_LFB_SRC_FMT_565, w, h, static_cast<FxI32>(w * 2),
                          written.data()) != FXFALSE;
  });
  if (!ok) violated("grLfbWriteRegion", "a region inside the screen was refused");
  checked("grLfbReadRegion", [&] {
    ok = grLfbReadRegion(buffer, x, y, w, h, w * 2, read.data()) != FXFALSE;
  });
  if (!ok) violated("grLfbReadRegion", "a region inside the screen was refused");
  if (read != written) violated("grLfbReadRegion", "565 words written did not read back unchanged");
}

void texture_memory_round_trip(FuzzedDataProvider &in) {
  GrTexInfo info = texture_info(in);
  const std::size_t host = host_chain_bytes(info.smallLod, info.largeLod, info.aspectRatio,
                                            info.format);
  FxU32 calculated = 0, required = 0;
  checked("grTexCalcMemRequired", [&] {
    calculated = grTexCalcMemRequired(info.smallLod, info.largeLod, info.aspectRatio, info.format);
  });
  checked("grTexTextureMemRequired", [&] {
    required = grTexTextureMemRequired(GR_MIPMAPLEVELMASK_BOTH, &info);
  });
  if (host > 0 && (calculated != required || calculated < host || calculated > 2 * host + 64)) {
    std::fprintf(stderr, "lods %d..%d aspect %d format %d: calc %u, required %u, host %zu\n",
                 static_cast<int>(info.largeLod), static_cast<int>(info.smallLod),
                 static_cast<int>(info.aspectRatio), static_cast<int>(info.format), calculated,
                 required, host);
    violated("grTexTextureMemRequired", "disagrees with grTexCalcMemRequired or the chain's size");
  }
}

// grGlideGetState then grGlideSetState of what it returned changes nothing, and a second
// grGlideGetState returns the same bytes.
void state_round_trip() {
  GlideContext &ctx = glide_shim::current();
  if (!ctx.display.open || ctx.plain_gl) return;
  GrState first{}, second{};
  checked("grGlideGetState", [&] { grGlideGetState(&first); });
  Snapshot before;
  before.take(ctx, kSmall);
  checked("grGlideSetState", [&] { grGlideSetState(&first); });
  if (const char *group = before.differs(ctx))
    violated("grGlideSetState", (std::string("restoring the saved state changed ") + group).c_str());
  checked("grGlideGetState", [&] { grGlideGetState(&second); });
  if (std::memcmp(&first, &second, sizeof first) != 0)
    violated("grGlideGetState", "the state saved again differs from the state restored");
}

// A polygon of `count` vertices from an array of exactly that many (indices inside it, or -1
// that the shim must refuse), or a count far beyond the array that the shim must refuse unread.
void polygon(FuzzedDataProvider &in, float span) {
  const bool absurd = in.ConsumeIntegralInRange(0, 15) == 0;
  const int count = in.ConsumeIntegralInRange(0, 8);
  std::vector<GrVertex> vertices;
  for (int i = 0; i < count; ++i) vertices.push_back(vertex(in, span));
  std::vector<int> indices;
  for (int i = 0; i < count; ++i) indices.push_back(in.ConsumeIntegralInRange(-1, count - 1));
  const int nverts = absurd ? in.ConsumeIntegralInRange(65537, std::numeric_limits<int>::max()) : count;
  const GrVertex *list = vertices.empty() ? nullptr : vertices.data();
  const int *ilist = indices.empty() ? nullptr : indices.data();
  switch (in.ConsumeIntegralInRange(0, 6)) {
    case 0: checked("grDrawPolygonVertexList", [&] { grDrawPolygonVertexList(nverts, list); }); break;
    case 1: checked("grDrawPolygon", [&] { grDrawPolygon(nverts, ilist, list); }); break;
    case 2: checked("grDrawPlanarPolygonVertexList", [&] { grDrawPlanarPolygonVertexList(nverts, list); }); break;
    case 3: checked("grDrawPlanarPolygon", [&] { grDrawPlanarPolygon(nverts, ilist, list); }); break;
    case 4: checked("grAADrawPolygonVertexList", [&] { grAADrawPolygonVertexList(nverts, list); }); break;
    case 5: checked("grAADrawPolygon", [&] { grAADrawPolygon(nverts, ilist, list); }); break;
    default:
      checked("guDrawPolygonVertexListWithClip", [&] { guDrawPolygonVertexListWithClip(nverts, list); });
      break;
  }
  const GlideShimError error = glideShimGetLastError();
  if (absurd && glide_shim::current().display.open && !glide_shim::current().plain_gl &&
      error != GLIDESHIM_ERR_OUT_OF_RANGE && error != GLIDESHIM_ERR_NULL_POINTER)
    violated("a polygon call", "an absurd vertex count was not refused");
}

}  // namespace glide_api_fuzz
