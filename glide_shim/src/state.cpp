// grGlideGetState / grGlideSetState and grDisableAllEffects. The saved state is every setting
// that changes a pixel (combine, blend and tests, chroma key, depth, clip, masks, render buffer,
// origin, hints, fog with its table, the TMU's modes, combine and source, the LFB write layout
// and constants, which the SST-1 GrState holds in lfbMode and beside it, and the gu texture
// manager's current mip map, which it holds as current_mm), packed field by field
// into the program's opaque GrState, which is a plain 312-byte block as in 3dfx's glide.h.
#include "context.h"

#include <cstring>
#include <type_traits>

using glide_shim::current;

namespace {

constexpr FxU32 kStateMagic = 0x47534833u;  // marks a GrState that grGlideGetState filled

#pragma pack(push, 1)
struct PackedCombine {
  FxI32 function, factor, local, other;
  FxU8 invert;
};
struct PackedState {
  FxU32 magic;
  PackedCombine color, alpha;
  FxU32 constant_color;
  FxI32 blend[4], alpha_test_function;
  FxU8 alpha_test_reference;
  FxI32 chroma_mode;
  FxU32 chroma_value;
  FxI32 depth_mode, depth_function;
  FxU8 depth_mask;
  FxI16 depth_bias;
  FxI32 cull, dither;
  FxU32 clip[4];
  FxU8 rgb_mask, alpha_mask;
  FxI32 render_buffer, origin;
  FxU32 stw_hint;
  FxI32 fog_mode;
  FxU32 fog_color;
  FxU8 fog_table[GR_FOG_TABLE_SIZE];
  FxU8 clamp_s, clamp_t, min_filter, mag_filter, mipmap_mode;  // enums of 0..2: a byte each
  FxU8 lod_blend, allow_lod_dither, lod_dither, multibase;
  float lod_bias;
  std::int64_t base[4];
  FxU8 tmu_rgb_function, tmu_rgb_factor, tmu_alpha_function, tmu_alpha_factor;  // 0..16
  FxU8 tmu_rgb_invert, tmu_alpha_invert;
  FxU8 source_valid;
  FxU32 source_address;
  FxI32 source_small_lod, source_large_lod, source_aspect, source_format;
  FxU32 source_even_odd;
  FxI32 ncc_select;
  FxU8 alpha_controls_itrgb, delta0;  // fbzColorPath bit 7; guColorCombineFunction's delta0
  float iterated4[4];                  // grConstantColorValue4 (gc->state.a, r, g, b)
  FxI8 detail_bias;                    // tDetail
  FxU8 detail_scale, detail_max;
  FxU8 lfb_mode;  // lfbMode's write bits: RGBA lanes (bits 0-1), byte swizzle (2), word swap (3)
  FxU8 lfb_constant_alpha;
  FxU16 lfb_constant_depth;
  FxI32 gu_current_mipmap;  // guTexSource's id, which the SST-1 GrState keeps as current_mm
};
#pragma pack(pop)

static_assert(std::is_trivially_copyable_v<PackedState>);
static_assert(sizeof(PackedState) <= sizeof(GrState),
              "GrState (GLIDE_STATE_PAD_SIZE bytes) must hold the whole saved state");

PackedCombine pack(const glide_shim::CombineUnit &unit) {
  return {unit.function, unit.factor, unit.local, unit.other, unit.invert ? FxU8{1} : FxU8{0}};
}

glide_shim::CombineUnit unpack(const PackedCombine &unit) {
  return {unit.function, unit.factor, unit.local, unit.other, unit.invert != 0};
}

// The TMU's enums and combine codes fit a byte; packing them so leaves GrState room.
FxU8 byte(FxI32 value) { return static_cast<FxU8>(value); }

PackedState save(const glide_shim::GlideContext &ctx) {
  PackedState s{};
  s.magic = kStateMagic;
  s.color = pack(ctx.color_path.color);
  s.alpha = pack(ctx.color_path.alpha);
  s.constant_color = ctx.color_path.constant_color;
  const auto &blend = ctx.blend;
  s.blend[0] = blend.rgb_src, s.blend[1] = blend.rgb_dst;
  s.blend[2] = blend.alpha_src, s.blend[3] = blend.alpha_dst;
  s.alpha_test_function = blend.alpha_test_function;
  s.alpha_test_reference = blend.alpha_test_reference;
  s.chroma_mode = ctx.chroma.mode;
  s.chroma_value = ctx.chroma.value;
  s.depth_mode = ctx.depth.mode;
  s.depth_function = ctx.depth.function;
  s.depth_mask = ctx.depth.mask ? 1 : 0;
  s.depth_bias = ctx.depth.bias_level;
  const auto &raster = ctx.raster;
  s.cull = raster.cull;
  s.dither = raster.dither;
  s.clip[0] = raster.clip.min_x, s.clip[1] = raster.clip.min_y;
  s.clip[2] = raster.clip.max_x, s.clip[3] = raster.clip.max_y;
  s.rgb_mask = raster.rgb_mask ? 1 : 0;
  s.alpha_mask = raster.alpha_mask ? 1 : 0;
  s.render_buffer = raster.render_buffer;
  s.origin = raster.origin;
  s.stw_hint = raster.stw_hint;
  s.fog_mode = ctx.fog.mode;
  s.fog_color = ctx.fog.color;
  std::memcpy(s.fog_table, ctx.fog.table, sizeof s.fog_table);
  const auto &tmu = ctx.tmu;
  s.clamp_s = byte(tmu.clamp_s), s.clamp_t = byte(tmu.clamp_t);
  s.min_filter = byte(tmu.min_filter), s.mag_filter = byte(tmu.mag_filter);
  s.mipmap_mode = byte(tmu.mipmap_mode);
  s.lod_blend = tmu.lod_blend ? 1 : 0;
  s.allow_lod_dither = tmu.allow_lod_dither ? 1 : 0;
  s.lod_dither = tmu.lod_dither ? 1 : 0;
  s.multibase = tmu.multibase ? 1 : 0;
  s.lod_bias = tmu.lod_bias;
  std::memcpy(s.base, tmu.base, sizeof s.base);
  s.tmu_rgb_function = byte(tmu.combine.rgb_function);
  s.tmu_rgb_factor = byte(tmu.combine.rgb_factor);
  s.tmu_alpha_function = byte(tmu.combine.alpha_function);
  s.tmu_alpha_factor = byte(tmu.combine.alpha_factor);
  s.tmu_rgb_invert = tmu.combine.rgb_invert ? 1 : 0;
  s.tmu_alpha_invert = tmu.combine.alpha_invert ? 1 : 0;
  s.source_valid = tmu.source.valid ? 1 : 0;
  s.source_address = tmu.source.address;
  s.source_small_lod = tmu.source.small_lod, s.source_large_lod = tmu.source.large_lod;
  s.source_aspect = tmu.source.aspect, s.source_format = tmu.source.format;
  s.source_even_odd = tmu.source.even_odd;
  s.ncc_select = tmu.tables.ncc_select;
  s.alpha_controls_itrgb = ctx.color_path.alpha_controls_itrgb ? 1 : 0;
  s.delta0 = ctx.color_path.delta0 ? 1 : 0;
  std::memcpy(s.iterated4, ctx.color_path.iterated4, sizeof s.iterated4);
  s.detail_bias = static_cast<FxI8>(tmu.detail_bias);
  s.detail_scale = static_cast<FxU8>(tmu.detail_scale);
  s.detail_max = static_cast<FxU8>(tmu.detail_max);
  const glide_shim::LfbWriteLayout &layout = ctx.lfb.layout;
  s.lfb_mode = static_cast<FxU8>(layout.color_format | (layout.swizzle_bytes ? 4 : 0) |
                                 (layout.swap_words ? 8 : 0));
  s.lfb_constant_alpha = ctx.lfb.constant_alpha;
  s.lfb_constant_depth = ctx.lfb.constant_depth;
  s.gu_current_mipmap = ctx.gu_textures.current;
  return s;
}

void restore(glide_shim::GlideContext &ctx, const PackedState &s) {
  ctx.color_path.color = unpack(s.color);
  ctx.color_path.alpha = unpack(s.alpha);
  ctx.color_path.constant_color = s.constant_color;
  auto &blend = ctx.blend;
  blend.rgb_src = s.blend[0], blend.rgb_dst = s.blend[1];
  blend.alpha_src = s.blend[2], blend.alpha_dst = s.blend[3];
  blend.alpha_test_function = s.alpha_test_function;
  blend.alpha_test_reference = s.alpha_test_reference;
  ctx.chroma = {s.chroma_mode, s.chroma_value};
  ctx.depth = {s.depth_mode, s.depth_function, s.depth_mask != 0, s.depth_bias};
  auto &raster = ctx.raster;
  raster.cull = s.cull;
  raster.dither = s.dither;
  raster.clip = {s.clip[0], s.clip[1], s.clip[2], s.clip[3]};
  raster.rgb_mask = s.rgb_mask != 0;
  raster.alpha_mask = s.alpha_mask != 0;
  raster.render_buffer = s.render_buffer;
  raster.origin = s.origin;
  raster.stw_hint = s.stw_hint;
  ctx.fog.mode = s.fog_mode;
  ctx.fog.color = s.fog_color;
  std::memcpy(ctx.fog.table, s.fog_table, sizeof s.fog_table);
  auto &tmu = ctx.tmu;
  tmu.clamp_s = s.clamp_s, tmu.clamp_t = s.clamp_t;
  tmu.min_filter = s.min_filter, tmu.mag_filter = s.mag_filter;
  tmu.mipmap_mode = s.mipmap_mode;
  tmu.lod_blend = s.lod_blend != 0;
  tmu.allow_lod_dither = s.allow_lod_dither != 0;
  tmu.lod_dither = s.lod_dither != 0;
  tmu.multibase = s.multibase != 0;
  tmu.lod_bias = s.lod_bias;
  std::memcpy(tmu.base, s.base, sizeof s.base);
  tmu.combine = {s.tmu_rgb_function, s.tmu_rgb_factor, s.tmu_alpha_function,
                 s.tmu_alpha_factor, s.tmu_rgb_invert != 0, s.tmu_alpha_invert != 0};
  tmu.source = {s.source_valid != 0, s.source_address, s.source_small_lod,
                s.source_large_lod, s.source_aspect, s.source_format, s.source_even_odd};
  tmu.tables.ncc_select = s.ncc_select;
  ctx.color_path.alpha_controls_itrgb = s.alpha_controls_itrgb != 0;
  ctx.color_path.delta0 = s.delta0 != 0;
  std::memcpy(ctx.color_path.iterated4, s.iterated4, sizeof s.iterated4);
  tmu.detail_bias = s.detail_bias;
  tmu.detail_scale = s.detail_scale;
  tmu.detail_max = s.detail_max;
  ctx.lfb.layout = {s.lfb_mode & 3, (s.lfb_mode & 4) != 0, (s.lfb_mode & 8) != 0};
  ctx.lfb.constant_alpha = s.lfb_constant_alpha;
  ctx.lfb.constant_depth = s.lfb_constant_depth;
  ctx.gu_textures.current = s.gu_current_mipmap;
}

}  // namespace

namespace glide_shim_api {  // exported through entry_points_*.cpp (exception barrier)

void grGlideGetState(GrState *state) {
  auto &ctx = current();
  if (!ctx.require_open("grGlideGetState")) return;
  if (state == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grGlideGetState: state is NULL");
    return;
  }
  const PackedState packed = save(ctx);
  std::memset(state, 0, sizeof *state);
  std::memcpy(state, &packed, sizeof packed);
}

void grGlideSetState(const GrState *state) {
  auto &ctx = current();
  if (!ctx.require_open("grGlideSetState")) return;
  if (state == nullptr) {
    ctx.report(GLIDESHIM_ERR_NULL_POINTER, "grGlideSetState: state is NULL");
    return;
  }
  PackedState packed;
  std::memcpy(&packed, state, sizeof packed);
  if (packed.magic != kStateMagic) {
    ctx.report(GLIDESHIM_ERR_INVALID_VALUE,
               "grGlideSetState: the GrState was not filled by grGlideGetState");
    return;
  }
  ctx.flush();
  restore(ctx, packed);
}

void grDisableAllEffects(void) {
  auto &ctx = current();
  if (!ctx.require_open("grDisableAllEffects")) return;
  // As gglide.c: blending, alpha test, chroma key, depth bias and buffering, and fog off.
  grAlphaBlendFunction(GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO);
  grAlphaTestFunction(GR_CMP_ALWAYS);
  grChromakeyMode(GR_CHROMAKEY_DISABLE);
  grDepthBiasLevel(0);
  grDepthBufferMode(GR_DEPTHBUFFER_DISABLE);
  grFogMode(GR_FOG_DISABLE);
}

}  // namespace glide_shim_api
