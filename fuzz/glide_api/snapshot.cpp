// Snapshot's copy and comparison of the context's state groups (snapshot.h).
#include "glide_api/snapshot.h"

#include <cstring>

namespace glide_api_fuzz {
namespace {

using glide_shim::GlideContext;

// Field by field: whole-struct byte comparisons would also compare padding, which an assignment
// of the same values may change.
bool same(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }  // NaN equals NaN
bool same(const glide_shim::ColorPathState &a, const glide_shim::ColorPathState &b) {
  return a.color == b.color && a.alpha == b.alpha && a.constant_color == b.constant_color &&
         a.alpha_controls_itrgb == b.alpha_controls_itrgb && a.delta0 == b.delta0 &&
         same(a.iterated4[0], b.iterated4[0]) && same(a.iterated4[1], b.iterated4[1]) &&
         same(a.iterated4[2], b.iterated4[2]) && same(a.iterated4[3], b.iterated4[3]);
}
bool same(const glide_shim::BlendState &a, const glide_shim::BlendState &b) {
  return a.rgb_src == b.rgb_src && a.rgb_dst == b.rgb_dst && a.alpha_src == b.alpha_src &&
         a.alpha_dst == b.alpha_dst && a.alpha_test_function == b.alpha_test_function &&
         a.alpha_test_reference == b.alpha_test_reference;
}
bool same(const glide_shim::ChromaKeyState &a, const glide_shim::ChromaKeyState &b) {
  return a.mode == b.mode && a.value == b.value;
}
bool same(const glide_shim::DepthState &a, const glide_shim::DepthState &b) {
  return a.mode == b.mode && a.function == b.function && a.mask == b.mask &&
         a.bias_level == b.bias_level;
}
bool same(const glide_shim::ClipRect &a, const glide_shim::ClipRect &b) {
  return a.min_x == b.min_x && a.min_y == b.min_y && a.max_x == b.max_x && a.max_y == b.max_y;
}
bool same(const glide_shim::RasterState &a, const glide_shim::RasterState &b) {
  return a.cull == b.cull && a.dither == b.dither && same(a.clip, b.clip) &&
         a.rgb_mask == b.rgb_mask && a.alpha_mask == b.alpha_mask &&
         a.render_buffer == b.render_buffer && a.origin == b.origin && a.stw_hint == b.stw_hint;
}
bool same(const glide_shim::DisplayState &a, const glide_shim::DisplayState &b) {
  return a.open == b.open && a.width == b.width && a.height == b.height &&
         a.color_format == b.color_format && same(a.gamma, b.gamma) && a.swaps == b.swaps &&
         a.none_width == b.none_width && a.none_height == b.none_height;
}
bool same(const glide_shim::TextureTarget &a, const glide_shim::TextureTarget &b) {
  return a.active == b.active && a.address == b.address && a.side == b.side &&
         same(a.saved_clip, b.saved_clip);
}
bool same(const glide_shim::TextureSource &a, const glide_shim::TextureSource &b) {
  return a.valid == b.valid && a.address == b.address && a.small_lod == b.small_lod &&
         a.large_lod == b.large_lod && a.aspect == b.aspect && a.format == b.format &&
         a.even_odd == b.even_odd;
}
bool same(const glide_shim::TextureTables &a, const glide_shim::TextureTables &b) {
  return std::memcmp(a.palette, b.palette, sizeof a.palette) == 0 &&
         std::memcmp(a.ncc, b.ncc, sizeof a.ncc) == 0 && a.ncc_select == b.ncc_select;
}
bool same(const glide_shim::TmuState &a, const glide_shim::TmuState &b) {
  return a.clamp_s == b.clamp_s && a.clamp_t == b.clamp_t && a.min_filter == b.min_filter &&
         a.mag_filter == b.mag_filter && a.mipmap_mode == b.mipmap_mode &&
         a.lod_blend == b.lod_blend && same(a.lod_bias, b.lod_bias) && a.combine == b.combine &&
         a.detail_bias == b.detail_bias && a.detail_scale == b.detail_scale &&
         a.detail_max == b.detail_max && same(a.source, b.source) &&
         a.allow_lod_dither == b.allow_lod_dither && a.lod_dither == b.lod_dither &&
         a.multibase == b.multibase && std::memcmp(a.base, b.base, sizeof a.base) == 0;
}
bool same(const glide_shim::FogState &a, const glide_shim::FogState &b) {
  return a.mode == b.mode && a.color == b.color &&
         std::memcmp(a.table, b.table, sizeof a.table) == 0;
}
bool same(const glide_shim::LfbWriteLayout &a, const glide_shim::LfbWriteLayout &b) {
  return a.color_format == b.color_format && a.swizzle_bytes == b.swizzle_bytes &&
         a.swap_words == b.swap_words;
}
bool same_bookkeeping(const glide_shim::GuTextureManager &a, const glide_shim::GuTextureManager &b) {
  return a.next_id == b.next_id && a.free_base == b.free_base && a.current == b.current &&
         a.ncc_owner[0] == b.ncc_owner[0] && a.ncc_owner[1] == b.ncc_owner[1] &&
         a.next_ncc_table == b.next_ncc_table;
}

}  // namespace

void Snapshot::take(GlideContext &ctx, unsigned what) {
  touches = what;
  initialized = ctx.initialized;
  plain_gl = ctx.plain_gl;
  color_path = ctx.color_path;
  blend = ctx.blend;
  chroma = ctx.chroma;
  depth = ctx.depth;
  raster = ctx.raster;
  display = ctx.display;
  texture_target = ctx.texture_target;
  // Every TMU field but the memory (swapped out and back: no copy).
  std::vector<std::uint8_t> held;
  held.swap(ctx.tmu.memory);
  tmu = ctx.tmu;
  ctx.tmu.memory.swap(held);
  if ((what & kMemory) != 0) memory.assign(ctx.tmu.memory.begin(), ctx.tmu.memory.end());
  fog = ctx.fog;
  std::vector<GrMipMapInfo> records;
  records.swap(ctx.gu_textures.records);
  gu = ctx.gu_textures;
  ctx.gu_textures.records.swap(records);
  if ((what & kGuRecords) != 0) gu.records = ctx.gu_textures.records;
  multipass = ctx.multipass;
  read_locked = ctx.lfb.read_locked, write_locked = ctx.lfb.write_locked;
  write_buffer = ctx.lfb.write_buffer, write_origin = ctx.lfb.write_origin;
  write_mode = ctx.lfb.write_mode, write_pipeline = ctx.lfb.write_pipeline;
  layout = ctx.lfb.layout;
  constant_alpha = ctx.lfb.constant_alpha, constant_depth = ctx.lfb.constant_depth;
  write_pixels = ctx.lfb.write_pixels;
}

const char *Snapshot::differs(const GlideContext &ctx) const {
  if (initialized != ctx.initialized || plain_gl != ctx.plain_gl) return "library state";
  if (!same(color_path, ctx.color_path)) return "colour path";
  if (!same(blend, ctx.blend)) return "blend";
  if (!same(chroma, ctx.chroma)) return "chroma key";
  if (!same(depth, ctx.depth)) return "depth";
  if (!same(raster, ctx.raster)) return "raster";
  if (!same(display, ctx.display)) return "display";
  if (!same(texture_target, ctx.texture_target)) return "texture target";
  if (!same(tmu, ctx.tmu)) return "texture modes";
  if (!same(tmu.tables, ctx.tmu.tables)) return "texture tables";
  if ((touches & kMemory) != 0 && memory != ctx.tmu.memory) return "TMU memory";
  if (!same(fog, ctx.fog)) return "fog";
  if (!same_bookkeeping(gu, ctx.gu_textures)) return "gu texture manager";
  if ((touches & kGuRecords) != 0 &&
      (gu.records.size() != ctx.gu_textures.records.size() ||
       (!gu.records.empty() && std::memcmp(gu.records.data(), ctx.gu_textures.records.data(),
                                           gu.records.size() * sizeof(GrMipMapInfo)) != 0)))
    return "gu mip map records";
  if (multipass.mmid[0] != ctx.multipass.mmid[0] || multipass.mmid[1] != ctx.multipass.mmid[1] ||
      multipass.tc_fnc != ctx.multipass.tc_fnc)
    return "multipass";
  if (read_locked != ctx.lfb.read_locked || write_locked != ctx.lfb.write_locked ||
      write_buffer != ctx.lfb.write_buffer || write_origin != ctx.lfb.write_origin ||
      write_mode != ctx.lfb.write_mode || write_pipeline != ctx.lfb.write_pipeline)
    return "LFB locks";
  if (!same(layout, ctx.lfb.layout) || constant_alpha != ctx.lfb.constant_alpha ||
      constant_depth != ctx.lfb.constant_depth)
    return "LFB write layout";
  if (write_pixels != ctx.lfb.write_pixels) return "LFB write copy";
  return nullptr;
}

}  // namespace glide_api_fuzz
