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

// The fidelity knobs (docs/environment.md, GLIDESHIM_PLAIN_GL): each replaces one modelled
// Voodoo behaviour by plain GL's, so the frame is no longer exact.
constexpr int kPlainWrite = 1;      // "write": GL's rounding to 565, no truncation or dither
constexpr int kPlainIterators = 2;  // "iterators": GL's interpolated colour, not truncated
constexpr int kPlainCombine = 4;    // "combine": x * f / 255 (GL_MODULATE), not (f + 1) >> 8
constexpr int kPlainBilinear = 8;   // "bilinear": GL_LINEAR's weights, not 4-bit ones
// The knobs named in a comma-separated list ("write,combine"; "all"); unknown names are ignored.
// The kPlain* bits of a GLIDESHIM_PLAIN_GL list (nullptr: none). Names it does not know are
// left out and listed in `unknown` (comma-separated, empty when every name was known).
int parse_fidelity_knobs(const char *list, std::string &unknown);

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
  // level sampled and its scale are uniforms (or compiled in: level_compiled), and the shader
  // does no LOD work per pixel.
  bool mipmap = false;
  bool lod_dither = false;  // GR_MIPMAP_NEAREST_DITHER with the hint that allows it
  bool wrap_s = false, wrap_t = false;
  bool alpha_controls_itrgb = false;  // the colour local chosen by the texture's alpha bit 7
  bool chroma_key = false;
  GrCmpFnc_t alpha_test = GR_CMP_ALWAYS;
  bool blending = false;  // GL blends the unquantised colour; otherwise the shader writes 565
  GrDitherMode_t dither = GR_DITHER_DISABLE;
  GrFogMode_t fog = GR_FOG_DISABLE;  // the fog source (low byte of grFogMode); flags are uniforms

  // The fast paths (GlideContext::fast_paths, off with GLIDESHIM_EXACT=1): code that gives the
  // exact path's bytes for less work per pixel. The combine units' sources and invert flags are
  // compiled in (below) instead of selected by 0/1 uniforms; the alpha combine is left out when
  // nothing can observe its result (no alpha test, no blending: a 565 buffer stores no alpha);
  // the dither matrix entry comes from integer arithmetic on the pixel's column and its row from
  // the top (a varying, not gl_FragCoord.y, except for lines), and texels from texelFetch
  // (GLSL 1.30). Off, the program is the exact path's, unchanged.
  bool fast = false;
  bool texel_fetch = false;  // fast, and the TMU has a source (texelFetch of a real texture)
  // Fast, with the sources below compiled in. A state sweep (a test of every combine setting)
  // would compile a program per setting, so the renderer compiles them in only for a state
  // drawn a second time; the first time the sources stay uniforms (without_sources()).
  bool sources = false;
  int rows_mod4 = 0;         // fast dither: the target's height & 3
  // Fast dither of lines: the row from gl_FragCoord.y. A line's varyings change only along it,
  // so v_row there is the line's own y, not the pixel's row (set by the renderer, which knows
  // the primitive).
  bool line_rows = false;
  // Fast with sources and one reachable LOD (no mip-mapping): the level sampled compiled in
  // as constants, its width and height in texels, its GR_LOD value (the scale from Glide's
  // 0..256 s,t to its texels is 2^-level_lod) and lodmin, instead of uniforms (a gather per
  // pixel in llvmpipe's fragment code) or a flat varying (a fifth input slot that llvmpipe sets
  // up, stores and reads back for every triangle). Set by the renderer, which binds the texture.
  bool level_compiled = false;
  int level_width = 0, level_height = 0, level_lod = 0, lod_min = 0;
  // Compiled-in sources, as unit_uniforms selects them (fast only; zero otherwise):
  // local 1 = constant, other 0/1/2 = iterated/texture/constant.
  int color_local = 0, color_other = 0, alpha_local = 0, alpha_other = 0;
  bool color_invert = false, alpha_invert = false, tmu_rgb_invert = false, tmu_alpha_invert = false;

  // Fidelity knobs (GLIDESHIM_PLAIN_GL, off by default): modelled behaviours replaced by what
  // plain GL does, for measuring what each costs and how far the picture moves without it.
  int plain = 0;  // kPlain* bits

  PipelineKey without_sources() const;
  std::string defines() const;  // also the cache key
};

// The key of the context's current state; `fast` allows the fast paths.
PipelineKey pipeline_key(const GlideContext &context, bool fast);
bool reads_texture(const ColorPathState &path);

std::string vertex_shader_source(bool fast);  // fast: GLSL 1.30, for PipelineKey::fast programs
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
