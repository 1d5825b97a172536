// GLSL 1.20 generation. Each combine unit is written out as straight-line arithmetic for its
// function and factor, in integer-valued floats (0..255) so (f+1)>>8 is exact; its sources and
// invert flag are 0/1 uniforms. Also generated: the TMU fetch, chroma key, alpha test, 565 write.
#include "gl/shader_source.h"

#include <algorithm>
#include <sstream>

namespace glide_shim {
namespace {

bool factor_reads_texture(GrCombineFactor_t factor) {
  const int source = static_cast<int>(factor) & 0x7;
  return source == GR_COMBINE_FACTOR_TEXTURE_ALPHA || source == GR_COMBINE_FACTOR_TEXTURE_RGB;
}

bool has_product(GrCombineFunction_t function) {
  return function != GR_COMBINE_FUNCTION_ZERO && function != GR_COMBINE_FUNCTION_LOCAL &&
         function != GR_COMBINE_FUNCTION_LOCAL_ALPHA;
}

UnitShape shape(GrCombineFunction_t function, GrCombineFactor_t factor) {
  return {function, has_product(function) ? factor : GR_COMBINE_FACTOR_ZERO};
}

std::string one_minus(GrCombineFactor_t factor, const std::string &source) {
  if ((static_cast<int>(factor) & 0x8) != 0) return "(255.0 - " + source + ")";
  return source;
}

// The factor's source, 0..255. In the TMU (`fbi` false) local is the texel, other the absent
// upstream TMU, and 4/5 mean DETAIL (grTexDetailControl's factor at the pixel's LOD) and
// LOD_FRACTION (the fraction of the pixel's LOD, 0..255; zero without mip-mapping).
std::string factor_code(GrCombineFactor_t factor, bool rgb, bool fbi, const std::string &local,
                        const std::string &local_alpha, const std::string &other_alpha) {
  const std::string zero = rgb ? "vec3(0.0)" : "0.0";
  auto widen = [rgb](const std::string &scalar) { return rgb ? "vec3(" + scalar + ")" : scalar; };
  switch (static_cast<int>(factor) & 0x7) {
    case GR_COMBINE_FACTOR_LOCAL: return one_minus(factor, local);
    case GR_COMBINE_FACTOR_OTHER_ALPHA: return one_minus(factor, widen(other_alpha));
    case GR_COMBINE_FACTOR_LOCAL_ALPHA: return one_minus(factor, widen(local_alpha));
    case GR_COMBINE_FACTOR_TEXTURE_ALPHA:  // DETAIL in the TMU
      return one_minus(factor, widen(fbi ? "tex.a" : "detail"));
    case GR_COMBINE_FACTOR_TEXTURE_RGB:  // LOD_FRACTION in the TMU
      if (!fbi) return one_minus(factor, widen("lod_frac"));
      return one_minus(factor, rgb ? "tex.rgb" : zero);
    default: return one_minus(factor, zero);
  }
}

// One combine unit, straight-line: clamp(((other or 0) - (local or 0)) * (f + 1) >> 8 + add),
// then inverted when the `invert` uniform expression is 1. The fast paths compile the invert in:
// `invert` is then "" (none) or "!" (always).
std::string combine_code(const std::string &result, const UnitShape &unit, bool rgb, bool fbi,
                         const std::string &local, const std::string &other,
                         const std::string &local_alpha, const std::string &other_alpha,
                         const std::string &invert, bool plain = false) {
  const std::string type = rgb ? "vec3" : "float";
  const std::string zero = type + "(0.0)";
  const std::string widened_local_alpha = rgb ? "vec3(" + local_alpha + ")" : local_alpha;
  std::string minuend = other, subtrahend = zero, add = zero;
  switch (unit.function) {
    case GR_COMBINE_FUNCTION_ZERO: minuend = zero; break;
    case GR_COMBINE_FUNCTION_LOCAL: minuend = zero, add = local; break;
    case GR_COMBINE_FUNCTION_LOCAL_ALPHA: minuend = zero, add = widened_local_alpha; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER: break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL: add = local; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL_ALPHA: add = widened_local_alpha; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL: subtrahend = local; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL: subtrahend = add = local; break;
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL_ALPHA:
      subtrahend = local, add = widened_local_alpha;
      break;
    case GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL: minuend = zero, subtrahend = add = local; break;
    default:  // SCALE_MINUS_LOCAL_ADD_LOCAL_ALPHA
      minuend = zero, subtrahend = local, add = widened_local_alpha;
      break;
  }
  std::ostringstream s;
  s << "  " << type << " " << result << " = ";
  if (has_product(unit.function) && plain) {
    // Fidelity knob `combine`: GL_MODULATE's product, x * f / 255 unrounded.
    s << "clamp((" << minuend << " - " << subtrahend << ") * "
      << factor_code(unit.factor, rgb, fbi, local, local_alpha, other_alpha) << " / 255.0 + "
      << add << ", 0.0, 255.0);\n";
  } else if (has_product(unit.function)) {
    s << "clamp(floor((" << minuend << " - " << subtrahend << ") * ("
      << factor_code(unit.factor, rgb, fbi, local, local_alpha, other_alpha)
      << " + 1.0) / 256.0) + " << add << ", 0.0, 255.0);\n";
  } else {
    s << add << ";\n";
  }
  if (invert == "!") {
    s << "  " << result << " = 255.0 - " << result << ";\n";
  } else if (!invert.empty()) {
    s << "  " << result << " = mix(" << result << ", 255.0 - " << result << ", " << invert << ");\n";
  }
  return s.str();
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

// The fog unit, after the alpha test (Voodoo order): the blend factor from the table, the
// iterated alpha or the iterated Z, then (fog - colour) * (f + 1) >> 8 + colour with MULT2
// dropping the "+ colour" and "- colour" terms and ADD2 replacing the fog colour by zero.
std::string fog_code(GrFogMode_t source) {
  if (source == GR_FOG_DISABLE) return "";
  std::ostringstream s;
  s << "  float fog_blend = ";
  if (source == GR_FOG_WITH_TABLE) {
    s << "fog_table_blend();\n";
  } else if (source == GR_FOG_WITH_ITERATED_ALPHA) {
    s << "it.a;\n";
  } else {  // iterated Z: the top 8 bits of the clamped 16-bit z
    s << "floor(clamp(floor(v_fog + 1.0 / 64.0), 0.0, 65535.0) / 256.0);\n";
  }
  s << "  vec3 fog = u_fog_flags.y > 0.5 ? vec3(0.0) : u_fog_color;\n"
       "  if (u_fog_flags.x < 0.5) fog -= rgb;\n"
       "  fog = floor(fog * (fog_blend + 1.0) / 256.0);  // arithmetic shift: floors negatives\n"
       "  if (u_fog_flags.x < 0.5) fog += rgb;\n"
       "  rgb = clamp(fog, 0.0, 255.0);\n";
  return s.str();
}

// The W code of 1/w as the hardware forms it (depth.cpp's w_code): leading zeros of the 16
// fraction bits, then the 12 bits after the leading one, inverted. Doubling is exact in float.
const char *kFogTableFunctions = R"(
float w_code(float oow) {
  if (oow >= 1.0) return 0.0;
  if (oow < 1.0 / 65536.0) return 65535.0;
  float m = oow;
  float zeros = 0.0;
  for (int i = 0; i < 16; ++i) {
    if (m < 0.5) { m *= 2.0; zeros += 1.0; }
  }
  float mantissa = floor(m * 8192.0) - 4096.0;
  return min(zeros * 4096.0 + (4095.0 - mantissa) + 1.0, 65535.0);
}
// Entry code >> 10 plus its delta times the next 8 bits of the code, >> 10 (Voodoo 1: no fog
// dither or zones; the delta is the 8-bit (next - this) << 2 that grFogTable loads).
float fog_table_blend() {
  float code = clamp(w_code(v_fog) + u_fog_bias, 0.0, 65535.0);
  vec2 entry = u_fog_table[int(floor(code / 1024.0))];
  return entry.x + floor(entry.y * mod(floor(code / 4.0), 256.0) / 1024.0);
}
)";

// The 4x4 dither matrix entry of this pixel (row from the top of the frame buffer), as `name`.
std::string dither_entry_code(const std::string &name) {
  return "  vec2 " + name + "_cell = mod(vec2(floor(gl_FragCoord.x), u_screen_height - 1.0 -"
         " floor(gl_FragCoord.y)), 4.0);\n"
         "  vec4 " + name + "_row = " + name + "_cell.y < 1.0 ? vec4(0.0, 8.0, 2.0, 10.0) : " +
         name + "_cell.y < 2.0 ? vec4(12.0, 4.0, 14.0, 6.0) : " + name +
         "_cell.y < 3.0 ? vec4(3.0, 11.0, 1.0, 9.0) : vec4(15.0, 7.0, 13.0, 5.0);\n"
         "  float " + name + " = " + name + "_cell.x < 1.0 ? " + name + "_row.x : " + name +
         "_cell.x < 2.0 ? " + name + "_row.y : " + name + "_cell.x < 3.0 ? " + name +
         "_row.z : " + name + "_row.w;\n";
}

// One filter at the chosen level: point (the texel under s,t) or Voodoo 1 bilinear.
std::string filter_code(bool bilinear, const char *address_s, const char *address_t,
                        bool plain) {
  std::ostringstream s;
  if (bilinear && plain) {
    // Fidelity knob `bilinear`: GL_LINEAR's weights (the whole fraction) and no rounding.
    s << "    vec2 uvb = uv - 0.5;\n"
         "    vec2 base = floor(uvb);\n"
         "    vec2 f = (uvb - base) * 16.0;\n"
      << "    float i0 = " << address_s << "(base.x, level.y), i1 = " << address_s
      << "(base.x + 1.0, level.y);\n"
      << "    float j0 = " << address_t << "(base.y, level.z), j1 = " << address_t
      << "(base.y + 1.0, level.z);\n"
         "    return (fetch(i0, j0, level) * (16.0 - f.x) * (16.0 - f.y) + fetch(i1, j0,"
         " level) * f.x * (16.0 - f.y) + fetch(i0, j1, level) * (16.0 - f.x) * f.y +"
         " fetch(i1, j1, level) * f.x * f.y) * (255.0 / 256.0);\n";
  } else if (bilinear) {
    s << "    vec2 uvb = uv - 0.5;\n"
         "    vec2 base = floor(uvb);\n"
         "    vec2 f = floor((uvb - base) * 16.0);  // Voodoo 1: 4-bit sub-texel fraction\n"
      << "    float i0 = " << address_s << "(base.x, level.y), i1 = " << address_s
      << "(base.x + 1.0, level.y);\n"
      << "    float j0 = " << address_t << "(base.y, level.z), j1 = " << address_t
      << "(base.y + 1.0, level.z);\n"
      << "    // Sum of the four integer products, recovered exactly by one rounding (the float\n"
         "    // error of k/255 * 255 summed over the taps stays far below 0.5), then >> 8.\n"
         "    vec4 sum = (fetch(i0, j0, level) * (16.0 - f.x) * (16.0 - f.y) + fetch(i1, j0,"
         " level) * f.x * (16.0 - f.y) + fetch(i0, j1, level) * (16.0 - f.x) * f.y +"
         " fetch(i1, j1, level) * f.x * f.y) * 255.0;\n"
         "    return floor(floor(sum + 0.5) / 256.0);\n";
  } else {
    s << "    return floor(fetch(" << address_s << "(floor(uv.x), level.y), " << address_t
      << "(floor(uv.y), level.z), level) * 255.0 + 0.5);\n";
  }
  return s.str();
}

// The TMU's fetch: the LOD (per pixel when mip-mapping, else lodmin), the level it selects, and
// the filter; the clamped LOD goes out for the LOD_FRACTION and DETAIL factors. The LOD follows
// the hardware: log2 of the larger screen-space gradient of the iterated (s/w, t/w) (constant
// over a triangle), minus log2 of the iterated 1/w, in 8.8 fixed point, plus the bias, plus the
// 4x4 dither / 16 when enabled, clamped to [lodmin, lodmax]; its integer part picks the level
// (the next one if the evenOdd mask left it out). Without mip-mapping lodmin == lodmax, so the
// LOD, the level and its scale are the same for every pixel and come in as uniforms.
std::string tmu_sample_code(const PipelineKey &key) {
  const bool plain_bilinear = (key.plain & kPlainBilinear) != 0;
  const char *address_s = key.wrap_s ? "wrap_index" : "clamp_index";
  const char *address_t = key.wrap_t ? "wrap_index" : "clamp_index";
  std::ostringstream s;
  s << "vec4 sample_tmu(out float lod) {\n"
       "  // Glide s,t span 0..256 along the longer side; a divisor <= 0 gives s = t = 0.\n"
       "  vec2 st = v_stq.z > 0.0 ? v_stq.xy / v_stq.z : vec2(0.0);\n";
  if (key.mipmap) {
    s << "  vec2 gx = dFdx(v_stq.xy), gy = dFdy(v_stq.xy);  // 256-texel units per pixel\n"
         "  lod = 0.5 * log2(max(max(dot(gx, gx), dot(gy, gy)), 1e-30)) -"
         " log2(max(abs(v_stq.z), 1e-30));\n"
         "  lod = floor(lod * 256.0) / 256.0 + u_lod_bias;\n";
    if (key.lod_dither) s << dither_entry_code("lod_d") << "  lod += lod_d / 16.0;\n";
    s << "  lod = clamp(lod, u_lod_range.x, u_lod_range.y);\n"
         "  float ilod = floor(lod);\n"
         "  if (u_tex_levels[int(ilod)].w < 0.5) ilod = min(ilod + 1.0, 8.0);\n"
         "  vec4 level = u_tex_levels[int(ilod)];\n"
         "  vec2 uv = st / exp2(ilod);  // texel units of the level\n";
  } else {
    s << "  lod = u_lod_range.x;\n"
         // The one level sampled is the first the atlas holds (lodmin, or the next one when
         // evenOdd left lodmin out), so its row is 0: a constant row saves an add per tap.
         "  vec4 level = vec4(0.0, u_level.yzw);\n"
         "  vec2 uv = st * u_level_scale;  // texel units of the level\n";
  }
  if (key.mag_bilinear == key.min_bilinear) {
    s << "  {\n" << filter_code(key.mag_bilinear, address_s, address_t, plain_bilinear) << "  }\n";
  } else {
    s << "  if (lod <= u_lod_range.x) {  // magnification\n"
      << filter_code(key.mag_bilinear, address_s, address_t, plain_bilinear) << "  } else {\n"
      << filter_code(key.min_bilinear, address_s, address_t, plain_bilinear) << "  }\n";
  }
  s << "}\n";
  return s.str();
}

// The TMU's LOD-dependent factors, from the clamped LOD (a multiple of 1/256), for the ones the
// texture combine reads. DETAIL as MAME's TMU: 0 from detail_bias down, else
// ((bias - LOD) << scale) >> 8 in 8.8, limited to detail_max.
std::string lod_factor_code(const PipelineKey &key) {
  auto reads = [&key](int source) {
    for (const UnitShape *unit : {&key.tmu_rgb, &key.tmu_alpha}) {
      if ((static_cast<int>(unit->factor) & 0x7) == source) return true;
    }
    return false;
  };
  std::string code;
  if (reads(GR_COMBINE_FACTOR_LOD_FRACTION)) {
    code += "  float lod_frac = floor((tex_lod - floor(tex_lod)) * 256.0);\n";
  }
  if (reads(GR_COMBINE_FACTOR_DETAIL_FACTOR)) {
    code += "  float detail = tex_lod >= u_detail.x ? 0.0 :"
            " min(floor((u_detail.x - tex_lod) * u_detail.y), u_detail.z);\n";
  }
  return code;
}

const char *kFragmentPrelude = R"(
uniform vec4 u_constant;    // constant colour, RGBA 0..255
uniform vec4 u_chroma;      // chroma-key colour, RGB 0..255 (a unused)
uniform float u_alpha_ref;  // alpha-test reference, 0..255
uniform vec4 u_color_select, u_color_other;  // local is constant, invert; other one-hot
uniform vec4 u_alpha_select, u_alpha_other;
uniform vec2 u_tmu_invert;                    // rgb, alpha
uniform sampler2D u_texture;
uniform vec2 u_tex_size;    // the atlas holding every level, in texels
uniform vec4 u_tex_levels[9];  // per GR_LOD: atlas row of the level's top, width, height, held
uniform vec2 u_lod_range;   // lodmin, lodmax as GR_LOD values (256 = 0 .. 1 = 8)
uniform float u_lod_bias;   // grTexLodBiasValue in quarters, as the tLOD register holds it
uniform vec4 u_level;       // without mip-mapping: u_tex_levels of the one level sampled
uniform float u_level_scale;  // and 1 / its size divisor, 2^-level
uniform vec3 u_detail;      // grTexDetailControl: bias (whole LODs), 2^scale, max (0..255)
uniform float u_screen_height;
varying vec4 v_color;       // iterated RGBA, 0..255, screen-linear like the hardware iterators
varying vec3 v_stq;         // sow, tow and their divisor, screen-linear
varying float v_fog;        // 1/w or ooz for fog, screen-linear like the hardware's iterators
uniform vec3 u_fog_color;   // RGB 0..255
uniform vec2 u_fog_flags;   // MULT2, ADD2 as 0/1
uniform vec2 u_fog_table[64];  // per entry: fog blend, and the hardware's delta byte
uniform float u_fog_bias;   // depth bias added to the W code (depth buffering on), code units

// A texel as GL returns it, k/255 for the TMU's widened 8-bit value k (the upload already
// holds the bit-replicated values); i, j are texel indices in `level`, already clamped or
// wrapped, and the level's rows start at level.x in the atlas.
float clamp_index(float i, float size) { return clamp(i, 0.0, size - 1.0); }
float wrap_index(float i, float size) { return mod(i, size); }

)";

// The texel fetch (see the prelude). texelFetch reads the same texel as the GL_NEAREST lookup
// at its centre, without the coordinate arithmetic.
std::string fetch_code(bool texel_fetch) {
  if (texel_fetch) {
    return "vec4 fetch(float i, float j, vec4 level) {\n"
           "  return texelFetch(u_texture, ivec2(int(i), int(j + level.x)), 0);\n"
           "}\n";
  }
  return "vec4 fetch(float i, float j, vec4 level) {\n"
         "  return texture2D(u_texture, (vec2(i, j + level.x) + 0.5) / u_tex_size);\n"
         "}\n";
}

// The fast paths' 565 write with the hardware's dither, in integers (GLSL 1.30). The matrix
// entry d from the pixel's column x and its row from the top y, low two bits only: y is
// height - 1 - row from the bottom, and (height - 1 - r) & 3 = (~r + (height & 3)) & 3, with
// height & 3 compiled in. The 4x4 matrix is the bit interleave 8 (x0 ^ y0) + 4 y0 + 2 (x1 ^ y1)
// + y1, the 2x2 one 2 + 8 (x0 ^ y0) + 4 y0: dither_entry_code's table without the selects. Then
// (c << 1) - (c >> 4) + (c >> 7) + d) >> 4 per channel (<< 2 and >> 6 for green), the exact
// path's floors on the integers 0..255 that rgb holds.
std::string fast_dither_code(GrDitherMode_t dither, int rows_mod4) {
  std::string s =
      "  ivec2 dither_p = ivec2(gl_FragCoord.xy);\n"
      "  int dither_y = ~dither_p.y";
  if (rows_mod4 != 0) s += " + " + std::to_string(rows_mod4);
  s += ";\n  int dither_a = dither_p.x ^ dither_y;\n";
  if (dither == GR_DITHER_2x2) {
    s += "  int d = 2 | ((dither_a & 1) << 3) | ((dither_y & 1) << 2);\n";
  } else {
    s += "  int d = ((dither_a & 1) << 3) | ((dither_y & 1) << 2) | (dither_a & 2) |"
         " ((dither_y >> 1) & 1);\n";
  }
  s += "  ivec3 c = ivec3(rgb);\n"
       "  vec3 q = vec3(((c << ivec3(1, 2, 1)) - (c >> 4) + (c >> ivec3(7, 6, 7)) + d) >> 4);\n";
  return s;
}

// The fast paths' compiled-in source of a combine unit's local and other (as unit_uniforms).
const char *fast_local(int local, bool rgb) {
  if (rgb) return local == 1 ? "u_constant.rgb" : "it.rgb";
  return local == 1 ? "u_constant.a" : "it.a";
}
const char *fast_other(int other, bool rgb) {
  if (rgb) return other == 1 ? "tex.rgb" : other == 2 ? "u_constant.rgb" : "it.rgb";
  return other == 1 ? "tex.a" : other == 2 ? "u_constant.a" : "it.a";
}

int other_index(GrCombineOther_t other) {  // as unit_uniforms: iterated 0, texture 1, constant 2
  return other == GR_COMBINE_OTHER_TEXTURE ? 1 : other == GR_COMBINE_OTHER_CONSTANT ? 2 : 0;
}

}  // namespace

int parse_fidelity_knobs(const char *list, std::string &unknown) {
  unknown.clear();
  if (list == nullptr) return 0;
  const std::string text = list;
  int knobs = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string name = text.substr(start, end - start);
    if (name == "write") knobs |= kPlainWrite;
    if (name == "iterators") knobs |= kPlainIterators;
    if (name == "combine") knobs |= kPlainCombine;
    if (name == "bilinear") knobs |= kPlainBilinear;
    if (name == "all") knobs |= kPlainWrite | kPlainIterators | kPlainCombine | kPlainBilinear;
    if (!name.empty() && name != "write" && name != "iterators" && name != "combine" && name != "bilinear" &&
        name != "all") {
      unknown += (unknown.empty() ? "'" : ", '") + name + "'";
    }
    start = end + 1;
  }
  return knobs;
}

UnitUniforms unit_uniforms(const CombineUnit &unit) {
  UnitUniforms u;
  u.select[0] = unit.local == GR_COMBINE_LOCAL_CONSTANT ? 1.0f : 0.0f;
  u.select[1] = unit.invert ? 1.0f : 0.0f;
  const int other = unit.other == GR_COMBINE_OTHER_TEXTURE    ? 1
                    : unit.other == GR_COMBINE_OTHER_CONSTANT ? 2
                                                              : 0;
  u.other[other] = 1.0f;
  return u;
}

bool reads_texture(const ColorPathState &path) {
  return path.color.other == GR_COMBINE_OTHER_TEXTURE ||
         path.alpha.other == GR_COMBINE_OTHER_TEXTURE || factor_reads_texture(path.color.factor) ||
         factor_reads_texture(path.alpha.factor);
}

PipelineKey pipeline_key(const GlideContext &context, bool fast) {
  PipelineKey key;
  const ColorPathState &path = context.color_path;
  key.color = shape(path.color.function, path.color.factor);
  key.alpha_controls_itrgb = path.alpha_controls_itrgb;
  key.alpha = shape(path.alpha.function, path.alpha.factor);
  key.texture = reads_texture(path);
  if (key.texture) {
    const TexCombineUnit &tmu = context.tmu.combine;
    key.tmu_rgb = shape(tmu.rgb_function, tmu.rgb_factor);
    key.tmu_alpha = shape(tmu.alpha_function, tmu.alpha_factor);
    // MAME's and 86Box's TMU: the magnification filter when the clamped LOD equals lodmin,
    // else the minification filter.
    const TmuState &unit = context.tmu;
    key.mag_bilinear = unit.mag_filter == GR_TEXTUREFILTER_BILINEAR;
    key.mipmap = unit.mipmap_mode != GR_MIPMAP_DISABLE && unit.source.valid &&
                 unit.source.small_lod != unit.source.large_lod;
    key.min_bilinear = key.mipmap ? unit.min_filter == GR_TEXTUREFILTER_BILINEAR : key.mag_bilinear;
    key.lod_dither = key.mipmap && unit.lod_dither;
    key.wrap_s = context.tmu.clamp_s == GR_TEXTURECLAMP_WRAP;
    key.wrap_t = context.tmu.clamp_t == GR_TEXTURECLAMP_WRAP;
  }
  key.chroma_key = context.chroma.mode == GR_CHROMAKEY_ENABLE;
  key.alpha_test = context.blend.alpha_test_function;
  key.blending = !(context.blend.rgb_src == GR_BLEND_ONE && context.blend.rgb_dst == GR_BLEND_ZERO);
  key.dither = context.raster.dither;
  key.fog = context.fog.mode & 0xFF;
  key.plain = context.fidelity_knobs;
  if (fast) {
    key.fast = key.sources = true;
    key.texel_fetch = key.texture && context.tmu.source.valid;
    const int height = context.texture_target.active ? context.texture_target.side
                                                     : context.display.height;
    key.rows_mod4 = key.dither != GR_DITHER_DISABLE ? height & 3 : 0;
    key.color_local = path.color.local == GR_COMBINE_LOCAL_CONSTANT ? 1 : 0;
    key.color_other = other_index(path.color.other);
    key.color_invert = path.color.invert;
    key.alpha_local = path.alpha.local == GR_COMBINE_LOCAL_CONSTANT ? 1 : 0;
    key.alpha_other = other_index(path.alpha.other);
    key.alpha_invert = path.alpha.invert;
    if (key.texture) {
      key.tmu_rgb_invert = context.tmu.combine.rgb_invert;
      key.tmu_alpha_invert = context.tmu.combine.alpha_invert;
    }
  }
  return key;
}

PipelineKey PipelineKey::without_sources() const {
  PipelineKey key = *this;
  key.sources = false;
  key.color_local = key.color_other = key.alpha_local = key.alpha_other = 0;
  key.color_invert = key.alpha_invert = key.tmu_rgb_invert = key.tmu_alpha_invert = false;
  return key;
}

std::string PipelineKey::defines() const {
  std::ostringstream s;
  for (const UnitShape *unit : {&color, &alpha, &tmu_rgb, &tmu_alpha}) {
    s << "unit " << unit->function << '/' << unit->factor << ' ';
  }
  s << "texture " << texture << " filter " << mag_bilinear << min_bilinear << " mipmap " << mipmap
    << lod_dither << " wrap " << wrap_s << wrap_t
    << " itrgb " << alpha_controls_itrgb << " chroma " << chroma_key << " alpha_test " << alpha_test << " blend " << blending
    << " dither " << dither << " fog " << fog;
  if (plain != 0) s << " plain " << plain;
  if (fast) s << " fast " << texel_fetch << rows_mod4;
  if (sources) {
    s << " sources " << color_local << color_other << color_invert
      << alpha_local << alpha_other << alpha_invert << tmu_rgb_invert << tmu_alpha_invert;
  }
  return s.str();
}

std::string vertex_shader_source() {
  return R"(#version 120
attribute vec2 a_position;  // screen pixels in the Glide origin
attribute float a_depth;    // GL window depth, 0..1
attribute vec4 a_color;     // 0..255
attribute vec3 a_stq;       // sow, tow, divisor
attribute float a_fog;      // fog iterator: 1/w (table fog) or ooz (iterated-Z fog)
uniform vec2 u_screen;      // width, height in pixels
uniform float u_y_down;     // 1 when the origin is the upper-left corner
varying vec4 v_color;
varying vec3 v_stq;
varying float v_fog;
void main() {
  vec2 ndc = a_position * 2.0 / u_screen - 1.0;
  if (u_y_down > 0.5) ndc.y = -ndc.y;
  gl_Position = vec4(ndc, a_depth * 2.0 - 1.0, 1.0);
  v_color = a_color;
  v_stq = a_stq;
  v_fog = a_fog;
}
)";
}

std::string fragment_shader_source(const PipelineKey &key) {
  std::ostringstream s;
  s << (key.fast ? "#version 130\n// " : "#version 120\n// ") << key.defines() << '\n'
    << kFragmentPrelude << fetch_code(key.texel_fetch);

  if (key.texture) s << tmu_sample_code(key);
  const bool plain_combine = (key.plain & kPlainCombine) != 0;

  if (key.fog == GR_FOG_WITH_TABLE) s << kFogTableFunctions;

  s << "void main() {\n"
       << ((key.plain & kPlainIterators) != 0
               ? "  vec4 it = v_color;  // fidelity knob `iterators`: GL's interpolation\n"
               : "  vec4 it = clamp(floor(v_color + 1.0 / 1024.0), 0.0, 255.0);  // iterators truncate\n");
  if (key.texture) {
    s << "  float tex_lod;\n"
         "  vec4 texel = sample_tmu(tex_lod);\n"
      << lod_factor_code(key)
      << combine_code("tmu_rgb", key.tmu_rgb, true, false, "texel.rgb", "vec3(0.0)", "texel.a",
                      "0.0", !key.sources ? "u_tmu_invert.x" : key.tmu_rgb_invert ? "!" : "", plain_combine)
      << combine_code("tmu_a", key.tmu_alpha, false, false, "texel.a", "0.0", "texel.a", "0.0",
                      !key.sources ? "u_tmu_invert.y" : key.tmu_alpha_invert ? "!" : "", plain_combine)
      << "  vec4 tex = vec4(tmu_rgb, tmu_a);\n";
  } else {
    s << "  vec4 tex = vec4(0.0);\n";
  }
  if (key.alpha_controls_itrgb) {  // grAlphaControlsITRGBLighting: texture alpha bit 7
    s << "  vec3 c_local = tex.a >= 128.0 ? u_constant.rgb : it.rgb;\n";
  } else if (key.sources) {
    s << "  vec3 c_local = " << fast_local(key.color_local, true) << ";\n";
  } else {
    s << "  vec3 c_local = mix(it.rgb, u_constant.rgb, u_color_select.x);\n";
  }
  if (key.sources) {
    s << "  vec3 c_other = " << fast_other(key.color_other, true) << ";\n"
      << "  float a_local = " << fast_local(key.alpha_local, false) << ";\n"
      << "  float a_other = " << fast_other(key.alpha_other, false) << ";\n";
  } else {
    s << "  vec3 c_other = u_color_other.x * it.rgb + u_color_other.y * tex.rgb +"
         " u_color_other.z * u_constant.rgb;\n"
         "  float a_local = mix(it.a, u_constant.a, u_alpha_select.x);\n"
         "  float a_other = u_alpha_other.x * it.a + u_alpha_other.y * tex.a +"
         " u_alpha_other.z * u_constant.a;\n";
  }
  if (key.chroma_key) {
    s << "  if (all(equal(c_other, u_chroma.rgb))) discard;  // exact match on 'other'\n";
  }
  s << combine_code("rgb", key.color, true, true, "c_local", "c_other", "a_local", "a_other",
                    !key.sources ? "u_color_select.y" : key.color_invert ? "!" : "", plain_combine);
  // The alpha combine's result reaches the pixel only through the alpha test and blending: a
  // 565 buffer has no alpha planes. The fast paths leave it out when neither is on.
  const bool alpha_seen = !key.fast || key.blending || key.alpha_test != GR_CMP_ALWAYS;
  if (alpha_seen) {
    s << combine_code("alpha", key.alpha, false, true, "a_local", "a_other", "a_local", "a_other",
                      !key.sources ? "u_alpha_select.y" : key.alpha_invert ? "!" : "", plain_combine);
  } else {
    s << "  float alpha = 255.0;  // not observable: no alpha test, no blending\n";
  }

  if (key.alpha_test == GR_CMP_NEVER) {
    s << "  discard;\n";
  } else if (const char *op = glsl_compare(key.alpha_test)) {
    s << "  if (!(alpha " << op << " u_alpha_ref)) discard;\n";
  }

  s << fog_code(key.fog);

  if (key.blending || (key.plain & kPlainWrite) != 0) {
    // GL blends the 8-bit colour; its rounding may differ from the Voodoo's by one 565 step.
    // (Fidelity knob `write`: GL's rounding to 565 instead of the truncation or dither.)
    s << "  gl_FragColor = vec4(rgb, alpha) / 255.0;\n";
  } else {
    if (key.dither == GR_DITHER_DISABLE) {
      s << "  vec3 q = floor(rgb / vec3(8.0, 4.0, 8.0));  // dither off: plain truncation\n";
    } else if (key.fast) {
      s << fast_dither_code(key.dither, key.rows_mod4);
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
