// Generated GLSL 1.20 for the Voodoo's per-pixel equations: texture fetch with the TMU's
// filtering and addressing, the texture, colour and alpha combine units with the hardware's
// (f+1)>>8 arithmetic, chroma key, alpha test, and the 565 write (truncation or dither).
#pragma once

#include "context.h"

#include <string>

namespace glide_shim {

// Everything about the state that changes the shader's code. The combine units' settings and
// all values (colours, references, texture size) are uniforms: llvmpipe compiles each new
// program for tens of milliseconds, so the code varies only where the structure does.
struct PipelineKey {
  bool texture = false;  // the colour path reads the TMU
  bool bilinear = false;
  bool wrap_s = false, wrap_t = false;
  bool chroma_key = false;
  GrCmpFnc_t alpha_test = GR_CMP_ALWAYS;
  bool blending = false;  // GL blends the unquantised colour; otherwise the shader writes 565
  GrDitherMode_t dither = GR_DITHER_DISABLE;

  std::string defines() const;  // also the cache key
};

PipelineKey pipeline_key(const GlideContext &context);
bool reads_texture(const ColorPathState &path);

std::string vertex_shader_source();
std::string fragment_shader_source(const PipelineKey &key);

// A combine unit as four vec4 uniforms of 0/1 selectors (exact in float arithmetic):
// [0] keep other, subtract local, add local, add local alpha (the function);
// [1] factor weights for local, other alpha, local alpha, texture alpha;
// [2] texture-RGB factor weight, one-minus, local is the constant colour, invert;
// [3] other is iterated, texture, constant (one-hot).
struct UnitUniforms {
  float v[4][4] = {};
};
UnitUniforms color_unit_uniforms(const CombineUnit &unit);
UnitUniforms alpha_unit_uniforms(const CombineUnit &unit);
// The TMU's rgb or alpha half: local is the texel, other the absent upstream TMU (zero).
UnitUniforms tmu_unit_uniforms(GrCombineFunction_t function, GrCombineFactor_t factor,
                               bool invert);

struct ShaderProgram {
  unsigned program = 0;
  int color_unit = -1, alpha_unit = -1, tmu_rgb_unit = -1, tmu_alpha_unit = -1;
  int screen = -1, y_down = -1, constant = -1, chroma = -1, alpha_ref = -1, texture = -1,
      tex_size = -1, tex_scale = -1, tex_max = -1, screen_height = -1;
};

}  // namespace glide_shim
