// Chapter "pixel operations": alpha blending, alpha test, chroma key, dither and gamma.
#include "context.h"

#include <cmath>
#include <string>

using glide_shim::current;

namespace {

bool is_blend_factor(GrAlphaBlendFnc_t f) {
  return (f >= GR_BLEND_ZERO && f <= GR_BLEND_ONE_MINUS_DST_ALPHA) ||
         f == GR_BLEND_ALPHA_SATURATE;  // 0xF, PREFOG_COLOR as a destination factor
}


}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grAlphaBlendFunction(GrAlphaBlendFnc_t rgb_sf, GrAlphaBlendFnc_t rgb_df,
                          GrAlphaBlendFnc_t alpha_sf, GrAlphaBlendFnc_t alpha_df) {
  auto &ctx = current();
  if (!ctx.require_open("grAlphaBlendFunction")) return;
  if (!is_blend_factor(rgb_sf) || !is_blend_factor(rgb_df) || !is_blend_factor(alpha_sf) ||
      !is_blend_factor(alpha_df)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grAlphaBlendFunction: unknown blend factor");
    return;
  }
  ctx.flush();
  ctx.blend.rgb_src = rgb_sf;
  ctx.blend.rgb_dst = rgb_df;
  ctx.blend.alpha_src = alpha_sf;
  ctx.blend.alpha_dst = alpha_df;
}

void grAlphaTestFunction(GrCmpFnc_t function) {
  auto &ctx = current();
  if (!ctx.require_open("grAlphaTestFunction")) return;
  if (!glide_shim::is_compare(function)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               "grAlphaTestFunction: unknown compare function " + std::to_string(function));
    return;
  }
  if (function == ctx.blend.alpha_test_function) return;
  ctx.flush();
  ctx.blend.alpha_test_function = function;
}

void grAlphaTestReferenceValue(GrAlpha_t value) {
  auto &ctx = current();
  if (!ctx.require_open("grAlphaTestReferenceValue")) return;
  if (value == ctx.blend.alpha_test_reference) return;
  ctx.flush();
  ctx.blend.alpha_test_reference = value;
}

void grChromakeyMode(GrChromakeyMode_t mode) {
  auto &ctx = current();
  if (!ctx.require_open("grChromakeyMode")) return;
  if (mode != GR_CHROMAKEY_DISABLE && mode != GR_CHROMAKEY_ENABLE) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grChromakeyMode: unknown mode " + std::to_string(mode));
    return;
  }
  if (mode == ctx.chroma.mode) return;
  ctx.flush();
  ctx.chroma.mode = mode;
}

void grChromakeyValue(GrColor_t value) {
  auto &ctx = current();
  if (!ctx.require_open("grChromakeyValue")) return;
  if (value == ctx.chroma.value) return;
  ctx.flush();
  ctx.chroma.value = value;
}

void grDitherMode(GrDitherMode_t mode) {
  auto &ctx = current();
  if (!ctx.require_open("grDitherMode")) return;
  if (mode != GR_DITHER_DISABLE && mode != GR_DITHER_2x2 && mode != GR_DITHER_4x4) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grDitherMode: unknown mode " + std::to_string(mode));
    return;
  }
  if (mode == ctx.raster.dither) return;
  ctx.flush();
  ctx.raster.dither = mode;
}

void grGammaCorrectionValue(float value) {
  auto &ctx = current();
  if (!ctx.require_open("grGammaCorrectionValue")) return;
  // The CLUT is only computed from it at scan-out, so no flush: frame-buffer data never changes.
  if (!std::isfinite(value) || value <= 0.0f || value > 20.0f) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "grGammaCorrectionValue: gamma " +
                                               std::to_string(value) + " is outside (0, 20]");
    return;
  }
  ctx.display.gamma = value;
}

}  // namespace glide_shim_api
