// Chapter "color combine": the colour, alpha and texture combine units, the constant colour,
// the ITRGB lighting override, the delta0 iterated colour, and the preset shorthands that set
// them (mapped as 3dfx's gglide.c / gu*.c do).
#include "context.h"

#include <string>

using glide_shim::CombineUnit;
using glide_shim::current;
using glide_shim::TexCombineUnit;

namespace {

bool is_function(GrCombineFunction_t f) {
  return (f >= GR_COMBINE_FUNCTION_ZERO && f <= GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL) ||
         f == GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL_ALPHA;
}
bool is_factor(GrCombineFactor_t f) {
  return (f >= GR_COMBINE_FACTOR_ZERO && f <= GR_COMBINE_FACTOR_TEXTURE_RGB) ||
         (f >= GR_COMBINE_FACTOR_ONE && f <= GR_COMBINE_FACTOR_ONE_MINUS_LOD_FRACTION);
}
bool is_other(GrCombineOther_t o) {
  return o >= GR_COMBINE_OTHER_ITERATED && o <= GR_COMBINE_OTHER_CONSTANT;
}

// Checks a colour or alpha combine; reports and returns false when any argument is bad.
bool check_unit(const char *name, const CombineUnit &unit, bool alpha) {
  auto &ctx = current();
  if (!ctx.require_open(name)) return false;
  std::string problem;
  if (!is_function(unit.function)) problem = "unknown function " + std::to_string(unit.function);
  else if (!is_factor(unit.factor)) problem = "unknown factor " + std::to_string(unit.factor);
  else if (!is_other(unit.other)) problem = "unknown other source " + std::to_string(unit.other);
  else if (unit.local < GR_COMBINE_LOCAL_ITERATED || unit.local > GR_COMBINE_LOCAL_DEPTH ||
           (!alpha && unit.local == GR_COMBINE_LOCAL_DEPTH))
    problem = "unknown local source " + std::to_string(unit.local);
  if (!problem.empty()) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, std::string(name) + ": " + problem);
    return false;
  }
  if (unit.local == GR_COMBINE_LOCAL_DEPTH) {
    ctx.report(GLIDESHIM_ERR_UNSUPPORTED,
               std::string(name) + ": GR_COMBINE_LOCAL_DEPTH is not implemented yet");
    return false;
  }
  return true;
}

void set_unit(CombineUnit &target, const CombineUnit &unit) {
  if (target == unit) return;
  current().flush();
  target = unit;
}

// The GR_TEXTURECOMBINE_* presets, as gu.c maps them; `name` is the entry point reported.
void texture_combine_preset(const char *name, GrChipID_t tmu, GrTextureCombineFnc_t function) {
  struct Setting {
    GrCombineFunction_t function;
    GrCombineFactor_t factor;
    FxBool invert;
  };
  static const Setting kSettings[] = {
      /* ZERO */ {GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, FXFALSE},
      /* DECAL */ {GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, FXFALSE},
      /* OTHER */ {GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, FXFALSE},
      /* ADD */ {GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL, GR_COMBINE_FACTOR_ONE, FXFALSE},
      /* MULTIPLY */ {GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL, FXFALSE},
      /* SUBTRACT */ {GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL, GR_COMBINE_FACTOR_ONE, FXFALSE},
      /* DETAIL */ {GR_COMBINE_FUNCTION_BLEND, GR_COMBINE_FACTOR_ONE_MINUS_DETAIL_FACTOR, FXFALSE},
      /* DETAIL_OTHER */ {GR_COMBINE_FUNCTION_BLEND, GR_COMBINE_FACTOR_DETAIL_FACTOR, FXFALSE},
      /* TRILINEAR_ODD */ {GR_COMBINE_FUNCTION_BLEND, GR_COMBINE_FACTOR_ONE_MINUS_LOD_FRACTION, FXFALSE},
      /* TRILINEAR_EVEN */ {GR_COMBINE_FUNCTION_BLEND, GR_COMBINE_FACTOR_LOD_FRACTION, FXFALSE},
      /* ONE */ {GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, FXTRUE},
  };
  auto &ctx = current();
  if (!ctx.require_open(name)) return;
  if (tmu != GR_TMU0) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               std::string(name) + ": TMU " + std::to_string(tmu) + " does not exist (one TMU)");
    return;
  }
  if (function < GR_TEXTURECOMBINE_ZERO || function > GR_TEXTURECOMBINE_ONE) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM,
               std::string(name) + ": unknown function " + std::to_string(function));
    return;
  }
  const Setting &s = kSettings[function];
  grTexCombine(tmu, s.function, s.factor, s.function, s.factor, s.invert, s.invert);
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grColorCombine(GrCombineFunction_t function, GrCombineFactor_t factor,
                    GrCombineLocal_t local, GrCombineOther_t other, FxBool invert) {
  const CombineUnit unit{function, factor, local, other, invert != FXFALSE};
  if (!check_unit("grColorCombine", unit, false)) return;
  set_unit(current().color_path.color, unit);
}

void grAlphaCombine(GrCombineFunction_t function, GrCombineFactor_t factor,
                    GrCombineLocal_t local, GrCombineOther_t other, FxBool invert) {
  const CombineUnit unit{function, factor, local, other, invert != FXFALSE};
  if (!check_unit("grAlphaCombine", unit, true)) return;
  set_unit(current().color_path.alpha, unit);
}

void grTexCombine(GrChipID_t tmu, GrCombineFunction_t rgb_function,
                  GrCombineFactor_t rgb_factor, GrCombineFunction_t alpha_function,
                  GrCombineFactor_t alpha_factor, FxBool rgb_invert, FxBool alpha_invert) {
  auto &ctx = current();
  if (!ctx.require_open("grTexCombine")) return;
  if (tmu != GR_TMU0) {
    ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE,
               "grTexCombine: TMU " + std::to_string(tmu) + " does not exist (one TMU)");
    return;
  }
  if (!is_function(rgb_function) || !is_function(alpha_function) || !is_factor(rgb_factor) ||
      !is_factor(alpha_factor)) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "grTexCombine: unknown function or factor");
    return;
  }
  const TexCombineUnit unit{rgb_function,          rgb_factor,
                            alpha_function,   alpha_factor,
                            rgb_invert != FXFALSE, alpha_invert != FXFALSE};
  if (ctx.tmu.combine == unit) return;
  ctx.flush();
  ctx.tmu.combine = unit;
}

void grConstantColorValue(GrColor_t value) {
  auto &ctx = current();
  if (!ctx.require_open("grConstantColorValue")) return;
  if (value == ctx.color_path.constant_color) return;
  ctx.flush();
  ctx.color_path.constant_color = value;
}

void grAlphaControlsITRGBLighting(FxBool enable) {
  auto &ctx = current();
  if (!ctx.require_open("grAlphaControlsITRGBLighting")) return;
  if ((enable != FXFALSE) == ctx.color_path.alpha_controls_itrgb) return;
  ctx.flush();
  ctx.color_path.alpha_controls_itrgb = enable != FXFALSE;
}

void grConstantColorValue4(float a, float r, float g, float b) {
  auto &ctx = current();
  if (!ctx.require_open("grConstantColorValue4")) return;
  for (float value : {a, r, g, b}) {
    if (!(value >= 0.0f && value <= 255.0f)) {
      ctx.report(GLIDESHIM_ERR_OUT_OF_RANGE, "grConstantColorValue4: " + std::to_string(value) +
                                                 " is outside 0..255 (a, r, g, b)");
      return;
    }
  }
  // As gglide.c: kept as the delta0 colour, which the RGB iterators hold in delta0 mode; the
  // constant colour (grConstantColorValue) is not changed.
  ctx.flush();
  ctx.color_path.iterated4[0] = a;
  ctx.color_path.iterated4[1] = r;
  ctx.color_path.iterated4[2] = g;
  ctx.color_path.iterated4[3] = b;
}

void guColorCombineFunction(GrColorCombineFnc_t function) {
  struct Setting {
    GrCombineFunction_t function;
    GrCombineFactor_t factor;
    GrCombineLocal_t local;
    GrCombineOther_t other;
    FxBool invert;
  };
  static const Setting kSettings[] = {
      /* ZERO */ {GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_NONE, FXFALSE},
      /* CCRGB */ {GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_NONE, FXFALSE},
      /* ITRGB */ {GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_NONE, FXFALSE},
      /* ITRGB_DELTA0 */ {GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_NONE, FXFALSE},
      /* DECAL_TEXTURE */ {GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* TEXTURE_TIMES_CCRGB */ {GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL, GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* TEXTURE_TIMES_ITRGB */ {GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* TEXTURE_TIMES_ITRGB_DELTA0 */ {GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* TEXTURE_TIMES_ITRGB_ADD_ALPHA */ {GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL_ALPHA, GR_COMBINE_FACTOR_LOCAL, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* TEXTURE_TIMES_ALPHA */ {GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL_ALPHA, GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* TEXTURE_TIMES_ALPHA_ADD_ITRGB */ {GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL, GR_COMBINE_FACTOR_LOCAL_ALPHA, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* TEXTURE_ADD_ITRGB */ {GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* TEXTURE_SUB_ITRGB */ {GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* CCRGB_BLEND_ITRGB_ON_TEXALPHA */ {GR_COMBINE_FUNCTION_BLEND, GR_COMBINE_FACTOR_TEXTURE_ALPHA, GR_COMBINE_LOCAL_CONSTANT, GR_COMBINE_OTHER_ITERATED, FXFALSE},
      /* DIFF_SPEC_A */ {GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL, GR_COMBINE_FACTOR_LOCAL_ALPHA, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* DIFF_SPEC_B */ {GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL_ALPHA, GR_COMBINE_FACTOR_LOCAL, GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE},
      /* ONE */ {GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_NONE, FXTRUE},
  };
  if (!current().require_open("guColorCombineFunction")) return;
  if (function < GR_COLORCOMBINE_ZERO || function > GR_COLORCOMBINE_ONE) {
    current().report(GLIDESHIM_ERR_INVALID_ENUM,
                     "guColorCombineFunction: unknown function " + std::to_string(function));
    return;
  }
  const Setting &s = kSettings[function];
  // gu.c leaves delta0 mode first, and the two *_DELTA0 presets enter it again.
  const bool delta0 = function == GR_COLORCOMBINE_ITRGB_DELTA0 ||
                      function == GR_COLORCOMBINE_TEXTURE_TIMES_ITRGB_DELTA0;
  if (delta0 != current().color_path.delta0) {
    current().flush();
    current().color_path.delta0 = delta0;
  }
  grColorCombine(s.function, s.factor, s.local, s.other, s.invert);
}

void guAlphaSource(GrAlphaSource_t mode) {
  if (!current().require_open("guAlphaSource")) return;
  switch (mode) {
    case GR_ALPHASOURCE_CC_ALPHA:
      grAlphaCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_CONSTANT,
                     GR_COMBINE_OTHER_NONE, FXFALSE);
      return;
    case GR_ALPHASOURCE_ITERATED_ALPHA:
      grAlphaCombine(GR_COMBINE_FUNCTION_LOCAL, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED,
                     GR_COMBINE_OTHER_NONE, FXFALSE);
      return;
    case GR_ALPHASOURCE_TEXTURE_ALPHA:
      grAlphaCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE, GR_COMBINE_LOCAL_NONE,
                     GR_COMBINE_OTHER_TEXTURE, FXFALSE);
      return;
    case GR_ALPHASOURCE_TEXTURE_ALPHA_TIMES_ITERATED_ALPHA:
      grAlphaCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_LOCAL,
                     GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
      return;
    default:
      current().report(GLIDESHIM_ERR_INVALID_ENUM,
                       "guAlphaSource: unknown mode " + std::to_string(mode));
  }
}

void guTexCombineFunction(GrChipID_t tmu, GrTextureCombineFnc_t function) {
  texture_combine_preset("guTexCombineFunction", tmu, function);
}

void grTexCombineFunction(GrChipID_t tmu, GrTextureCombineFnc_t function) {
  texture_combine_preset("grTexCombineFunction", tmu, function);
}

}  // namespace glide_shim_api
