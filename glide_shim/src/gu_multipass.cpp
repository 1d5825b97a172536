// Multipass texturing (guMP*, the SST-1 driver's gump.c and ddgump.c): two mip maps of the gu
// texture manager act as two "virtual TMUs" on the one real TMU. guMPDrawTriangle draws the
// triangle once per mip map, each pass with a TMU0 combine that gives its share of the
// two-TMU result, and adds (or multiplies) the second pass onto the first with the blender,
// depth-testing it for equality so it lands exactly on the first pass's pixels.
#include "context.h"

#include <string>

using glide_shim::current;

namespace {

bool is_allocated(const glide_shim::GlideContext &ctx, GrMipMapId_t mmid) {
  return mmid < ctx.gu_textures.next_id;
}

// The TMU0 combine _gumpTexCombineFunction writes for one pass. Its textureMode bits translate
// to grTexCombine arguments: SST_TC_REPLACE is LOCAL; ZERO_OTHER with SST_TC_BLEND_LOD(FRAC)
// is SCALE_MINUS_LOCAL_ADD_LOCAL ((0 - local) * f + local), and the factor is the detail
// factor (or LOD fraction) itself with REVERSE_BLEND set, one minus it without.
void pass_combine(GrMPTextureCombineFnc_t function, int pass, GrCombineFunction_t *combine,
                  GrCombineFactor_t *factor) {
  *combine = GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL;
  // Which pass sets REVERSE_BLEND: the second for DETAIL0 and TRILINEAR0, the first for
  // DETAIL1 and TRILINEAR1.
  const bool first_pass = pass == 0;
  switch (function) {
    case GR_MPTEXTURECOMBINE_DETAIL0:
      *factor = first_pass ? GR_COMBINE_FACTOR_ONE_MINUS_DETAIL_FACTOR
                           : GR_COMBINE_FACTOR_DETAIL_FACTOR;
      return;
    case GR_MPTEXTURECOMBINE_DETAIL1:
      *factor = first_pass ? GR_COMBINE_FACTOR_DETAIL_FACTOR
                           : GR_COMBINE_FACTOR_ONE_MINUS_DETAIL_FACTOR;
      return;
    case GR_MPTEXTURECOMBINE_TRILINEAR0:
      *factor = first_pass ? GR_COMBINE_FACTOR_ONE_MINUS_LOD_FRACTION
                           : GR_COMBINE_FACTOR_LOD_FRACTION;
      return;
    case GR_MPTEXTURECOMBINE_TRILINEAR1:
      *factor = first_pass ? GR_COMBINE_FACTOR_LOD_FRACTION
                           : GR_COMBINE_FACTOR_ONE_MINUS_LOD_FRACTION;
      return;
    default:  // ADD and MULTIPLY: each pass replaces with its own texel
      *combine = GR_COMBINE_FUNCTION_LOCAL;
      *factor = GR_COMBINE_FACTOR_NONE;
      return;
  }
}

void select_pass(int pass) {
  const GrMPState &state = current().multipass;
  GrCombineFunction_t combine;
  GrCombineFactor_t factor;
  pass_combine(state.tc_fnc, pass, &combine, &factor);
  guTexSource(state.mmid[pass]);
  grTexCombine(GR_TMU0, combine, factor, combine, factor, FXFALSE, FXFALSE);
}

// The colour combine with its local/alpha bias removed, as the driver clears
// SST_CC_ADD_CLOCAL, SST_CC_ADD_ALOCAL and SST_CC_SUB_CLOCAL: functions whose "other" is zero
// become ZERO, the rest SCALE_OTHER.
GrCombineFunction_t without_bias(GrCombineFunction_t function) {
  switch (function) {
    case GR_COMBINE_FUNCTION_ZERO:
    case GR_COMBINE_FUNCTION_LOCAL:
    case GR_COMBINE_FUNCTION_LOCAL_ALPHA:
    case GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL:
    case GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL_ALPHA:
      return GR_COMBINE_FUNCTION_ZERO;
    default:
      return GR_COMBINE_FUNCTION_SCALE_OTHER;
  }
}

void set_color_combine(const glide_shim::CombineUnit &unit) {
  grColorCombine(unit.function, unit.factor, unit.local, unit.other, unit.invert ? FXTRUE : FXFALSE);
}

// The state guMPDrawTriangle changes between passes, and restores afterwards.
struct SavedState {
  glide_shim::CombineUnit color;
  glide_shim::BlendState blend;
  glide_shim::DepthState depth;
  GrFogMode_t fog_mode;
  glide_shim::TexCombineUnit tex_combine;

  explicit SavedState(const glide_shim::GlideContext &ctx)
      : color(ctx.color_path.color),
        blend(ctx.blend),
        depth(ctx.depth),
        fog_mode(ctx.fog.mode),
        tex_combine(ctx.tmu.combine) {}

  void restore() const {
    set_color_combine(color);
    grAlphaBlendFunction(blend.rgb_src, blend.rgb_dst, blend.alpha_src, blend.alpha_dst);
    grDepthBufferFunction(depth.function);
    grDepthMask(depth.mask ? FXTRUE : FXFALSE);
    grFogMode(fog_mode);
    grTexCombine(GR_TMU0, tex_combine.rgb_function, tex_combine.rgb_factor,
                 tex_combine.alpha_function, tex_combine.alpha_factor,
                 tex_combine.rgb_invert ? FXTRUE : FXFALSE,
                 tex_combine.alpha_invert ? FXTRUE : FXFALSE);
  }
};

// Later passes land on the first pass's pixels: depth compared for equality, not written.
void depth_equal_no_writes(const glide_shim::GlideContext &ctx) {
  if (ctx.depth.mode == GR_DEPTHBUFFER_DISABLE) return;
  grDepthBufferFunction(GR_CMP_EQUAL);
  grDepthMask(FXFALSE);
}

bool fog_enabled(const glide_shim::GlideContext &ctx) {
  return (ctx.fog.mode & 0xFF) != GR_FOG_DISABLE;
}

// ADD, DETAIL* and TRILINEAR*: the second pass is added onto the first, without the fog colour
// and the colour combine's bias, which the first pass already contributed.
void draw_added_passes(glide_shim::GlideContext &ctx, const GrVertex *a, const GrVertex *b,
                       const GrVertex *c) {
  select_pass(0);
  grDrawTriangle(a, b, c);

  select_pass(1);
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE);
  depth_equal_no_writes(ctx);
  if (fog_enabled(ctx)) grFogMode(ctx.fog.mode | GR_FOG_ADD2);
  glide_shim::CombineUnit color = ctx.color_path.color;
  color.function = without_bias(color.function);
  set_color_combine(color);
  grDrawTriangle(a, b, c);
}

// MULTIPLY: the first pass without fog colour and bias, the second (the texel alone) multiplies
// the destination, and with fog a third pass adds the fog colour's share.
void draw_multiplied_passes(glide_shim::GlideContext &ctx, const SavedState &saved,
                            const GrVertex *a, const GrVertex *b, const GrVertex *c) {
  const bool fog = fog_enabled(ctx);
  select_pass(0);
  if (fog) grFogMode(saved.fog_mode | GR_FOG_ADD2);
  glide_shim::CombineUnit color = saved.color;
  color.function = without_bias(color.function);
  set_color_combine(color);
  grDrawTriangle(a, b, c);

  select_pass(1);
  grAlphaBlendFunction(GR_BLEND_DST_COLOR, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  depth_equal_no_writes(ctx);
  if (fog) grFogMode(GR_FOG_DISABLE);
  grColorCombine(GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                 GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_TEXTURE, FXFALSE);
  grDrawTriangle(a, b, c);

  if (!fog) return;
  // Third pass: no texture; the colour combine gives zero, and fog in MULT2 mode leaves only
  // fog * fogColor, added to the destination.
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE, GR_BLEND_ONE);
  grFogMode(saved.fog_mode | GR_FOG_MULT2);
  grColorCombine(GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, GR_COMBINE_LOCAL_ITERATED,
                 GR_COMBINE_OTHER_ITERATED, FXFALSE);
  grDrawTriangle(a, b, c);
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void guMPInit(void) {
  GrMPState &state = current().multipass;
  for (GrMipMapId_t &mmid : state.mmid) mmid = GR_NULL_MIPMAP_HANDLE;
  state.tc_fnc = GR_MPTEXTURECOMBINE_ADD;
}

void guMPTexCombineFunction(GrMPTextureCombineFnc_t tc) {
  if (tc > GR_MPTEXTURECOMBINE_SUBTRACT) {
    current().report(GLIDESHIM_ERR_INVALID_ENUM,
                     "guMPTexCombineFunction: " + std::to_string(tc) +
                         " is not a GR_MPTEXTURECOMBINE_* function");
    return;
  }
  current().multipass.tc_fnc = tc;
}

void guMPTexSource(GrChipID_t virtual_tmu, GrMipMapId_t mmid) {
  auto &ctx = current();
  if (virtual_tmu < GR_TMU0 || virtual_tmu >= GR_TMU0 + GLIDE_NUM_VIRTUAL_TMU) {
    ctx.report(GLIDESHIM_ERR_INVALID_ENUM, "guMPTexSource: virtual TMU " +
                                               std::to_string(virtual_tmu) +
                                               " is not GR_TMU0 or GR_TMU1");
    return;
  }
  if (mmid != GR_NULL_MIPMAP_HANDLE && !is_allocated(ctx, mmid)) {
    ctx.report(GLIDESHIM_ERR_INVALID_VALUE, "guMPTexSource: mip map " + std::to_string(mmid) +
                                                " was not allocated by guTexAllocateMemory");
    return;
  }
  ctx.multipass.mmid[virtual_tmu] = mmid;
}

void guMPDrawTriangle(const GrVertex *a, const GrVertex *b, const GrVertex *c) {
  auto &ctx = current();
  if (!ctx.require_open("guMPDrawTriangle")) return;
  if (a == nullptr || b == nullptr || c == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "guMPDrawTriangle: NULL vertex pointer");
    return;
  }
  // The states one TMU cannot split into passes (the driver reports "Illegal state"): blending,
  // alpha-controlled lighting, alpha test and chroma key.
  const glide_shim::BlendState &blend = ctx.blend;
  const bool blending = !(blend.rgb_src == GR_BLEND_ONE && blend.rgb_dst == GR_BLEND_ZERO &&
                          blend.alpha_src == GR_BLEND_ONE && blend.alpha_dst == GR_BLEND_ZERO);
  if (blending || ctx.color_path.alpha_controls_itrgb ||
      blend.alpha_test_function != GR_CMP_ALWAYS ||
      ctx.chroma.mode != GR_CHROMAKEY_DISABLE) {
    ctx.report(GLIDESHIM_ERR_INCONSISTENT,
               "guMPDrawTriangle: illegal state for multipass (alpha blending, "
               "grAlphaControlsITRGBLighting, alpha test or chroma key is on)");
    return;
  }
  if (ctx.multipass.tc_fnc == GR_MPTEXTURECOMBINE_SUBTRACT) {
    ctx.report(GLIDESHIM_ERR_UNSUPPORTED,
               "guMPDrawTriangle: GR_MPTEXTURECOMBINE_SUBTRACT is not implemented (the alpha "
               "blender cannot subtract)");
    return;
  }
  for (int pass = 0; pass < GLIDE_NUM_VIRTUAL_TMU; ++pass) {
    if (!is_allocated(ctx, ctx.multipass.mmid[pass])) {
      ctx.report(GLIDESHIM_ERR_INCONSISTENT,
                 "guMPDrawTriangle: virtual TMU " + std::to_string(pass) +
                     " has no mip map (call guMPTexSource first)");
      return;
    }
  }
  const SavedState saved(ctx);
  if (ctx.multipass.tc_fnc == GR_MPTEXTURECOMBINE_MULTIPLY) {
    draw_multiplied_passes(ctx, saved, a, b, c);
  } else {
    draw_added_passes(ctx, a, b, c);
  }
  saved.restore();
}

}  // namespace glide_shim_api
