// The stages of the generated fragment shader as GLSL text, which shader_source.cpp puts
// together in the Voodoo's order: the TMU (shader_tmu.cpp), the combine units
// (shader_combine.cpp), and the alpha test, fog and fast-path dither after them
// (shader_pixel_ops.cpp).
#pragma once

#include "gl/shader_source.h"

#include <string>

namespace glide_shim {
namespace shader_stages {

// The TMU: its sampling function, the LOD-dependent factors, the texel fetch.
std::string tmu_sample_code(const PipelineKey &key);
std::string lod_factor_code(const PipelineKey &key);
std::string fetch_code(bool texel_fetch);

// The combine units; has_product: the function multiplies by its factor. `fast` (the fast
// paths) leaves out a product that is always 0: (other * (0 + 1)) >> 8 with factor ZERO and
// nothing subtracted, since every source is 0..255.
bool has_product(GrCombineFunction_t function);
std::string combine_code(const std::string &result, const UnitShape &unit, bool rgb, bool fbi,
                         const std::string &local, const std::string &other,
                         const std::string &local_alpha, const std::string &other_alpha,
                         const std::string &invert, bool plain = false, bool fast = false);
const char *fast_local(int local, bool rgb);
const char *fast_other(int other, bool rgb);

// After the combine units: the alpha test's operator, the fog unit and its table lookup, and
// the fast paths' dithered 565 write.
const char *glsl_compare(GrCmpFnc_t function);
std::string fog_code(GrFogMode_t source);
extern const char *kFogTableFunctions;
// `rgb` names the combined colour (0..255; an integer conversion truncates it); line_rows: the
// row from gl_FragCoord.y (rows_mod4: the target's height & 3), not from v_row.
std::string fast_dither_code(GrDitherMode_t dither, const char *rgb, bool line_rows,
                             int rows_mod4);

}  // namespace shader_stages
}  // namespace glide_shim
