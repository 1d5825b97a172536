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
  const float bias = static_cast<float>(depth.bias_level);
  if (is_w_buffer(depth.mode)) {
    // A bias of b codes moves w by 2^(b/4096), i.e. scales 1/w by 2^(-b/4096): still affine.
    return std::clamp(std::min(oow, 1.0f) * std::exp2(-bias / 4096.0f), 0.0f, 1.0f);
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

}  // namespace glide_shim

using glide_shim::current;


extern "C" {

void grDepthBufferMode(GrDepthBufferMode_t mode) {
  auto &ctx = current();
  if (!ctx.require_open("grDepthBufferMode")) return;
  if (mode == GR_DEPTHBUFFER_ZBUFFER_COMPARE_TO_BIAS ||
      mode == GR_DEPTHBUFFER_WBUFFER_COMPARE_TO_BIAS) {
    ctx.report(GLIDESHIM_ERR_UNSUPPORTED,
               "grDepthBufferMode: the COMPARE_TO_BIAS modes are not implemented yet");
    return;
  }
  if (mode != GR_DEPTHBUFFER_DISABLE && mode != GR_DEPTHBUFFER_ZBUFFER &&
      mode != GR_DEPTHBUFFER_WBUFFER) {
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

}  // extern "C"
