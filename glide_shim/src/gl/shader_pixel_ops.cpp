// The pixel operations after the combine units, as GLSL: the alpha test's comparison, the fog
// unit (table, iterated alpha or iterated Z) with the W code and table lookup it needs, and the
// fast paths' dithered 565 write in integer arithmetic.
#include "gl/shader_stages.h"

#include <sstream>

namespace glide_shim {
namespace shader_stages {

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

// The fast paths' 565 write with the hardware's dither, in integers (GLSL 1.30). The matrix
// entry d from the pixel's column x and its row from the top y, low two bits only. y comes from
// the vertex shader's v_row, the row from the target's top plus 0.5 at a pixel centre (its
// interpolation error, far below 0.5 for coordinates up to 32768, cannot move it to another
// row): gl_FragCoord.y costs llvmpipe's origin transform, a per-pixel gather of a uniform, about
// a fifth of a Gouraud pixel's instructions. Lines (line_rows) keep gl_FragCoord.y: a line's
// v_row is its own y, flat across it (tests/image/fast_paths_test.cpp, DitheredPrimitives).
// The 4x4 matrix is the bit interleave 8 (x0 ^ y0) + 4 y0 + 2 (x1 ^ y1) + y1, the 2x2 one
// 2 + 8 (x0 ^ y0) + 4 y0: dither_entry_code's table without the selects. Then
// (c << 1) - (c >> 4) + (c >> 7) + d) >> 4 per channel (<< 2 and >> 6 for green), the exact
// path's floors on the integers 0..255 that rgb holds (or on the clamped, unfloored iterated
// colour, whose truncation is its floor).
std::string fast_dither_code(GrDitherMode_t dither, const char *rgb, bool line_rows,
                             int rows_mod4) {
  std::string s;
  if (line_rows) {  // (height - 1 - r) & 3 = (~r + (height & 3)) & 3, r the row from the bottom
    s = "  ivec2 dither_p = ivec2(gl_FragCoord.x, ~int(gl_FragCoord.y) + " +
        std::to_string(rows_mod4) + ");\n";
  } else {
    s = "  ivec2 dither_p = ivec2(gl_FragCoord.x, v_row);\n";
  }
  s += "  int dither_a = dither_p.x ^ dither_p.y;\n";
  if (dither == GR_DITHER_2x2) {
    s += "  int d = 2 | ((dither_a & 1) << 3) | ((dither_p.y & 1) << 2);\n";
  } else {
    s += "  int d = ((dither_a & 1) << 3) | ((dither_p.y & 1) << 2) | (dither_a & 2) |"
         " ((dither_p.y >> 1) & 1);\n";
  }
  s += std::string("  ivec3 c = ivec3(") + rgb + ");\n"
       "  vec3 q = vec3(((c << ivec3(1, 2, 1)) - (c >> 4) + (c >> ivec3(7, 6, 7)) + d) >> 4);\n";
  return s;
}

}  // namespace shader_stages
}  // namespace glide_shim
