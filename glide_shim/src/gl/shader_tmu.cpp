// The TMU as GLSL: the texel fetch, point or Voodoo 1 bilinear filtering with clamp or wrap
// addressing, the LOD (per pixel when mip-mapping, with the optional 4x4 LOD dither), and the
// LOD_FRACTION and DETAIL factors the texture combine reads.
#include "gl/shader_stages.h"

#include <iomanip>
#include <sstream>

namespace glide_shim {
namespace shader_stages {
namespace {

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
      << "    // Sum of the four integer products k * w, each tap's k/255 times its integer weight\n"
         "    // w * 255: the float error summed over the taps stays below 0.05, so adding one\n"
         "    // half and flooring the quotient by 256 gives (sum k * w) >> 8 exactly.\n"
         "    vec2 g = 16.0 - f;\n"
         "    vec4 sum = fetch(i0, j0, level) * (g.x * g.y * 255.0) + fetch(i1, j0, level) *"
         " (f.x * g.y * 255.0) + fetch(i0, j1, level) * (g.x * f.y * 255.0) + fetch(i1, j1,"
         " level) * (f.x * f.y * 255.0);\n"
         "    return floor((sum + 0.5) / 256.0);\n";
  } else {
    s << "    return floor(fetch(" << address_s << "(floor(uv.x), level.y), " << address_t
      << "(floor(uv.y), level.z), level) * 255.0 + 0.5);\n";
  }
  return s.str();
}

}  // namespace

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
  } else if (key.level_compiled) {
    // The same values as the uniforms below, compiled in: whole numbers, and a power of two
    // written exactly (at most 9 significant digits).
    s << "  lod = " << key.lod_min << ".0;\n"
      << "  vec4 level = vec4(0.0, " << key.level_width << ".0, " << key.level_height
      << ".0, 1.0);  // row 0 as below\n"
      << "  vec2 uv = st * " << std::setprecision(9) << std::fixed
      << 1.0 / static_cast<double>(1 << key.level_lod) << ";  // texel units of the level\n";
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

// The texel fetch (see shader_source.cpp's prelude). texelFetch reads the same texel as the
// GL_NEAREST lookup at its centre, without the coordinate arithmetic.
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

}  // namespace shader_stages
}  // namespace glide_shim
