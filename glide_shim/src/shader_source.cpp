// GLSL generation. The combine units are written out per state as straight-line expressions in
// integer-valued floats (0..255), so the compiler folds away everything the state does not use.
#include "shader_source.h"

#include <sstream>

namespace glide_shim {
namespace {

bool factor_reads_texture(GrCombineFactor_t factor) {
  const int source = static_cast<int>(factor) & 0x7;
  return source == GR_COMBINE_FACTOR_TEXTURE_ALPHA || source == 0x5;  // 5: texture RGB
}

std::string one_minus(GrCombineFactor_t factor, const std::string &source) {
  if ((static_cast<int>(factor) & 0x8) != 0) return "(255.0 - " + source + ")";
  return source;
}

// The factor of the colour unit: a vec3 in 0..255.
std::string color_factor(GrCombineFactor_t factor) {
  switch (static_cast<int>(factor) & 0x7) {
    case GR_COMBINE_FACTOR_LOCAL: return one_minus(factor, "c_local");
    case GR_COMBINE_FACTOR_OTHER_ALPHA: return one_minus(factor, "vec3(a_other)");
    case GR_COMBINE_FACTOR_LOCAL_ALPHA: return one_minus(factor, "vec3(a_local)");
    case GR_COMBINE_FACTOR_TEXTURE_ALPHA: return one_minus(factor, "vec3(tex.a)");
    case 0x5: return one_minus(factor, "tex.rgb");
    default: return one_minus(factor, "vec3(0.0)");
  }
}

// The factor of the alpha unit: a float in 0..255.
std::string alpha_factor(GrCombineFactor_t factor) {
  switch (static_cast<int>(factor) & 0x7) {
    case GR_COMBINE_FACTOR_LOCAL:
    case GR_COMBINE_FACTOR_LOCAL_ALPHA: return one_minus(factor, "a_local");
    case GR_COMBINE_FACTOR_OTHER_ALPHA: return one_minus(factor, "a_other");
    case GR_COMBINE_FACTOR_TEXTURE_ALPHA: return one_minus(factor, "tex.a");
    default: return one_minus(factor, "0.0");
  }
}

// The TMU's factor: local is this TMU's texel, other is the (absent) upstream TMU, so zero.
// DETAIL (4) and LOD_FRACTION (5) are zero with a single LOD level.
std::string tmu_factor(GrCombineFactor_t factor, bool rgb) {
  switch (static_cast<int>(factor) & 0x7) {
    case GR_COMBINE_FACTOR_LOCAL: return one_minus(factor, rgb ? "texel.rgb" : "texel.a");
    case GR_COMBINE_FACTOR_LOCAL_ALPHA:
      return one_minus(factor, rgb ? "vec3(texel.a)" : "texel.a");
    default: return one_minus(factor, rgb ? "vec3(0.0)" : "0.0");
  }
}

// One combine unit: out = clamp(((other or 0) - (local or 0)) * (f + 1) >> 8 + add), then the
// optional invert. `zero` is the type's zero literal.
std::string combine(const std::string &result, GrCombineFunction_t function,
                    const std::string &factor, const std::string &local,
                    const std::string &other, const std::string &local_alpha, bool invert,
                    const std::string &type) {
  const std::string zero = type + "(0.0)";
  std::string minuend = other, subtrahend = zero, add = zero;
  switch (function) {
    case GR_COMBINE_FUNCTION_ZERO: minuend = zero; break;
    case GR_COMBINE_FUNCTION_LOCAL: minuend = zero; add = local; break;
    case GR_COMBINE_FUNCTION_LOCAL_ALPHA: minuend = zero; add = type + "(" + local_alpha + ")"; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER: break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL: add = local; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL_ALPHA: add = type + "(" + local_alpha + ")"; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL: subtrahend = local; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL:
      subtrahend = local;
      add = local;
      break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL_ALPHA:
      subtrahend = local;
      add = type + "(" + local_alpha + ")";
      break;
    case GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL:
      minuend = zero;
      subtrahend = local;
      add = local;
      break;
    case GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL_ALPHA:
      minuend = zero;
      subtrahend = local;
      add = type + "(" + local_alpha + ")";
      break;
    default: minuend = zero; break;
  }
  std::ostringstream s;
  s << "  " << type << " " << result << " = clamp(floor((" << minuend << " - " << subtrahend
    << ") * (" << factor << " + 1.0) / 256.0) + " << add << ", 0.0, 255.0);\n";
  if (invert) s << "  " << result << " = 255.0 - " << result << ";\n";
  return s.str();
}

std::string color_local(GrCombineLocal_t local) {
  return local == GR_COMBINE_LOCAL_CONSTANT ? "u_constant.rgb" : "it.rgb";
}
std::string color_other(GrCombineOther_t other) {
  if (other == GR_COMBINE_OTHER_TEXTURE) return "tex.rgb";
  if (other == GR_COMBINE_OTHER_CONSTANT) return "u_constant.rgb";
  return "it.rgb";
}
std::string alpha_local(GrCombineLocal_t local) {
  return local == GR_COMBINE_LOCAL_CONSTANT ? "u_constant.a" : "it.a";
}
std::string alpha_other(GrCombineOther_t other) {
  if (other == GR_COMBINE_OTHER_TEXTURE) return "tex.a";
  if (other == GR_COMBINE_OTHER_CONSTANT) return "u_constant.a";
  return "it.a";
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
uniform sampler2D u_texture;
uniform vec2 u_tex_size;    // largest level in texels
uniform float u_tex_scale;  // texels per Glide s,t unit: the longer side / 256
uniform vec4 u_tex_max;     // largest integer each stored channel holds (31, 63, 15, 1, 255)
uniform float u_screen_height;
varying vec4 v_color;       // iterated RGBA, 0..255, screen-linear like the hardware iterators
varying vec3 v_stq;         // sow, tow and their divisor, screen-linear

// A stored texel widened to 8 bits by bit replication, as the TMU does: the first eight bits
// of the channel's bits repeated, floor(n * 256 / max) clamped to 255.
vec4 widen(vec4 stored) {
  vec4 n = floor(stored * u_tex_max + 0.5);
  return min(floor(n * 256.0 / u_tex_max), vec4(255.0));
}
vec4 fetch(float i, float j) {  // texel indices, already clamped or wrapped
  return widen(texture2D(u_texture, (vec2(i, j) + 0.5) / u_tex_size));
}
float clamp_index(float i, float size) { return clamp(i, 0.0, size - 1.0); }
float wrap_index(float i, float size) { return mod(i, size); }
)";

}  // namespace

bool reads_texture(const ColorPathState &path) {
  return path.color.other == GR_COMBINE_OTHER_TEXTURE ||
         path.alpha.other == GR_COMBINE_OTHER_TEXTURE || factor_reads_texture(path.color.factor) ||
         factor_reads_texture(path.alpha.factor);
}

PipelineKey pipeline_key(const GlideContext &context) {
  PipelineKey key;
  key.color = context.color_path.color;
  key.alpha = context.color_path.alpha;
  key.texture = reads_texture(context.color_path);
  if (key.texture) {
    key.tex = context.tmu.combine;
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
  auto unit = [&s](const char *name, const CombineUnit &u) {
    s << name << ':' << u.function << ',' << u.factor << ',' << u.local << ',' << u.other << ','
      << u.invert << ';';
  };
  unit("cc", color);
  unit("ac", alpha);
  s << "tc:" << tex.rgb_function << ',' << tex.rgb_factor << ',' << tex.alpha_function << ','
    << tex.alpha_factor << ',' << tex.rgb_invert << ',' << tex.alpha_invert << ';' << "t:"
    << texture << bilinear << wrap_s << wrap_t << ";ck:" << chroma_key << ";at:" << alpha_test
    << ";bl:" << blending << ";di:" << dither;
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
      << combine("tmu_rgb", key.tex.rgb_function, tmu_factor(key.tex.rgb_factor, true),
                 "texel.rgb", "vec3(0.0)", "texel.a", key.tex.rgb_invert, "vec3")
      << combine("tmu_a", key.tex.alpha_function, tmu_factor(key.tex.alpha_factor, false),
                 "texel.a", "0.0", "texel.a", key.tex.alpha_invert, "float")
      << "  vec4 tex = vec4(tmu_rgb, tmu_a);\n";
  } else {
    s << "  vec4 tex = vec4(0.0);\n";
  }
  s << "  vec3 c_local = " << color_local(key.color.local) << ";\n"
    << "  vec3 c_other = " << color_other(key.color.other) << ";\n"
    << "  float a_local = " << alpha_local(key.alpha.local) << ";\n"
    << "  float a_other = " << alpha_other(key.alpha.other) << ";\n";
  if (key.chroma_key) {
    s << "  if (all(equal(c_other, u_chroma.rgb))) discard;  // exact match on the 'other' colour\n";
  }
  s << combine("rgb", key.color.function, color_factor(key.color.factor), "c_local", "c_other",
               "a_local", key.color.invert, "vec3")
    << combine("alpha", key.alpha.function, alpha_factor(key.alpha.factor), "a_local", "a_other",
               "a_local", key.alpha.invert, "float");

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
      s << "  vec3 v = rgb;\n"
           "  vec3 q = vec3(floor((v.r * 2.0 - floor(v.r / 16.0) + floor(v.r / 128.0) + d) /"
           " 16.0),\n"
           "                floor((v.g * 4.0 - floor(v.g / 16.0) + floor(v.g / 64.0) + d) /"
           " 16.0),\n"
           "                floor((v.b * 2.0 - floor(v.b / 16.0) + floor(v.b / 128.0) + d) /"
           " 16.0));\n";
    }
    s << "  gl_FragColor = vec4(q / vec3(31.0, 63.0, 31.0), alpha / 255.0);  // exact 565\n";
  }
  s << "}\n";
  return s.str();
}

}  // namespace glide_shim
