// The combine units as GLSL: each written out as straight-line arithmetic for its function and
// factor, in integer-valued floats (0..255) so (f+1)>>8 is exact; its sources and invert flag are
// 0/1 uniforms, or compiled in by the fast paths (fast_local, fast_other).
#include "gl/shader_stages.h"

#include <sstream>

namespace glide_shim {
namespace shader_stages {
namespace {

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

}  // namespace

bool has_product(GrCombineFunction_t function) {
  return function != GR_COMBINE_FUNCTION_ZERO && function != GR_COMBINE_FUNCTION_LOCAL &&
         function != GR_COMBINE_FUNCTION_LOCAL_ALPHA;
}

// One combine unit, straight-line: clamp(((other or 0) - (local or 0)) * (f + 1) >> 8 + add),
// then inverted when the `invert` uniform expression is 1. The fast paths compile the invert in:
// `invert` is then "" (none) or "!" (always).
std::string combine_code(const std::string &result, const UnitShape &unit, bool rgb, bool fbi,
                         const std::string &local, const std::string &other,
                         const std::string &local_alpha, const std::string &other_alpha,
                         const std::string &invert, bool plain, bool fast) {
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
  } else if (has_product(unit.function) && fast && unit.factor == GR_COMBINE_FACTOR_ZERO &&
             subtrahend == zero) {
    // floor(other * 1 / 256) is 0 for every source value 0..255: only the added term is left
    // (and the sources of the product need not be computed, e.g. a texture's colour).
    s << "clamp(" << add << ", 0.0, 255.0);  // factor ZERO: the product is 0\n";
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

// The fast paths' compiled-in source of a combine unit's local and other (as unit_uniforms).
const char *fast_local(int local, bool rgb) {
  if (rgb) return local == 1 ? "u_constant.rgb" : "it.rgb";
  return local == 1 ? "u_constant.a" : "it.a";
}
const char *fast_other(int other, bool rgb) {
  if (rgb) return other == 1 ? "tex.rgb" : other == 2 ? "u_constant.rgb" : "it.rgb";
  return other == 1 ? "tex.a" : other == 2 ? "u_constant.a" : "it.a";
}

}  // namespace shader_stages
}  // namespace glide_shim
