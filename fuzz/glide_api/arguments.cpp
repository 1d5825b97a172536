// Argument decoding (arguments.h).
#include "glide_api/arguments.h"

#include <algorithm>
#include <limits>

namespace glide_api_fuzz {

// Mostly values near a valid range [lo, hi] (one past each end included), sometimes any int.
int enum_value(FuzzedDataProvider &in, int lo, int hi) {
  if (in.ConsumeIntegralInRange(0, 15) == 0) return in.ConsumeIntegral<int>();
  return in.ConsumeIntegralInRange(lo - 1, hi + 1);
}

FxU32 small_or_any(FuzzedDataProvider &in, FxU32 hi) {
  if (in.ConsumeIntegralInRange(0, 7) == 0) return in.ConsumeIntegral<FxU32>();
  return in.ConsumeIntegralInRange<FxU32>(0, hi);
}

FxBool boolean(FuzzedDataProvider &in) {
  // FxBool is an int: Glide programs pass 0 and 1, a careless one anything.
  return in.ConsumeIntegralInRange(0, 7) == 0 ? in.ConsumeIntegral<FxBool>() : in.ConsumeBool();
}

// A float for a vertex field: on-screen values most of the time, then the edges of float.
float coordinate(FuzzedDataProvider &in, float span) {
  switch (in.ConsumeIntegralInRange(0, 11)) {
    case 0: return std::numeric_limits<float>::quiet_NaN();
    case 1: return std::numeric_limits<float>::infinity();
    case 2: return -std::numeric_limits<float>::infinity();
    case 3: return std::numeric_limits<float>::max();
    case 4: return std::numeric_limits<float>::denorm_min();
    case 5: return 786432.0f + in.ConsumeFloatingPointInRange(-8.0f, 8.0f);  // the 3<<18 snap
    case 6: return in.ConsumeFloatingPoint<float>();
    default: return in.ConsumeFloatingPointInRange(-0.5f * span, 1.5f * span);
  }
}

GrVertex vertex(FuzzedDataProvider &in, float span) {
  GrVertex v{};
  v.x = coordinate(in, span);
  v.y = coordinate(in, span);
  v.r = coordinate(in, 255.0f), v.g = coordinate(in, 255.0f), v.b = coordinate(in, 255.0f);
  v.a = coordinate(in, 255.0f);
  v.ooz = coordinate(in, 65535.0f);
  v.oow = coordinate(in, 1.0f);
  for (GrTmuVertex &t : v.tmuvtx) {
    t.sow = coordinate(in, 256.0f), t.tow = coordinate(in, 256.0f), t.oow = coordinate(in, 1.0f);
  }
  return v;
}

// Host bytes of a mip-map chain large_lod..small_lod as GrTexInfo.data holds it (every level at
// its plain texel count), computed here from the Glide 2.x tables, independently of the shim;
// 0 when the arguments are not a valid texture.
std::size_t host_chain_bytes(GrLOD_t small_lod, GrLOD_t large_lod, GrAspectRatio_t aspect,
                             GrTextureFormat_t format) {
  if (large_lod < GR_LOD_256 || small_lod > GR_LOD_1 || large_lod > small_lod) return 0;
  if (aspect < GR_ASPECT_8x1 || aspect > GR_ASPECT_1x8) return 0;
  if (format < GR_TEXFMT_8BIT || format > GR_TEXFMT_RSVD2) return 0;
  // The reserved codes name no format: the shim refuses them and sizes them as 0.
  if (format == GR_TEXFMT_RSVD0 || format == GR_TEXFMT_RSVD1 || format == GR_TEXFMT_RSVD2) return 0;
  const int texel_bytes = format >= GR_TEXFMT_16BIT ? 2 : 1;
  const int wide = GR_ASPECT_1x1 - aspect;  // log2(width / height)
  std::size_t bytes = 0;
  for (GrLOD_t lod = large_lod; lod <= small_lod; ++lod) {
    const int side = 256 >> lod;
    const int width = wide >= 0 ? side : std::max(side >> -wide, 1);
    const int height = wide <= 0 ? side : std::max(side >> wide, 1);
    bytes += static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
             static_cast<std::size_t>(texel_bytes);
  }
  return bytes;
}

// A data buffer for a download: exactly the chain's size when the arguments are valid (ASan
// catches any read past it), else a few bytes that a correct shim never reads.
std::vector<std::uint8_t> texel_data(FuzzedDataProvider &in, std::size_t bytes) {
  std::vector<std::uint8_t> data(bytes > 0 ? bytes : 8);
  const std::vector<std::uint8_t> pattern = in.ConsumeBytes<std::uint8_t>(16);
  for (std::size_t i = 0; i < data.size(); ++i)
    data[i] = pattern.empty() ? static_cast<std::uint8_t>(i) : pattern[i % pattern.size()];
  return data;
}

GrTexInfo texture_info(FuzzedDataProvider &in) {
  GrTexInfo info{};
  info.largeLod = enum_value(in, GR_LOD_256, GR_LOD_1);
  info.smallLod = enum_value(in, GR_LOD_256, GR_LOD_1);
  info.aspectRatio = enum_value(in, GR_ASPECT_8x1, GR_ASPECT_1x8);
  info.format = enum_value(in, GR_TEXFMT_8BIT, GR_TEXFMT_RSVD2);
  return info;
}

}  // namespace glide_api_fuzz
