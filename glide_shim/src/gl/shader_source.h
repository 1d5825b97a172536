// Generated GLSL 1.20 for the Voodoo's per-pixel equations: texture fetch with the TMU's
// filtering and addressing, the texture, colour and alpha combine units with the hardware's
// (f+1)>>8 arithmetic, chroma key, alpha test, and the 565 write (truncation or dither).
#pragma once

#include "context.h"

#include <string>

namespace glide_shim {

// The parts of a combine unit that shape its arithmetic; sources and invert are uniforms.
struct UnitShape {
  GrCombineFunction_t function = GR_COMBINE_FUNCTION_ZERO;
  GrCombineFactor_t factor = GR_COMBINE_FACTOR_ZERO;  // zero when the function has no product
};

// Everything about the state that changes the shader's code. llvmpipe compiles each new
// program for tens of milliseconds, so sources, invert flags and every value (colours,
// references, texture size) are uniforms; the function and factor of each unit are compiled in,
// which keeps the per-pixel arithmetic straight-line (20-30% faster than selecting at run time).
struct PipelineKey {
  UnitShape color, alpha, tmu_rgb, tmu_alpha;
  bool texture = false;  // the colour path reads the TMU
  // Filters: with one reachable LOD (no mip-mapping) only the magnification filter is used.
  bool mag_bilinear = false, min_bilinear = false;
  // LOD computed per pixel (grTexMipMapMode on, more than one level); without it the LOD, the
  // level sampled and its scale are uniforms, and the shader does no LOD work per pixel.
  bool mipmap = false;
  bool lod_dither = false;  // GR_MIPMAP_NEAREST_DITHER with the hint that allows it
  bool wrap_s = false, wrap_t = false;
  bool alpha_controls_itrgb = false;  // the colour local chosen by the texture's alpha bit 7
  bool chroma_key = false;
  GrCmpFnc_t alpha_test = GR_CMP_ALWAYS;
  bool blending = false;  // GL blends the unquantised colour; otherwise the shader writes 565
  GrDitherMode_t dither = GR_DITHER_DISABLE;
  GrFogMode_t fog = GR_FOG_DISABLE;  // the fog source (low byte of grFogMode); flags are uniforms

  std::string defines() const;  // also the cache key
};

PipelineKey pipeline_key(const GlideContext &context);
bool reads_texture(const ColorPathState &path);

std::string vertex_shader_source();
std::string fragment_shader_source(const PipelineKey &key);

// The run-time half of a combine unit, as 0/1 selectors (exact in float arithmetic):
// x = local is the constant colour, y = invert, z/w unused; other is one-hot in `other`
// (iterated, texture, constant).
struct UnitUniforms {
  float select[4] = {};
  float other[4] = {};
};
UnitUniforms unit_uniforms(const CombineUnit &unit);

struct ShaderProgram {
  unsigned program = 0;
  int color_select = -1, color_other = -1, alpha_select = -1, alpha_other = -1,
      tmu_invert = -1;
  int screen = -1, y_down = -1, constant = -1, chroma = -1, alpha_ref = -1, texture = -1,
      tex_size = -1, tex_levels = -1, lod_range = -1, lod_bias = -1, screen_height = -1;
  int level = -1, level_scale = -1, detail = -1;
  int fog_color = -1, fog_flags = -1, fog_table = -1, fog_bias = -1;
};

}  // namespace glide_shim
