// The GlideContext: construction, the defaults grSstWinOpen loads, and the current pointer.
#include "context.h"

#include "gl/gl_renderer.h"
#include "gl/shader_source.h"

#include <cstdlib>
#include <cstring>

namespace glide_shim {

GlideContext::GlideContext() = default;
GlideContext::~GlideContext() = default;

GlideContext &current() {
  static GlideContext context;
  return context;
}

void GlideContext::load_window_defaults(int width, int height, GrColorFormat_t format,
                                        GrOriginLocation_t origin) {
  vertex_fields_stale = true;
  // Colour path: vertex colour through, constant alpha (gsst.c's grSstWinOpen).
  color_path.color = {GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                      GR_COMBINE_LOCAL_ITERATED, GR_COMBINE_OTHER_ITERATED, false};
  color_path.alpha = {GR_COMBINE_FUNCTION_SCALE_OTHER, GR_COMBINE_FACTOR_ONE,
                      GR_COMBINE_LOCAL_NONE, GR_COMBINE_OTHER_CONSTANT, false};
  color_path.constant_color = 0xFFFFFFFFu;
  color_path.alpha_controls_itrgb = false;
  color_path.delta0 = false;
  for (float &value : color_path.iterated4) value = 0.0f;

  blend = {GR_BLEND_ONE, GR_BLEND_ZERO, GR_BLEND_ONE, GR_BLEND_ZERO, GR_CMP_ALWAYS, 0};
  chroma = {GR_CHROMAKEY_DISABLE, 0};
  depth = {GR_DEPTHBUFFER_DISABLE, GR_CMP_LESS, false, 0};

  raster.cull = GR_CULL_DISABLE;
  raster.dither = GR_DITHER_4x4;
  raster.clip = {0, 0, static_cast<FxU32>(width), static_cast<FxU32>(height)};
  raster.rgb_mask = true;
  raster.alpha_mask = false;
  raster.render_buffer = GR_BUFFER_BACKBUFFER;
  raster.origin = origin;
  raster.stw_hint = 0;

  // TMU: clamp, point sampled, no mipmaps, and a texture combine of ZERO, so texturing
  // contributes nothing until the program configures it.
  tmu.clamp_s = tmu.clamp_t = GR_TEXTURECLAMP_CLAMP;
  tmu.min_filter = tmu.mag_filter = GR_TEXTUREFILTER_POINT_SAMPLED;
  tmu.mipmap_mode = GR_MIPMAP_DISABLE;
  tmu.lod_blend = false;
  tmu.lod_bias = 0.0f;
  tmu.combine = {GR_COMBINE_FUNCTION_ZERO, GR_COMBINE_FACTOR_NONE, GR_COMBINE_FUNCTION_ZERO,
                 GR_COMBINE_FACTOR_NONE, false, false};
  tmu.detail_bias = tmu.detail_scale = tmu.detail_max = 0;
  tmu.allow_lod_dither = false;
  tmu.lod_dither = false;
  tmu.multibase = false;
  for (std::int64_t &base : tmu.base) base = 0;
  tmu.source = {false, 0, GR_LOD_1, GR_LOD_1, GR_ASPECT_1x1, GR_TEXFMT_RGB_565,
                GR_MIPMAPLEVELMASK_BOTH};
  tmu.tables = TextureTables{};  // palette and NCC tables all zero, NCC table 0 selected
  tmu.memory.assign(kTmuMemoryBytes, 0);
  gu_textures.reset();  // the driver's grSstWinOpen calls guTexMemReset

  display.open = true;
  display.width = width;
  display.height = height;
  display.color_format = format;
  display.gamma = 1.7f;
  display.swaps = 0;
  display.dump_dir_missing_reported = false;

  lfb = LfbLockState{};
  fog = FogState{GR_FOG_DISABLE, 0, {}};
  perf = PerfStatsState{};
  texture_target = TextureTarget{};
  plain_gl = false;
  const char *exact = std::getenv("GLIDESHIM_EXACT");
  fast_paths = !(exact != nullptr && std::strcmp(exact, "1") == 0);
  std::string unknown_knobs;
  fidelity_knobs = parse_fidelity_knobs(std::getenv("GLIDESHIM_PLAIN_GL"), unknown_knobs);
  if (!unknown_knobs.empty()) {
    report(GLIDESHIM_ERR_INVALID_VALUE,
           "grSstWinOpen: GLIDESHIM_PLAIN_GL names no fidelity knob " + unknown_knobs +
               " (known: write, iterators, combine, bilinear, all); the others apply");
  }
}

void GlideContext::flush() {
  vertex_fields_stale = true;  // the state that fields_read reads may change next
  if (renderer) renderer->flush();
}

void close_window_at_exit() {
  static const bool registered = std::atexit([] {
    if (current().display.open) grSstWinClose();
  }) == 0;
  (void)registered;
}

bool is_compare(GrCmpFnc_t function) {
  return function >= GR_CMP_NEVER && function <= GR_CMP_ALWAYS;
}

Rgba8 unpack_color(GrColor_t color, GrColorFormat_t format) {
  auto byte = [color](int shift) { return static_cast<std::uint8_t>((color >> shift) & 0xFFu); };
  if (format == GR_COLORFORMAT_ABGR) return {byte(0), byte(8), byte(16), byte(24)};
  if (format == GR_COLORFORMAT_RGBA) return {byte(24), byte(16), byte(8), byte(0)};
  if (format == GR_COLORFORMAT_BGRA) return {byte(8), byte(16), byte(24), byte(0)};
  return {byte(16), byte(8), byte(0), byte(24)};  // GR_COLORFORMAT_ARGB
}

}  // namespace glide_shim
