// Chapter "depth buffer": mode, compare function, write mask and bias, and the depth codes.
#include "depth.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace glide_shim {

bool is_w_buffer(GrDepthBufferMode_t mode) {
  return mode == GR_DEPTHBUFFER_WBUFFER || mode == GR_DEPTHBUFFER_WBUFFER_COMPARE_TO_BIAS;
}

bool is_z_buffer(GrDepthBufferMode_t mode) {
  return mode == GR_DEPTHBUFFER_ZBUFFER || mode == GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS;
}

bool compares_to_bias(GrDepthBufferMode_t mode) {
  return mode == GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS ||
         mode == GR_DEPTHBUFFER_WBUFFER_COMPARE_TO_BIAS;
}

FxU16 w_code(double oow) {
  // 1/w >= 1 saturates to the nearest code; so does a negative 1/w (w behind the eye), whose
  // integer bits are set in the hardware's iterator.
  if (!(oow < 1.0) || oow < 0.0) return 0;
  const auto fixed = static_cast<std::uint64_t>(std::max(0.0, oow) * 4294967296.0);  // .32
  const auto top = static_cast<unsigned>(fixed >> 16);
  if (top == 0) return 0xFFFF;
  int zeros = 0;
  while ((top & (0x8000u >> zeros)) == 0) ++zeros;
  const auto mantissa = static_cast<unsigned>((fixed >> (31 - zeros - 12)) & 0xFFF);
  const unsigned code = (static_cast<unsigned>(zeros) << 12) + (~mantissa & 0xFFF) + 1;
  return static_cast<FxU16>(std::min(code, 0xFFFFu));
}

double oow_from_w_code(FxU16 code) {
  if (code == 0) return 1.0;
  if (code == 0xFFFF) return 0.0;
  const unsigned exponent = (code - 1u) >> 12;
  const unsigned mantissa = ~(code - 1u) & 0xFFF;
  return static_cast<double>(0x1000 | mantissa) / std::ldexp(1.0, 13 + static_cast<int>(exponent));
}

float vertex_depth(const DepthState &depth, float ooz, float oow) {
  if (depth.mode == GR_DEPTHBUFFER_DISABLE) return 0.0f;
  // gglide.c sets the depth-bias enable (fbzMode bit 16) only in the plain Z and W modes.
  const float bias = compares_to_bias(depth.mode) ? 0.0f : static_cast<float>(depth.bias_level);
  if (is_w_buffer(depth.mode)) {
    // A bias of b codes moves w by 2^(b/4096), i.e. scales 1/w by 2^(-b/4096): still affine.
    // Without a bias the scale is exactly 1 (most draws): no exp2f per vertex.
    const float unbiased = std::min(oow, 1.0f);
    return std::clamp(bias == 0.0f ? unbiased : unbiased * std::exp2(-bias / 4096.0f), 0.0f, 1.0f);
  }
  return std::clamp((ooz + bias) / 65535.0f, 0.0f, 1.0f);
}

double gl_depth_from_code(FxU16 code, bool w_buffer) {
  return w_buffer ? oow_from_w_code(code) : static_cast<double>(code) / 65535.0;
}

FxU16 code_from_gl_depth(float depth, bool w_buffer) {
  if (w_buffer) return w_code(depth);
  return static_cast<FxU16>(std::lround(std::clamp(depth, 0.0f, 1.0f) * 65535.0f));
}

int bias_compare_intervals(const DepthState &depth, DepthInterval intervals[2]) {
  // The 24-bit buffer's levels k / kTop, as glReadPixels returns them, and their codes: the Z
  // code rises with k, the W code falls (1/w falls as w, and the code, rise).
  constexpr std::int64_t kTop = (1 << 24) - 1;
  const bool w_buffer = is_w_buffer(depth.mode);
  auto code = [w_buffer](std::int64_t k) {
    return static_cast<int>(code_from_gl_depth(
        static_cast<float>(static_cast<double>(k) / static_cast<double>(kTop)), w_buffer));
  };
  auto first = [](std::int64_t low, std::int64_t high, const auto &holds) {  // first k holding
    while (low < high) {
      const std::int64_t middle = low + (high - low) / 2;
      if (holds(middle)) high = middle; else low = middle + 1;
    }
    return low;
  };
  const int source = static_cast<std::uint16_t>(depth.bias_level);  // zaColor[15:0]
  // The levels whose code is `source`: [equal_low, equal_high] (empty when low > high); below
  // and above them the codes are on one side each, which side depending on the mode.
  std::int64_t equal_low = 0, equal_high = 0;
  bool less_is_below = false;  // whether source < code holds on the levels below equal_low
  if (w_buffer) {
    equal_low = first(0, kTop + 1, [&](std::int64_t k) { return code(k) <= source; });
    equal_high = first(0, kTop + 1, [&](std::int64_t k) { return code(k) < source; }) - 1;
    less_is_below = true;
  } else {
    equal_low = first(0, kTop + 1, [&](std::int64_t k) { return code(k) >= source; });
    equal_high = first(0, kTop + 1, [&](std::int64_t k) { return code(k) > source; }) - 1;
  }
  // Levels below equal_low and above equal_high, and the equal ones.
  const std::int64_t below_high = equal_low - 1, above_low = equal_high + 1;
  struct Levels {
    std::int64_t low, high;
  };
  Levels sides[2];
  int count = 0;
  auto add = [&](std::int64_t low, std::int64_t high) {
    low = std::max<std::int64_t>(low, 0), high = std::min(high, kTop);
    if (low <= high) sides[count++] = {low, high};
  };
  switch (depth.function) {
    case GR_CMP_NEVER: break;
    case GR_CMP_LESS:  // source < code
      if (less_is_below) add(0, below_high); else add(above_low, kTop);
      break;
    case GR_CMP_LEQUAL:
      if (less_is_below) add(0, equal_high); else add(equal_low, kTop);
      break;
    case GR_CMP_GREATER:  // source > code
      if (less_is_below) add(above_low, kTop); else add(0, below_high);
      break;
    case GR_CMP_GEQUAL:
      if (less_is_below) add(equal_low, kTop); else add(0, equal_high);
      break;
    case GR_CMP_EQUAL: add(equal_low, equal_high); break;
    case GR_CMP_NOTEQUAL:
      add(0, below_high);
      add(above_low, kTop);
      break;
    default: add(0, kTop); break;  // ALWAYS
  }
  if (count == 2 && sides[0].high + 1 >= sides[1].low) {  // no level has the code: one interval
    sides[0].high = sides[1].high;
    count = 1;
  }
  for (int i = 0; i < count; ++i) {
    intervals[i] = {static_cast<double>(sides[i].low) / static_cast<double>(kTop),
                    static_cast<double>(sides[i].high) / static_cast<double>(kTop)};
  }
  return count;
}

}  // namespace glide_shim

using glide_shim::current;


namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grDepthBufferMode(GrDepthBufferMode_t mode) {
  auto &ctx = current();
  if (!ctx.require_open("grDepthBufferMode")) return;
  if (mode != GR_DEPTHBUFFER_DISABLE && !glide_shim::is_z_buffer(mode) &&
      !glide_shim::is_w_buffer(mode)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grDepthBufferMode: unknown mode " + std::to_string(mode));
    return;
  }

  if (mode == ctx.depth.mode) return;
  ctx.flush();
  ctx.depth.mode = mode;
}

void grDepthBufferFunction(GrCmpFnc_t function) {
  auto &ctx = current();
  if (!ctx.require_open("grDepthBufferFunction")) return;
  if (!glide_shim::is_compare(function)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grDepthBufferFunction: unknown compare function " + std::to_string(function));
    return;
  }
  if (function == ctx.depth.function) return;
  ctx.flush();
  ctx.depth.function = function;
}

void grDepthMask(FxBool mask) {
  auto &ctx = current();
  if (!ctx.require_open("grDepthMask")) return;
  if ((mask != FXFALSE) == ctx.depth.mask) return;
  ctx.flush();
  ctx.depth.mask = mask != FXFALSE;
}

void grDepthBiasLevel(FxI16 level) {
  auto &ctx = current();
  if (!ctx.require_open("grDepthBiasLevel")) return;
  if (level == ctx.depth.bias_level) return;
  ctx.flush();
  ctx.depth.bias_level = level;
}

}  // namespace glide_shim_api
