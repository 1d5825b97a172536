// GLSL generation: the vertex shader, and the fragment shader for a PipelineKey, written in
// the Voodoo's order (iterators, TMU, colour and alpha combine, chroma key, alpha test, fog, then
// blending or the 565 write with truncation or dither) from the stages of shader_stages.h.
#include "gl/shader_source.h"
#include "gl/shader_stages.h"

#include <sstream>

namespace glide_shim {
namespace {

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
varying float v_row;        // rows from the target's top, row + 0.5 at a pixel centre
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

// The fast paths' colour that reaches the 565 write is the iterated colour itself (the SDK's
// Gouraud state: colour combine LOCAL of the iterated RGB, nothing after it changes it). Its
// integer conversion can then truncate it_clamped (0..255), which is the same as flooring it.
bool rgb_is_iterated(const PipelineKey &key) {
  return key.sources && (key.plain & kPlainIterators) == 0 &&
         key.color.function == GR_COMBINE_FUNCTION_LOCAL && key.color_local == 0 &&
         !key.color_invert && !key.alpha_controls_itrgb && key.fog == GR_FOG_DISABLE;
}

}  // namespace

using namespace shader_stages;

// The vertex shader, in the fragment shader's GLSL version (1.30 for the fast programs).
std::string vertex_shader_source(bool fast) {
  std::string s = fast ? "#version 130\n" : "#version 120\n";
  s += R"(attribute vec2 a_position;  // screen pixels in the Glide origin
attribute float a_depth;    // GL window depth, 0..1
attribute vec4 a_color;     // 0..255
attribute vec3 a_stq;       // sow, tow, divisor
attribute float a_fog;      // fog iterator: 1/w (table fog) or ooz (iterated-Z fog)
uniform vec2 u_screen;      // width, height in pixels
uniform float u_y_down;     // 1 when the origin is the upper-left corner
varying vec4 v_color;
varying vec3 v_stq;
varying float v_fog;
varying float v_row;  // rows from the target's top, row + 0.5 at a pixel centre (fast dither)
void main() {
  vec2 ndc = a_position * 2.0 / u_screen - 1.0;
  if (u_y_down > 0.5) ndc.y = -ndc.y;
  gl_Position = vec4(ndc, a_depth * 2.0 - 1.0, 1.0);
  // Exact: a snapped y (a multiple of 1/16, |y| <= 32768) and height - y are floats.
  v_row = u_y_down > 0.5 ? a_position.y : u_screen.y - a_position.y;
  v_color = a_color;
  v_stq = a_stq;
  v_fog = a_fog;
}
)";
  return s;
}

std::string fragment_shader_source(const PipelineKey &key) {
  std::ostringstream s;
  s << (key.fast ? "#version 130\n// " : "#version 120\n// ") << key.defines() << '\n'
    << kFragmentPrelude << fetch_code(key.texel_fetch);

  if (key.texture) s << tmu_sample_code(key);
  const bool plain_combine = (key.plain & kPlainCombine) != 0;

  if (key.fog == GR_FOG_WITH_TABLE) s << kFogTableFunctions;

  s << "void main() {\n";
  if ((key.plain & kPlainIterators) != 0) {
    s << "  vec4 it = v_color;  // fidelity knob `iterators`: GL's interpolation\n";
  } else if (key.fast) {
    // The same values as the exact path's clamp(floor(x)), which the clamp passes through
    // unchanged, NaN included; the unfloored copy lets an integer conversion do the floor.
    s << "  vec4 it_clamped = clamp(v_color + 1.0 / 1024.0, 0.0, 255.0);\n"
         "  vec4 it = floor(it_clamped);  // iterators truncate\n";
  } else {
    s << "  vec4 it = clamp(floor(v_color + 1.0 / 1024.0), 0.0, 255.0);  // iterators truncate\n";
  }
  if (key.texture) {
    s << "  float tex_lod;\n"
         "  vec4 texel = sample_tmu(tex_lod);\n"
      << lod_factor_code(key)
      << combine_code("tmu_rgb", key.tmu_rgb, true, false, "texel.rgb", "vec3(0.0)", "texel.a",
                      "0.0", !key.sources ? "u_tmu_invert.x" : key.tmu_rgb_invert ? "!" : "",
                      plain_combine, key.fast)
      << combine_code("tmu_a", key.tmu_alpha, false, false, "texel.a", "0.0", "texel.a", "0.0",
                      !key.sources ? "u_tmu_invert.y" : key.tmu_alpha_invert ? "!" : "",
                      plain_combine, key.fast)
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
                    !key.sources ? "u_color_select.y" : key.color_invert ? "!" : "", plain_combine,
                    key.fast);
  // The alpha combine's result reaches the pixel only through the alpha test and blending: a
  // 565 buffer has no alpha planes. The fast paths leave it out when neither is on.
  const bool alpha_seen = !key.fast || key.blending || key.alpha_test != GR_CMP_ALWAYS;
  if (alpha_seen) {
    s << combine_code("alpha", key.alpha, false, true, "a_local", "a_other", "a_local", "a_other",
                      !key.sources ? "u_alpha_select.y" : key.alpha_invert ? "!" : "",
                      plain_combine, key.fast);
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
      s << fast_dither_code(key.dither, rgb_is_iterated(key) ? "it_clamped.rgb" : "rgb",
                            key.line_rows, key.rows_mod4);
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
    // q / 31 (or 63) to within an ulp gives q back from any float-to-565 conversion (and
    // from llvmpipe's, which rounds to 8 bits and truncates that, as round(8.23 q) >> 3 = q).
    // The fast paths multiply by the reciprocal: llvmpipe divides as written, a vdivps per
    // channel that costs several times a multiply.
    s << (key.fast ? "  gl_FragColor = vec4(q * vec3(1.0 / 31.0, 1.0 / 63.0, 1.0 / 31.0)"
                   : "  gl_FragColor = vec4(q / vec3(31.0, 63.0, 31.0)")
      << ", alpha / 255.0);  // exact 565\n";
  }
  s << "}\n";
  return s.str();
}

}  // namespace glide_shim
