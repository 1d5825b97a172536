// Voodoo 1 reference arithmetic (see voodoo_reference.h). Integer formulas follow MAME's
// voodoo_render.cpp register semantics as Glide 2.x programs them (gglide.c / gtex.c), 86Box's
// 4-bit bilinear weights and SST-1 Glide's gamma.c; every value is an 8-bit channel (0..255)
// unless a comment says otherwise.
#include "voodoo_reference.h"

#include <glide.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>

namespace voodoo_ref {
namespace {

[[noreturn]] void throw_bad_enum(const char* what, int value) {
  throw std::invalid_argument(std::string("voodoo_ref: unsupported ") + what + " " +
                              std::to_string(value));
}

int clamp8(int v) { return std::clamp(v, 0, 255); }

// x >> 8 rounded towards -infinity. The combine products are signed (other - local can be
// negative) and the hardware shifts them as two's complement; C++17 leaves >> of a negative
// value implementation-defined, so the floor is spelled out.
int floor_shift8(int x) { return x >= 0 ? x >> 8 : -((-x + 255) >> 8); }

// x / n (n > 0) rounded towards -infinity: the tap index of a sub-texel coordinate.
int floor_div(int x, int n) { return x >= 0 ? x / n : -((-x + n - 1) / n); }

// What a GR_COMBINE_FUNCTION_* sets in the combine unit (gglide.c / gtex.c switch statements):
// zero the 'other' input, subtract 'local', and which value is added after the multiply.
enum class Add { kNothing, kLocal, kLocalAlpha };
struct FunctionBits {
  bool zero_other;
  bool sub_local;
  Add add;
};

FunctionBits function_bits(int function) {
  switch (function) {
    case GR_COMBINE_FUNCTION_ZERO: return {true, false, Add::kNothing};
    case GR_COMBINE_FUNCTION_LOCAL: return {true, false, Add::kLocal};
    case GR_COMBINE_FUNCTION_LOCAL_ALPHA: return {true, false, Add::kLocalAlpha};
    case GR_COMBINE_FUNCTION_SCALE_OTHER: return {false, false, Add::kNothing};
    case GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL: return {false, false, Add::kLocal};
    case GR_COMBINE_FUNCTION_SCALE_OTHER_ADD_LOCAL_ALPHA: return {false, false, Add::kLocalAlpha};
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL: return {false, true, Add::kNothing};
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL: return {false, true, Add::kLocal};
    case GR_COMBINE_FUNCTION_SCALE_OTHER_MINUS_LOCAL_ADD_LOCAL_ALPHA:
      return {false, true, Add::kLocalAlpha};
    case GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL: return {true, true, Add::kLocal};
    case GR_COMBINE_FUNCTION_SCALE_MINUS_LOCAL_ADD_LOCAL_ALPHA:
      return {true, true, Add::kLocalAlpha};
    default: throw_bad_enum("combine function", function);
  }
}

// Factor source 4 is the TMU output alpha in the FBI but DETAIL in a TMU, and 5 is LOD_FRACTION
// in a TMU (TEXTURE_RGB exists only on Voodoo 2 FBIs).
enum class Unit { kFbi, kTmu };

// Resolved factor f in 0..255. `local` is this channel's local value (a_local in an alpha unit);
// `texture_alpha` is the TMU output's alpha in the FBI and the detail factor in a TMU.
int resolve_factor(int factor, Unit unit, int local, int other_alpha, int local_alpha,
                   int texture_alpha, int lod_fraction = 0) {
  const bool one_minus = (factor & 0x8) != 0;
  int source = 0;
  switch (factor & ~0x8) {
    case GR_COMBINE_FACTOR_ZERO: source = 0; break;
    case GR_COMBINE_FACTOR_LOCAL: source = local; break;
    case GR_COMBINE_FACTOR_OTHER_ALPHA: source = other_alpha; break;
    case GR_COMBINE_FACTOR_LOCAL_ALPHA: source = local_alpha; break;
    case GR_COMBINE_FACTOR_TEXTURE_ALPHA: source = texture_alpha; break;
    case GR_COMBINE_FACTOR_LOD_FRACTION:
      if (unit != Unit::kTmu) throw_bad_enum("FBI combine factor", factor);
      source = lod_fraction;
      break;
    default: throw_bad_enum("combine factor", factor);
  }
  return one_minus ? 255 - source : source;
}

Rgba rgb_of(const Rgba& c, int alpha) { return {c.r, c.g, c.b, alpha}; }

Rgba select_other_rgb(int other, const CombineInputs& in) {
  switch (other) {
    case GR_COMBINE_OTHER_ITERATED: return in.iterated;
    case GR_COMBINE_OTHER_TEXTURE: return in.texture;
    case GR_COMBINE_OTHER_CONSTANT: return in.constant;
    default: throw_bad_enum("combine other", other);
  }
}

int select_local_alpha(int local, const CombineInputs& in) {
  switch (local) {
    case GR_COMBINE_LOCAL_ITERATED: return in.iterated.a;
    case GR_COMBINE_LOCAL_CONSTANT: return in.constant.a;
    case GR_COMBINE_LOCAL_DEPTH: return in.depth_alpha;
    default: throw_bad_enum("alpha combine local", local);
  }
}

Rgba select_local_rgb(int local, const CombineInputs& in) {
  switch (local) {
    case GR_COMBINE_LOCAL_ITERATED: return in.iterated;
    case GR_COMBINE_LOCAL_CONSTANT: return in.constant;
    default: throw_bad_enum("colour combine local", local);
  }
}

int expand5(int v) { return (v << 3) | (v >> 2); }
int expand6(int v) { return (v << 2) | (v >> 4); }
int expand4(int v) { return v * 0x11; }
int expand3(int v) { return (v << 5) | (v << 2) | (v >> 1); }
int expand2(int v) { return v * 0x55; }

// 3-3-2 RGB in the low byte of an RGB_332 or ARGB_8332 texel.
Rgba decode_332(int byte, int alpha) {
  return {expand3((byte >> 5) & 7), expand3((byte >> 2) & 7), expand2(byte & 3), alpha};
}

int tap_index(int i, int size, int clamp_mode) {
  switch (clamp_mode) {
    case GR_TEXTURECLAMP_CLAMP: return std::clamp(i, 0, size - 1);
    case GR_TEXTURECLAMP_WRAP: return ((i % size) + size) % size;
    default: throw_bad_enum("texture clamp mode", clamp_mode);
  }
}

Rgba fetch_texel(const Texture& tex, int x, int y) {
  return decode_texel(tex.format, tex.texels[static_cast<std::size_t>(y) * tex.width + x]);
}

void check_texture(const Texture& tex) {
  const bool size_ok = tex.width > 0 && tex.height > 0 &&
                       tex.texels.size() == static_cast<std::size_t>(tex.width) * tex.height;
  if (!size_ok) throw std::invalid_argument("voodoo_ref: texel count does not match the size");
}

// Per-channel factor of the alpha blender, 0..256. `source_side` tells the source factor (where
// 2/6/0xF mean DST_COLOR / ONE_MINUS_DST_COLOR / ALPHA_SATURATE) from the destination factor
// (SRC_COLOR / ONE_MINUS_SRC_COLOR / PREFOG_COLOR).
int blend_factor(int factor, bool source_side, int sa, int da, int src_c, int dst_c) {
  switch (factor) {
    case GR_BLEND_ZERO: return 0;
    case GR_BLEND_SRC_ALPHA: return sa + 1;
    case GR_BLEND_SRC_COLOR: return (source_side ? dst_c : src_c) + 1;
    case GR_BLEND_DST_ALPHA: return da + 1;
    case GR_BLEND_ONE: return 256;
    case GR_BLEND_ONE_MINUS_SRC_ALPHA: return 256 - sa;
    case GR_BLEND_ONE_MINUS_SRC_COLOR: return 256 - (source_side ? dst_c : src_c);
    case GR_BLEND_ONE_MINUS_DST_ALPHA: return 256 - da;
    case GR_BLEND_ALPHA_SATURATE: return source_side ? std::min(sa, 256 - da) + 1 : src_c + 1;
    default: throw_bad_enum("blend factor", factor);
  }
}

int blend_channel(int src_c, int dst_c, int src_factor, int dst_factor, int sa, int da) {
  const int fs = blend_factor(src_factor, true, sa, da, src_c, dst_c);
  const int fd = blend_factor(dst_factor, false, sa, da, src_c, dst_c);
  return clamp8((src_c * fs + dst_c * fd) >> 8);
}

// W code before the final clamp: e = 15 with mantissa 0 gives 0x10000, which MAME keeps until
// the bias is added.
int w_code_unclamped(double oow) {
  if (!(oow < 1.0) || oow < 0.0) return 0;
  // oow in [0, 1) as the .32 fixed-point fraction of the iterator; scaling by 2^32 is exact.
  const auto frac = static_cast<std::uint32_t>(std::floor(oow * 4294967296.0));
  if ((frac >> 16) == 0) return 0xFFFF;
  int e = 0;
  while ((frac & (0x80000000u >> e)) == 0) ++e;
  const int mantissa = static_cast<int>((frac >> (19 - e)) & 0xFFF);
  return (e << 12) + (~mantissa & 0xFFF) + 1;
}

}  // namespace

bool operator==(const Rgba& x, const Rgba& y) {
  return x.r == y.r && x.g == y.g && x.b == y.b && x.a == y.a;
}

bool operator!=(const Rgba& x, const Rgba& y) { return !(x == y); }

std::ostream& operator<<(std::ostream& os, const Rgba& c) {
  return os << "{r=" << c.r << " g=" << c.g << " b=" << c.b << " a=" << c.a << "}";
}

int combine_channel(int function, int f, bool invert, int other, int local, int local_alpha) {
  const FunctionBits bits = function_bits(function);
  const int blend = (bits.zero_other ? 0 : other) - (bits.sub_local ? local : 0);  // -255..255
  int add = 0;
  if (bits.add == Add::kLocal) add = local;
  if (bits.add == Add::kLocalAlpha) add = local_alpha;
  const int out = clamp8(floor_shift8(blend * (f + 1)) + add);
  return invert ? 255 - out : out;
}

Rgba combine_other(const CombineConfig& color, const CombineConfig& alpha,
                   const CombineInputs& in) {
  return rgb_of(select_other_rgb(color.other, in), select_other_rgb(alpha.other, in).a);
}

Rgba combine_local(const CombineConfig& color, const CombineConfig& alpha,
                   const CombineInputs& in) {
  const int a_local = select_local_alpha(alpha.local, in);
  if (in.alpha_controls_itrgb) {
    return rgb_of((in.texture.a & 0x80) != 0 ? in.constant : in.iterated, a_local);
  }
  return rgb_of(select_local_rgb(color.local, in), a_local);
}

Rgba combine_fbi(const CombineConfig& color, const CombineConfig& alpha, const CombineInputs& in) {
  const Rgba other = combine_other(color, alpha, in);
  const Rgba local = combine_local(color, alpha, in);
  const int tex_a = in.texture.a;
  auto rgb = [&](int o, int l) {
    const int f = resolve_factor(color.factor, Unit::kFbi, l, other.a, local.a, tex_a);
    return combine_channel(color.function, f, color.invert, o, l, local.a);
  };
  const int fa = resolve_factor(alpha.factor, Unit::kFbi, local.a, other.a, local.a, tex_a);
  return {rgb(other.r, local.r), rgb(other.g, local.g), rgb(other.b, local.b),
          combine_channel(alpha.function, fa, alpha.invert, other.a, local.a, local.a)};
}

Rgba combine_tmu(const TexCombineConfig& config, const Rgba& texel, const Rgba& upstream,
                 int detail, int lod_fraction) {
  auto rgb = [&](int o, int l) {
    const int f = resolve_factor(config.rgb_factor, Unit::kTmu, l, upstream.a, texel.a, detail,
                                 lod_fraction);
    return combine_channel(config.rgb_function, f, config.rgb_invert, o, l, texel.a);
  };
  const int fa = resolve_factor(config.alpha_factor, Unit::kTmu, texel.a, upstream.a, texel.a,
                                detail, lod_fraction);
  return {rgb(upstream.r, texel.r), rgb(upstream.g, texel.g), rgb(upstream.b, texel.b),
          combine_channel(config.alpha_function, fa, config.alpha_invert, upstream.a, texel.a,
                          texel.a)};
}

Rgba decode_texel(int format, std::uint16_t raw) {
  const int lo = raw & 0xFF;
  const int hi = raw >> 8;
  switch (format) {
    case GR_TEXFMT_RGB_565:
      return {expand5(raw >> 11), expand6((raw >> 5) & 0x3F), expand5(raw & 0x1F), 255};
    case GR_TEXFMT_ARGB_1555:
      return {expand5((raw >> 10) & 0x1F), expand5((raw >> 5) & 0x1F), expand5(raw & 0x1F),
              (raw & 0x8000) != 0 ? 255 : 0};
    case GR_TEXFMT_ARGB_4444:
      return {expand4((raw >> 8) & 0xF), expand4((raw >> 4) & 0xF), expand4(raw & 0xF),
              expand4(raw >> 12)};
    case GR_TEXFMT_ARGB_8332: return decode_332(lo, hi);
    case GR_TEXFMT_RGB_332: return decode_332(lo, 255);
    case GR_TEXFMT_ALPHA_8: return {lo, lo, lo, lo};
    case GR_TEXFMT_INTENSITY_8: return {lo, lo, lo, 255};
    case GR_TEXFMT_ALPHA_INTENSITY_44: {
      const int i = expand4(lo & 0xF);
      return {i, i, i, expand4(lo >> 4)};
    }
    case GR_TEXFMT_ALPHA_INTENSITY_88: return {lo, lo, lo, hi};
    default: throw_bad_enum("texture format", format);
  }
}

TexelCoord glide_st_to_texel(double s, double t, int width, int height) {
  const double scale = std::max(width, height) / 256.0;
  return {s * scale, t * scale};
}

Rgba sample_texture(const Texture& tex, TexelCoord coord, int filter, int clamp_s, int clamp_t) {
  check_texture(tex);
  if (filter == GR_TEXTUREFILTER_POINT_SAMPLED) {
    const int x = tap_index(static_cast<int>(std::floor(coord.u)), tex.width, clamp_s);
    const int y = tap_index(static_cast<int>(std::floor(coord.v)), tex.height, clamp_t);
    return fetch_texel(tex, x, y);
  }
  if (filter != GR_TEXTUREFILTER_BILINEAR) throw_bad_enum("texture filter", filter);

  // Coordinates in 1/16 texel, shifted by half a texel so that 0.5 lands on texel 0's centre;
  // floor(16u) - 8 equals floor(16 (u - 0.5)) and stays exact in double.
  constexpr int kSteps = 1 << kBilinearFractionBits;
  const int qs = static_cast<int>(std::floor(coord.u * kSteps)) - kSteps / 2;
  const int qt = static_cast<int>(std::floor(coord.v * kSteps)) - kSteps / 2;
  const int s0 = floor_div(qs, kSteps);
  const int t0 = floor_div(qt, kSteps);
  const int fs = qs - s0 * kSteps;  // 0..kSteps-1
  const int ft = qt - t0 * kSteps;  // 0..kSteps-1
  const int x0 = tap_index(s0, tex.width, clamp_s);
  const int x1 = tap_index(s0 + 1, tex.width, clamp_s);
  const int y0 = tap_index(t0, tex.height, clamp_t);
  const int y1 = tap_index(t0 + 1, tex.height, clamp_t);
  const Rgba c00 = fetch_texel(tex, x0, y0);
  const Rgba c10 = fetch_texel(tex, x1, y0);
  const Rgba c01 = fetch_texel(tex, x0, y1);
  const Rgba c11 = fetch_texel(tex, x1, y1);
  const int w00 = (kSteps - fs) * (kSteps - ft);  // the four weights sum to kSteps^2 = 256
  const int w10 = fs * (kSteps - ft);
  const int w01 = (kSteps - fs) * ft;
  const int w11 = fs * ft;
  auto mix = [&](int Rgba::*ch) {
    return (c00.*ch * w00 + c10.*ch * w10 + c01.*ch * w01 + c11.*ch * w11) >>
           (2 * kBilinearFractionBits);
  };
  return {mix(&Rgba::r), mix(&Rgba::g), mix(&Rgba::b), mix(&Rgba::a)};
}

bool alpha_test_passes(int function, int alpha, int reference) {
  switch (function) {
    case GR_CMP_NEVER: return false;
    case GR_CMP_LESS: return alpha < reference;
    case GR_CMP_EQUAL: return alpha == reference;
    case GR_CMP_LEQUAL: return alpha <= reference;
    case GR_CMP_GREATER: return alpha > reference;
    case GR_CMP_NOTEQUAL: return alpha != reference;
    case GR_CMP_GEQUAL: return alpha >= reference;
    case GR_CMP_ALWAYS: return true;
    default: throw_bad_enum("alpha test function", function);
  }
}

bool chroma_key_discards(const Rgba& color_other, const Rgba& key) {
  return color_other.r == key.r && color_other.g == key.g && color_other.b == key.b;
}

std::uint16_t pack_rgb565(const Rgba& c) {
  return static_cast<std::uint16_t>(((c.r >> 3) << 11) | ((c.g >> 2) << 5) | (c.b >> 3));
}

Rgba unpack_rgb565(std::uint16_t word) {
  return {expand5(word >> 11), expand6((word >> 5) & 0x3F), expand5(word & 0x1F), 255};
}

Rgba alpha_blend(const Rgba& src, const Rgba& dst, int src_factor, int dst_factor) {
  auto ch = [&](int s, int d) { return blend_channel(s, d, src_factor, dst_factor, src.a, dst.a); };
  return {ch(src.r, dst.r), ch(src.g, dst.g), ch(src.b, dst.b), src.a};
}

std::uint16_t blend_to_rgb565(const Rgba& src, std::uint16_t dst_word, int src_factor,
                              int dst_factor) {
  return pack_rgb565(alpha_blend(src, unpack_rgb565(dst_word), src_factor, dst_factor));
}

int w_buffer_code(double oow, std::int16_t bias) {
  return std::clamp(w_code_unclamped(oow) + bias, 0, 0xFFFF);
}

double w_buffer_code_to_oow(int code) {
  if (code < 0 || code > 0xFFFF) throw std::invalid_argument("voodoo_ref: W code out of range");
  if (code == 0) return 1.0;
  if (code == 0xFFFF) return std::ldexp(1.0, -17);
  const int e = (code - 1) >> 12;                     // leading zeros, 0..15
  const int mantissa = 0xFFF - ((code - 1) & 0xFFF);  // 12 bits after the leading one
  // The code's .32 fractions span [lead, lead + 2^(19-e)); return the middle one.
  const std::uint32_t lead = static_cast<std::uint32_t>(0x1000 + mantissa) << (19 - e);
  const std::uint32_t middle = lead + (1u << (18 - e));
  return std::ldexp(static_cast<double>(middle), -32);
}

int z_buffer_code(double ooz, std::int16_t bias) {
  const double z = std::floor(ooz);
  int code = 0;
  if (z >= 65535.0) {
    code = 0xFFFF;
  } else if (z > 0.0) {
    code = static_cast<int>(z);
  }
  return std::clamp(code + bias, 0, 0xFFFF);
}

int detail_factor(int lod_88, int detail_bias, int detail_scale, int detail_max) {
  if (detail_bias < -32 || detail_bias > 31 || detail_scale < 0 || detail_scale > 7 ||
      detail_max < 0 || detail_max > 255) {
    throw std::invalid_argument("voodoo_ref: tDetail field out of range");
  }
  const int bias_88 = detail_bias * 256;  // MAME: s8(bias << 2) << 6
  if (bias_88 <= lod_88) return 0;
  return std::min(((bias_88 - lod_88) << detail_scale) >> 8, detail_max);
}

int detail_max_field(float detail_max) { return static_cast<int>(detail_max * 255.0f); }

bool depth_test_passes(int function, int source, int stored) {
  switch (function) {
    case GR_CMP_NEVER: return false;
    case GR_CMP_LESS: return source < stored;
    case GR_CMP_EQUAL: return source == stored;
    case GR_CMP_LEQUAL: return source <= stored;
    case GR_CMP_GREATER: return source > stored;
    case GR_CMP_NOTEQUAL: return source != stored;
    case GR_CMP_GEQUAL: return source >= stored;
    case GR_CMP_ALWAYS: return true;
    default: throw_bad_enum("depth function", function);
  }
}

int compare_to_bias_source(std::int16_t bias_level) { return static_cast<std::uint16_t>(bias_level); }

std::array<int, 256> gamma_table(double gamma) {
  if (!(gamma > 0.0)) throw std::invalid_argument("voodoo_ref: gamma must be positive");
  std::array<int, 256> table{};
  for (int x = 0; x < 256; ++x) {
    table[x] = static_cast<int>(std::floor(255.0 * std::pow(x / 255.0, 1.0 / gamma) + 0.5));
  }
  return table;
}

std::array<int, 33> gamma_clut(double gamma) {
  const std::array<int, 256> table = gamma_table(gamma);
  std::array<int, 33> clut{};
  for (int i = 0; i < 32; ++i) clut[i] = table[i * 8];
  clut[32] = 255;
  return clut;
}

int gamma_scan_out_channel(int x, const std::array<int, 33>& clut) {
  if (x < 0 || x > 255) throw std::invalid_argument("voodoo_ref: channel value out of 0..255");
  const int i = x >> 3;
  const int frac = x & 7;  // eighths of the way from entry i to entry i+1
  return (clut[i] * (8 - frac) + clut[i + 1] * frac) >> 3;
}

Rgba gamma_scan_out(std::uint16_t word, const std::array<int, 33>& clut) {
  const Rgba c = unpack_rgb565(word);
  return {gamma_scan_out_channel(c.r, clut), gamma_scan_out_channel(c.g, clut),
          gamma_scan_out_channel(c.b, clut), 255};
}

}  // namespace voodoo_ref
