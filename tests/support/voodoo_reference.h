// Independent CPU reference of the 3dfx Voodoo 1 (SST-1) pixel arithmetic, for tests of the
// Glide shim: combine units, texel expansion and sampling, alpha/chroma tests, alpha blend and
// 565 write, W/Z depth codes and the gamma CLUT. Built from the team's notes on MAME, 86Box
// and 3dfx's sources (shared/docs/voodoo_pipeline.md, glide_api.md), never from the shim's sources.
#ifndef VOODOO_REFERENCE_H
#define VOODOO_REFERENCE_H

#include <array>
#include <cstdint>
#include <iosfwd>
#include <vector>

namespace voodoo_ref {

// One colour in the pipeline's 8-bit space: every channel 0..255.
struct Rgba {
  int r = 0;
  int g = 0;
  int b = 0;
  int a = 0;
};

bool operator==(const Rgba& x, const Rgba& y);
bool operator!=(const Rgba& x, const Rgba& y);
std::ostream& operator<<(std::ostream& os, const Rgba& c);

// ---------------------------------------------------------------------------------------------
// Combine units. All enum fields take Glide 2.x values (GR_COMBINE_FUNCTION_*, GR_COMBINE_FACTOR_*,
// GR_COMBINE_LOCAL_*, GR_COMBINE_OTHER_*); an unknown value throws std::invalid_argument.

// Arguments of grColorCombine or grAlphaCombine.
struct CombineConfig {
  int function;
  int factor;
  int local;
  int other;
  bool invert;
};

// Arguments of grTexCombine (the TMU has no local/other selection).
struct TexCombineConfig {
  int rgb_function;
  int rgb_factor;
  int alpha_function;
  int alpha_factor;
  bool rgb_invert;
  bool alpha_invert;
};

// What the FBI combine units can select from for one pixel.
struct CombineInputs {
  Rgba iterated;        // vertex colour after the 12.12 iterators, already truncated to 0..255
  Rgba texture;         // output of TMU0 (after its grTexCombine), 0..255
  Rgba constant;        // grConstantColorValue, 0..255
  int depth_alpha = 0;  // GR_COMBINE_LOCAL_DEPTH: bits 15..8 of the clamped 16-bit Z, 0..255
  // grAlphaControlsITRGBLighting(FXTRUE), fbzColorPath's local-select override: the colour
  // unit's local RGB is `constant` where bit 7 of texture.a is set, else `iterated`, whatever
  // grColorCombine's local says (MAME's combine_color).
  bool alpha_controls_itrgb = false;
};

// The shared datapath of one channel of any combine unit:
// clamp0..255(((zero_other ? 0 : other) - (sub_local ? local : 0)) * (f + 1) >> 8 + add),
// then 255 - x if invert. `f` is the resolved factor 0..255 (after the 'one minus' bit);
// `add` is 0, local or local_alpha according to `function`. The >> 8 is a floor division (two's
// complement arithmetic shift, as in MAME's int32 code), so a negative product rounds towards
// -infinity: BLEND with factor ZERO, other 0, local 100 gives 99.
int combine_channel(int function, int f, bool invert, int other, int local, int local_alpha);

// The colour unit's 'other' RGB (grColorCombine's other) with a_other (grAlphaCombine's other)
// in alpha; its RGB is what the chroma key compares.
Rgba combine_other(const CombineConfig& color, const CombineConfig& alpha, const CombineInputs& in);

// The colour unit's local RGB with a_local (grAlphaCombine's local) in alpha.
Rgba combine_local(const CombineConfig& color, const CombineConfig& alpha, const CombineInputs& in);

// FBI colour combine (RGB) and alpha combine (A) for one pixel. In the colour unit the
// LOCAL_ALPHA / OTHER_ALPHA factors and the *_ADD_LOCAL_ALPHA functions use a_local / a_other.
// GR_COMBINE_FACTOR_TEXTURE_RGB (Voodoo 2 only) and a colour local of DEPTH throw.
Rgba combine_fbi(const CombineConfig& color, const CombineConfig& alpha, const CombineInputs& in);

// One TMU's combine: local = this TMU's filtered texel, other = the upstream TMU's output
// (kNoUpstreamTmu for the last TMU). Factors 4 (DETAIL) and 5 (LOD_FRACTION) take `detail` and
// `lod_fraction` (0..255, see detail_factor; the fraction is the low 8 bits of the 8.8 LOD).
Rgba combine_tmu(const TexCombineConfig& config, const Rgba& texel, const Rgba& upstream,
                 int detail = 0, int lod_fraction = 0);
inline constexpr Rgba kNoUpstreamTmu{0, 0, 0, 0};

// The TMU's detail factor at LOD `lod_88` (8.8 fixed point, after bias, dither and the clamp
// to [lodmin, lodmax]) for grTexDetailControl's register fields: bias (-32..31, whole LODs),
// scale (0..7) and max (0..255). MAME's TMU: 0 when bias * 256 <= lod_88, else
// ((bias * 256 - lod_88) << scale) >> 8, limited to max. (MAME stores the shifted value in a u8
// before the limit, which wraps from 256 up; the hardware's limit is taken as saturating here.)
int detail_factor(int lod_88, int detail_bias, int detail_scale, int detail_max);

// grTexDetailControl's tDetail fields as the driver packs them (ditex.c): max is
// (FxU32)(detail_max * 255.0f).
int detail_max_field(float detail_max);

// ---------------------------------------------------------------------------------------------
// Texels and sampling.

// Expands one raw texel (GR_TEXFMT_*: RGB_565, ARGB_4444, ARGB_1555, ARGB_8332, RGB_332, ALPHA_8,
// INTENSITY_8, AI_44, AI_88) to 8 bits per channel by bit replication. 8-bit formats use the low
// byte of `raw`. Palette and NCC formats throw std::invalid_argument.
Rgba decode_texel(int format, std::uint16_t raw);

// One mipmap level as Glide stores it: row-major, one element per texel holding the raw 8- or
// 16-bit value. Width and height are powers of two, 1..256.
struct Texture {
  int width = 0;
  int height = 0;
  int format = 0;
  std::vector<std::uint16_t> texels;
};

// A texture coordinate in texel units of the sampled level: 0 is the left/top edge of texel 0,
// `width` the right edge of the last texel.
struct TexelCoord {
  double u = 0.0;
  double v = 0.0;
};

// Glide's s,t (sow/oow, tow/oow) span 0..256 across the longer side of every texture and
// 256/aspect across the shorter one, so both axes scale by max(width, height) / 256.
TexelCoord glide_st_to_texel(double s, double t, int width, int height);

// Number of sub-texel fraction bits of the Voodoo 1 bilinear filter (Voodoo 2 has 8).
inline constexpr int kBilinearFractionBits = 4;

// Samples `tex` at texel coordinate (u, v). `filter` is GR_TEXTUREFILTER_POINT_SAMPLED (texel
// floor(u), floor(v)) or GR_TEXTUREFILTER_BILINEAR (Voodoo 1: u - 0.5 quantised down to 1/16
// texel, weights (16-f)(16-g), f(16-g), (16-f)g, fg, sum >> 8). `clamp_s` / `clamp_t` are
// GR_TEXTURECLAMP_CLAMP (each tap index clamped to [0, size-1]) or GR_TEXTURECLAMP_WRAP (index
// modulo size).
Rgba sample_texture(const Texture& tex, TexelCoord coord, int filter, int clamp_s, int clamp_t);

// ---------------------------------------------------------------------------------------------
// Per-pixel tests.

// grAlphaTestFunction(function) with grAlphaTestReferenceValue(reference): true if the pixel is
// kept, comparing the combined alpha (0..255) as `alpha <op> reference` (GR_CMP_*).
bool alpha_test_passes(int function, int alpha, int reference);

// Chroma key: the colour unit's 'other' RGB (see combine_other) equal to the key in all three
// channels discards the pixel; alpha is ignored.
bool chroma_key_discards(const Rgba& color_other, const Rgba& key);

// ---------------------------------------------------------------------------------------------
// Alpha blend and the 565 frame buffer.

// 8-bit RGB -> 565 word by truncation (dither off: r>>3, g>>2, b>>3); alpha is dropped.
std::uint16_t pack_rgb565(const Rgba& c);

// 565 word -> 8-bit RGB by bit replication; alpha 255, which is also what the blender reads as
// destination alpha when there are no alpha planes (our 565 frame buffer).
Rgba unpack_rgb565(std::uint16_t word);

// grAlphaBlendFunction RGB factors (GR_BLEND_*) in MAME / 3dfx-simulator form:
// rgb = clamp((src * fs + dst * fd) >> 8), factors ZERO 0, ONE 256, SRC_ALPHA sa+1,
// ONE_MINUS_SRC_ALPHA 256-sa, DST_ALPHA da+1, ONE_MINUS_DST_ALPHA 256-da, value 2 = DST_COLOR
// (source factor, d+1 per channel) / SRC_COLOR (destination factor, s+1), value 6 its one-minus
// form (256-d / 256-s), 0xF = ALPHA_SATURATE (source, min(sa, 256-da)+1) / PREFOG_COLOR
// (destination; no fog is modelled, so the pre-fog colour is `src`). `dst.a` is the destination
// alpha. The result alpha is src.a: SST-1 forces the alpha factors to ONE/ZERO.
Rgba alpha_blend(const Rgba& src, const Rgba& dst, int src_factor, int dst_factor);

// Blends `src` over the stored 565 word (expanded by replication, destination alpha 255) and
// returns the word written with dither off.
std::uint16_t blend_to_rgb565(const Rgba& src, std::uint16_t dst_word, int src_factor,
                              int dst_factor);

// ---------------------------------------------------------------------------------------------
// Depth codes (16-bit values stored in the aux buffer; LEQUAL passes when new <= stored).

// W-buffer code of an interpolated 1/w: oow >= 1 (or negative) -> 0; the top 16 fraction bits of
// oow (as .32 fixed point, truncated) all zero -> 0xFFFF; otherwise with e = leading zeros of
// those 16 bits and m = the 12 bits after the leading one, (e << 12) + (~m & 0xFFF) + 1. `bias`
// (grDepthBiasLevel) is added before the result is clamped to 0..0xFFFF.
int w_buffer_code(double oow, std::int16_t bias = 0);

// A representative 1/w for a W code: the centre of the interval of oow values that produce it
// (code 0 -> 1.0, 0xFFFF -> 2^-17), so that w_buffer_code(w_buffer_code_to_oow(c)) == c.
double w_buffer_code_to_oow(int code);

// Z-buffer code: ooz (65535/z, larger is nearer) floored and clamped to 0..0xFFFF, then `bias`
// added and clamped again.
int z_buffer_code(double ooz, std::int16_t bias = 0);

// The depth test (GR_CMP_*): `source OP stored`, where stored is the aux buffer's code and
// source the pixel's (biased) code, or in the COMPARE_TO_BIAS modes (fbzMode bit 20) the
// zaColor depth field, i.e. grDepthBiasLevel as an unsigned 16-bit value (MAME's depth_test).
// The pixel's own code, without bias, is what a passing pixel writes.
bool depth_test_passes(int function, int source, int stored);
int compare_to_bias_source(std::int16_t bias_level);

// ---------------------------------------------------------------------------------------------
// Gamma (scan-out only; the frame buffer and LFB reads are pre-gamma).

// grGammaCorrectionValue(gamma): table[x] = round(255 * (x/255)^(1/gamma)), x = 0..255.
std::array<int, 256> gamma_table(double gamma);

// The 33-entry video CLUT Glide loads from that table: entry i = table[8i] for i < 32, entry 32 =
// 255 (SST-1 Glide writes 0xFFFFFF there).
std::array<int, 33> gamma_clut(double gamma);

// MAME's scan-out of one 8-bit channel value x through the CLUT:
// (clut[x>>3] * (8 - (x&7)) + clut[(x>>3)+1] * (x&7)) >> 3.
int gamma_scan_out_channel(int x, const std::array<int, 33>& clut);

// Displayed colour of a 565 pixel: each channel expanded by replication, then passed through the
// CLUT as above; alpha 255.
Rgba gamma_scan_out(std::uint16_t word, const std::array<int, 33>& clut);

}  // namespace voodoo_ref

#endif  // VOODOO_REFERENCE_H
