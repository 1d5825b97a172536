// GLSL 1.20 generation. The combine units are one fixed piece of arithmetic driven by 0/1
// selector uniforms, in integer-valued floats (0..255) so (f+1)>>8 is exact; the generated parts
// are the TMU fetch (filter, addressing), chroma key, alpha test and the 565 write.
#include "shader_source.h"

#include <sstream>

namespace glide_shim {
namespace {

bool factor_reads_texture(GrCombineFactor_t factor) {
  const int source = static_cast<int>(factor) & 0x7;
  return source == GR_COMBINE_FACTOR_TEXTURE_ALPHA || source == GR_COMBINE_FACTOR_TEXTURE_RGB;
}

// Row [0]: which terms of ((other or 0) - (local or 0)) * (f + 1) >> 8 + add the function uses.
void set_function(UnitUniforms &u, GrCombineFunction_t function) {
  float *f = u.v[0];
  switch (function) {
    case GR_COMBINE_FUNCTION_LOCAL: f[2] = 1; break;
    case GR_COMBINE_FUNCTION_LOCAL_ALPHA: f[3] = 1; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER: f[0] = 1; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL: f[0] = 1, f[2] = 1; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL_ALPHA: f[0] = 1, f[3] = 1; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL: f[0] = 1, f[1] = 1; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL: f[0] = 1, f[1] = 1, f[2] = 1; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL_ALPHA:
      f[0] = 1, f[1] = 1, f[3] = 1;
      break;
    case GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL: f[1] = 1, f[2] = 1; break;
    case GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL_ALPHA: f[1] = 1, f[3] = 1; break;
    default: break;  // ZERO
  }
}

// Rows [1] and [2].x-y: the factor's source and its one-minus bit. `texture_sources` is false in
// the TMU, where 4 and 5 mean DETAIL and LOD_FRACTION, both zero with a single LOD.
void set_factor(UnitUniforms &u, GrCombineFactor_t factor, bool texture_sources, bool rgb) {
  switch (static_cast<int>(factor) & 0x7) {
    case GR_COMBINE_FACTOR_LOCAL: u.v[1][0] = 1; break;
    case GR_COMBINE_FACTOR_OTHER_ALPHA: u.v[1][1] = 1; break;
    case GR_COMBINE_FACTOR_LOCAL_ALPHA: u.v[1][2] = 1; break;
    case GR_COMBINE_FACTOR_TEXTURE_ALPHA:
      if (texture_sources) u.v[1][3] = 1;
      break;
    case GR_COMBINE_FACTOR_TEXTURE_RGB:
      if (texture_sources && rgb) u.v[2][0] = 1;
      break;
    default: break;  // ZERO
  }
  u.v[2][1] = (static_cast<int>(factor) & 0x8) != 0 ? 1.0f : 0.0f;
}

void set_other(UnitUniforms &u, GrCombineOther_t other) {
  if (other == GR_COMBINE_OTHER_TEXTURE) u.v[3][1] = 1;
  else if (other == GR_COMBINE_OTHER_CONSTANT) u.v[3][2] = 1;
  else u.v[3][0] = 1;
}

UnitUniforms fbi_unit(const CombineUnit &unit, bool rgb) {
  UnitUniforms u;
  set_function(u, unit.function);
  set_factor(u, unit.factor, true, rgb);
  u.v[2][2] = unit.local == GR_COMBINE_LOCAL_CONSTANT ? 1.0f : 0.0f;
  u.v[2][3] = unit.invert ? 1.0f : 0.0f;
  set_other(u, unit.other);
  return u;
}

const char *glsl_compare(GrCmpFnc_t function) {
  switch (function) {
    case GR_CMP_LESS: return "<";
    case GR_CMP_EQUAL: return "==";
    case GR_CMP_LEQUAL: return "<=";
    case GR_CMP_GREATER: return ">";
    case GR_CMP_NOTEQUAL: return "!=";
    case GR_CMP_GEQUAL: return ">=";
    default: return nullptr;  // NEVER and ALWAYS have no comparison
  }
}

const char *kFragmentPrelude = R"(
uniform vec4 u_constant;    // constant colour, RGBA 0..255
uniform vec4 u_chroma;      // chroma-key colour, RGB 0..255 (a unused)
uniform float u_alpha_ref;  // alpha-test reference, 0..255
uniform vec4 u_color_unit[4], u_alpha_unit[4], u_tmu_rgb_unit[4], u_tmu_alpha_unit[4];
uniform sampler2D u_texture;
uniform vec2 u_tex_size;    // largest level in texels
uniform float u_tex_scale;  // texels per Glide s,t unit: the longer side / 256
uniform vec4 u_tex_max;     // largest integer each stored channel holds (31, 63, 15, 1, 255)
uniform float u_screen_height;
varying vec4 v_color;       // iterated RGBA, 0..255, screen-linear like the hardware iterators
varying vec3 v_stq;         // sow, tow and their divisor, screen-linear

// A stored texel widened to 8 bits by bit replication, as the TMU does: the channel's bits
// repeated and the first eight kept, which is floor(n * 256 / max) clamped to 255.
vec4 widen(vec4 stored) {
  vec4 n = floor(stored * u_tex_max + 0.5);
  return min(floor(n * 256.0 / u_tex_max), vec4(255.0));
}
vec4 fetch(float i, float j) {  // texel indices, already clamped or wrapped
  return widen(texture2D(u_texture, (vec2(i, j) + 0.5) / u_tex_size));
}
float clamp_index(float i, float size) { return clamp(i, 0.0, size - 1.0); }
float wrap_index(float i, float size) { return mod(i, size); }

// One combine unit: clamp(((other or 0) - (local or 0)) * (f + 1) >> 8 + add), then invert.
// The selectors k[] are 0 or 1, so every product and sum stays an exact integer.
vec3 combine_rgb(vec4 k0, vec4 k1, vec4 k2, vec3 local, vec3 other, float a_local,
                 float a_other, vec4 tex) {
  vec3 f = k1.x * local + vec3(k1.y * a_other + k1.z * a_local + k1.w * tex.a) + k2.x * tex.rgb;
  f = mix(f, 255.0 - f, k2.y);
  vec3 sum = floor((k0.x * other - k0.y * local) * (f + 1.0) / 256.0) + k0.z * local +
             vec3(k0.w * a_local);
  vec3 result = clamp(sum, 0.0, 255.0);
  return mix(result, 255.0 - result, k2.w);
}
float combine_alpha(vec4 k0, vec4 k1, vec4 k2, float local, float other, float tex_a) {
  float f = k1.x * local + k1.y * other + k1.z * local + k1.w * tex_a;
  f = mix(f, 255.0 - f, k2.y);
  float sum = floor((k0.x * other - k0.y * local) * (f + 1.0) / 256.0) + (k0.z + k0.w) * local;
  float result = clamp(sum, 0.0, 255.0);
  return mix(result, 255.0 - result, k2.w);
}
)";

}  // namespace

UnitUniforms color_unit_uniforms(const CombineUnit &unit) { return fbi_unit(unit, true); }
UnitUniforms alpha_unit_uniforms(const CombineUnit &unit) { return fbi_unit(unit, false); }

UnitUniforms tmu_unit_uniforms(GrCombineFunction_t function, GrCombineFactor_t factor,
                               bool invert) {
  UnitUniforms u;
  set_function(u, function);
  set_factor(u, factor, false, true);
  u.v[2][3] = invert ? 1.0f : 0.0f;
  return u;
}

bool reads_texture(const ColorPathState &path) {
  return path.color.other == GR_COMBINE_OTHER_TEXTURE ||
         path.alpha.other == GR_COMBINE_OTHER_TEXTURE || factor_reads_texture(path.color.factor) ||
         factor_reads_texture(path.alpha.factor);
}

PipelineKey pipeline_key(const GlideContext &context) {
  PipelineKey key;
  key.texture = reads_texture(context.color_path);
  if (key.texture) {
    // With a single LOD the magnification filter decides (voodoo_pipeline.md, texture fetch).
    key.bilinear = context.tmu.mag_filter == GR_TEXTUREFILTER_BILINEAR;
    key.wrap_s = context.tmu.clamp_s == GR_TEXTURECLAMP_WRAP;
    key.wrap_t = context.tmu.clamp_t == GR_TEXTURECLAMP_WRAP;
  }
  key.chroma_key = context.chroma.mode == GR_CHROMAKEY_ENABLE;
  key.alpha_test = context.blend.alpha_test_function;
  key.blending = !(context.blend.rgb_src == GR_BLEND_ONE && context.blend.rgb_dst == GR_BLEND_ZERO);
  key.dither = context.raster.dither;
  return key;
}

std::string PipelineKey::defines() const {
  std::ostringstream s;
  s << "texture " << texture << " bilinear " << bilinear << " wrap " << wrap_s << wrap_t
    << " chroma " << chroma_key << " alpha_test " << alpha_test << " blend " << blending
    << " dither " << dither;
  return s.str();
}

std::string vertex_shader_source() {
  return R"(#version 120
attribute vec2 a_position;  // screen pixels in the Glide origin
attribute float a_depth;    // GL window depth, 0..1
attribute vec4 a_color;     // 0..255
attribute vec3 a_stq;       // sow, tow, divisor
uniform vec2 u_screen;      // width, height in pixels
uniform float u_y_down;     // 1 when the origin is the upper-left corner
varying vec4 v_color;
varying vec3 v_stq;
void main() {
  vec2 ndc = a_position * 2.0 / u_screen - 1.0;
  if (u_y_down > 0.5) ndc.y = -ndc.y;
  gl_Position = vec4(ndc, a_depth * 2.0 - 1.0, 1.0);
  v_color = a_color;
  v_stq = a_stq;
}
)";
}

std::string fragment_shader_source(const PipelineKey &key) {
  std::ostringstream s;
  s << "#version 120\n// " << key.defines() << '\n' << kFragmentPrelude;

  if (key.texture) {
    const char *address_s = key.wrap_s ? "wrap_index" : "clamp_index";
    const char *address_t = key.wrap_t ? "wrap_index" : "clamp_index";
    s << "vec4 sample_tmu() {\n"
         "  // Glide s,t span 0..256 along the longer side; a divisor <= 0 gives s = t = 0.\n"
         "  vec2 st = v_stq.z > 0.0 ? v_stq.xy / v_stq.z : vec2(0.0);\n"
         "  vec2 uv = st * u_tex_scale;  // texel units\n";
    if (key.bilinear) {
      s << "  uv -= 0.5;\n"
           "  vec2 base = floor(uv);\n"
           "  vec2 f = floor((uv - base) * 16.0);  // Voodoo 1: 4-bit sub-texel fraction\n"
        << "  float i0 = " << address_s << "(base.x, u_tex_size.x), i1 = " << address_s
        << "(base.x + 1.0, u_tex_size.x);\n"
        << "  float j0 = " << address_t << "(base.y, u_tex_size.y), j1 = " << address_t
        << "(base.y + 1.0, u_tex_size.y);\n"
        << "  return floor((fetch(i0, j0) * (16.0 - f.x) * (16.0 - f.y) + fetch(i1, j0) * f.x *"
           " (16.0 - f.y) + fetch(i0, j1) * (16.0 - f.x) * f.y + fetch(i1, j1) * f.x * f.y) /"
           " 256.0);\n";
    } else {
      s << "  return fetch(" << address_s << "(floor(uv.x), u_tex_size.x), " << address_t
        << "(floor(uv.y), u_tex_size.y));\n";
    }
    s << "}\n";
  }

  s << "void main() {\n"
       "  vec4 it = clamp(floor(v_color + 1.0 / 1024.0), 0.0, 255.0);  // iterators truncate\n";
  if (key.texture) {
    s << "  vec4 texel = sample_tmu();\n"
         "  vec4 tex = vec4(combine_rgb(u_tmu_rgb_unit[0], u_tmu_rgb_unit[1], u_tmu_rgb_unit[2],"
         " texel.rgb, vec3(0.0), texel.a, 0.0, vec4(0.0)),\n"
         "                  combine_alpha(u_tmu_alpha_unit[0], u_tmu_alpha_unit[1],"
         " u_tmu_alpha_unit[2], texel.a, 0.0, 0.0));\n";
  } else {
    s << "  vec4 tex = vec4(0.0);\n";
  }
  s << "  vec3 c_local = mix(it.rgb, u_constant.rgb, u_color_unit[2].z);\n"
       "  vec3 c_other = u_color_unit[3].x * it.rgb + u_color_unit[3].y * tex.rgb +"
       " u_color_unit[3].z * u_constant.rgb;\n"
       "  float a_local = mix(it.a, u_constant.a, u_alpha_unit[2].z);\n"
       "  float a_other = u_alpha_unit[3].x * it.a + u_alpha_unit[3].y * tex.a +"
       " u_alpha_unit[3].z * u_constant.a;\n";
  if (key.chroma_key) {
    s << "  if (all(equal(c_other, u_chroma.rgb))) discard;  // exact match on 'other'\n";
  }
  s << "  vec3 rgb = combine_rgb(u_color_unit[0], u_color_unit[1], u_color_unit[2], c_local,"
       " c_other, a_local, a_other, tex);\n"
       "  float alpha = combine_alpha(u_alpha_unit[0], u_alpha_unit[1], u_alpha_unit[2],"
       " a_local, a_other, tex.a);\n";

  if (key.alpha_test == GR_CMP_NEVER) {
    s << "  discard;\n";
  } else if (const char *op = glsl_compare(key.alpha_test)) {
    s << "  if (!(alpha " << op << " u_alpha_ref)) discard;\n";
  }

  if (key.blending) {
    // GL blends the 8-bit colour; its rounding may differ from the Voodoo's by one 565 step.
    s << "  gl_FragColor = vec4(rgb, alpha) / 255.0;\n";
  } else {
    if (key.dither == GR_DITHER_DISABLE) {
      s << "  vec3 q = floor(rgb / vec3(8.0, 4.0, 8.0));  // dither off: plain truncation\n";
    } else {
      // The hardware's dither: matrix entry d by frame-buffer row (from the top) and column.
      s << "  vec2 cell = mod(vec2(floor(gl_FragCoord.x), u_screen_height - 1.0 -"
           " floor(gl_FragCoord.y)), ";
      if (key.dither == GR_DITHER_2x2) {
        s << "2.0);\n  float d = cell.y < 1.0 ? (cell.x < 1.0 ? 2.0 : 10.0) : (cell.x < 1.0 ?"
             " 14.0 : 6.0);\n";
      } else {
        s << "4.0);\n"
             "  vec4 row = cell.y < 1.0 ? vec4(0.0, 8.0, 2.0, 10.0) : cell.y < 2.0 ?"
             " vec4(12.0, 4.0, 14.0, 6.0) : cell.y < 3.0 ? vec4(3.0, 11.0, 1.0, 9.0) :"
             " vec4(15.0, 7.0, 13.0, 5.0);\n"
             "  float d = cell.x < 1.0 ? row.x : cell.x < 2.0 ? row.y : cell.x < 3.0 ? row.z :"
             " row.w;\n";
      }
      s << "  vec3 q = floor((rgb * vec3(2.0, 4.0, 2.0) - floor(rgb / 16.0) +"
           " floor(rgb / vec3(128.0, 64.0, 128.0)) + d) / 16.0);\n";
    }
    s << "  gl_FragColor = vec4(q / vec3(31.0, 63.0, 31.0), alpha / 255.0);  // exact 565\n";
  }
  s << "}\n";
  return s.str();
}

}  // namespace glide_shim
